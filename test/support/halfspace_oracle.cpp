// SPDX-License-Identifier: MIT
// The brute-force half-space oracle (see the header).
#include "support/halfspace_oracle.hpp"

#include <algorithm>
#include <set>

namespace cvms::test {

namespace {

bool satisfies(const Vec3& x, std::span<const HalfspaceRow> rows) {
  return std::all_of(rows.begin(), rows.end(), [&](const HalfspaceRow& r) { return dot(r.normal, x) <= r.offset; });
}

}  // namespace

std::vector<HalfspaceRow> as_inequalities(const HalfspaceSystem& s) {
  std::vector<HalfspaceRow> rows = s.inequalities;
  for (const HalfspaceRow& e : s.equalities) {
    rows.push_back(e);
    rows.push_back({-e.normal, -e.offset});
  }
  return rows;
}

std::vector<Vec3> brute_force_vertices(std::span<const HalfspaceRow> rows) {
  std::set<Vec3> found;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (std::size_t j = i + 1; j < rows.size(); ++j) {
      const Vec3 c_ij = cross(rows[i].normal, rows[j].normal);
      for (std::size_t k = j + 1; k < rows.size(); ++k) {
        const Rational det = dot(rows[k].normal, c_ij);
        if (det == 0) continue;
        const Vec3 x = (1 / det) * (rows[i].offset * cross(rows[j].normal, rows[k].normal) +
                                    rows[j].offset * cross(rows[k].normal, rows[i].normal) + rows[k].offset * c_ij);
        if (satisfies(x, rows)) found.insert(x);
      }
    }
  }
  return {found.begin(), found.end()};
}

SetShape brute_force_intersection(std::span<const HalfspaceRow> rows) {
  const std::vector<Vec3> v = brute_force_vertices(rows);
  return hull_oracle(v);
}

SetShape brute_force_difference(const ConvexSet& a, const ConvexSet& b) {
  const std::vector<HalfspaceRow> rows_a = as_inequalities(to_halfspaces(a));
  std::vector<HalfspaceRow> rows;
  for (const Vec3& vb : b.vertices()) {
    for (const HalfspaceRow& r : rows_a) rows.push_back({r.normal, r.offset - dot(r.normal, vb)});
  }
  // Rows with equal normals: only the tightest can be tight at a vertex, so
  // keeping it alone changes no point (and keeps the enumeration small).
  std::vector<HalfspaceRow> tightest;
  for (const HalfspaceRow& r : rows) {
    auto it = std::find_if(tightest.begin(), tightest.end(), [&](const HalfspaceRow& t) { return t.normal == r.normal; });
    if (it == tightest.end()) {
      tightest.push_back(r);
    } else if (r.offset < it->offset) {
      it->offset = r.offset;
    }
  }
  return brute_force_intersection(tightest);
}

bool contained(const ConvexSet& inner, const ConvexSet& outer) {
  const std::vector<HalfspaceRow> rows = as_inequalities(to_halfspaces(outer));
  const std::vector<Vec3> v = inner.vertices();
  return std::all_of(v.begin(), v.end(), [&](const Vec3& x) { return satisfies(x, rows); });
}

}  // namespace cvms::test
