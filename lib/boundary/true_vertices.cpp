// SPDX-License-Identifier: MIT
// The vertex set and the splitting of true_vertices.hpp.
//
// A vertex v lies in the relative interior of the segment [a, b] iff
// b - a and v - a are parallel and v is in the segment's bounding box and
// is neither end. Candidates come from three lexicographic orders of the
// vertices, by coordinates (k, k + 1, k + 2) for k = 0, 1, 2: the vertices
// that share the segment's first coordinates in that order where a and b
// agree, and lie between a and b in the next, form one range of the order,
// and the test scans the smallest of the three ranges (for an edge parallel
// to a coordinate axis, the vertices on its line). Points of a line are ordered along it by the lexicographic
// order (the first nonzero coordinate of the direction decides it), so the
// hits sorted that way, reversed when b precedes a, are the pieces' order.
#include "true_vertices.hpp"

#include <algorithm>
#include <numeric>

#include "cvms/error.hpp"
#include "cvms/predicates.hpp"
#include "representation_order.hpp"

namespace cvms::detail {

// The ends are deduplicated as pointers in the representation order (an
// integer comparison, no cross products), and only the distinct points are
// copied and sorted by value.
std::vector<Vec3> true_vertices(const std::vector<std::vector<DirectedSegment>>& segments_per_plane) {
  std::vector<const Vec3*> ends;
  for (const auto& segments : segments_per_plane)
    for (const auto& s : segments) {
      ends.push_back(&s.from);
      ends.push_back(&s.to);
    }
  const RepresentationLess less;
  std::sort(ends.begin(), ends.end(), less);
  ends.erase(std::unique(ends.begin(), ends.end(), [](const Vec3* p, const Vec3* q) { return *p == *q; }),
             ends.end());
  std::sort(ends.begin(), ends.end(), [](const Vec3* p, const Vec3* q) { return *p < *q; });
  std::vector<Vec3> vertices;
  vertices.reserve(ends.size());
  for (const Vec3* p : ends) vertices.push_back(*p);
  return vertices;
}

SegmentSplitter::SegmentSplitter(const std::vector<Vec3>& vertices) : vertices_(vertices) {
  near_.reserve(vertices.size());
  for (const Vec3& p : vertices)
    near_.push_back({to_double_nearest(p.x), to_double_nearest(p.y), to_double_nearest(p.z)});
  by_representation_.resize(vertices.size());
  std::iota(by_representation_.begin(), by_representation_.end(), std::uint32_t{0});
  std::sort(by_representation_.begin(), by_representation_.end(), [&](std::uint32_t i, std::uint32_t j) {
    return RepresentationLess::less(vertices[i], vertices[j]);
  });
  for (int k = 0; k < 3; ++k) {
    auto& order = by_axis_[k];
    order.resize(vertices.size());
    std::iota(order.begin(), order.end(), std::uint32_t{0});
    const int k1 = (k + 1) % 3;
    const int k2 = (k + 2) % 3;
    std::sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) {
      const Vec3& p = vertices[i];
      const Vec3& q = vertices[j];
      if (int c = cmp(p[k], q[k]); c != 0) return c < 0;
      if (int c = cmp(p[k1], q[k1]); c != 0) return c < 0;
      return p[k2] < q[k2];
    });
  }
}

// Rounding to nearest is monotone, so different nearest doubles order the
// values; only equal ones need the exact comparison.
int SegmentSplitter::compare(std::uint32_t i, int k, const Rational& x, double near_x) const {
  const double near_p = near_[i][static_cast<std::size_t>(k)];
  if (near_p != near_x) return near_p < near_x ? -1 : 1;
  return cmp(vertices_[i][k], x);
}

std::span<const std::uint32_t> SegmentSplitter::candidates(int k, const Query& q) const {
  // The coordinates k, k + 1, k + 2 in turn: those a and b share are fixed,
  // the first they differ in is a range; the rest are free.
  std::array<int, 3> axes{k, (k + 1) % 3, (k + 2) % 3};
  int fixed = 0;
  while (fixed < 2 && q.a[axes[fixed]] == q.b[axes[fixed]]) ++fixed;
  const auto r = static_cast<std::size_t>(axes[fixed]);
  // Sign of (vertex i's key) - (the query's), compared on the first fixed + 1 coordinates.
  const auto key_compare = [&](std::uint32_t i, const Rational& bound, double near_bound) {
    for (int m = 0; m < fixed; ++m) {
      const int axis = axes[m];
      if (int c = compare(i, axis, q.a[axis], q.near_a[static_cast<std::size_t>(axis)]); c != 0) return c;
    }
    return compare(i, axes[fixed], bound, near_bound);
  };
  const auto& order = by_axis_[k];
  const auto first = std::partition_point(order.begin(), order.end(), [&](std::uint32_t i) {
    return key_compare(i, *q.lo[r], q.near_lo[r]) < 0;
  });
  const auto last = std::partition_point(
      first, order.end(), [&](std::uint32_t i) { return key_compare(i, *q.hi[r], q.near_hi[r]) <= 0; });
  return {first, last};
}

// Searched in the representation order: integer comparisons where the
// value order would cross-multiply.
std::uint32_t SegmentSplitter::id(const Vec3& p) const {
  const auto it = std::lower_bound(
      by_representation_.begin(), by_representation_.end(), p,
      [&](std::uint32_t i, const Vec3& q) { return RepresentationLess::less(vertices_[i], q); });
  if (it == by_representation_.end() || vertices_[*it] != p)
    throw Error(ErrorCategory::invalid_argument, "assemble_boundary: a segment end is not a vertex");
  return *it;
}

void SegmentSplitter::split(const DirectedSegment& segment, std::vector<std::array<std::uint32_t, 2>>& edges) const {
  const Vec3& a = segment.from;
  const Vec3& b = segment.to;
  Query q{a, b, {}, {}, {}, {}, {}};
  for (std::size_t k = 0; k < 3; ++k) {
    const int axis = static_cast<int>(k);
    const bool a_low = a[axis] < b[axis];
    q.lo[k] = a_low ? &a[axis] : &b[axis];
    q.hi[k] = a_low ? &b[axis] : &a[axis];
    q.near_a[k] = to_double_nearest(a[axis]);
    const double near_b = to_double_nearest(b[axis]);
    q.near_lo[k] = a_low ? q.near_a[k] : near_b;
    q.near_hi[k] = a_low ? near_b : q.near_a[k];
  }
  // The smallest of the candidate ranges of the orders that fix the most
  // coordinates (the range of any order holds every vertex on the segment,
  // so the choice only saves work): for a segment parallel to an axis, the
  // one order that searches its line alone.
  std::array<int, 3> fixed{};
  for (int k = 0; k < 3; ++k)
    for (int m = 0; m < 2 && a[(k + m) % 3] == b[(k + m) % 3]; ++m) ++fixed[k];
  const int most = *std::max_element(fixed.begin(), fixed.end());
  std::span<const std::uint32_t> candidates;
  bool found = false;
  for (int k = 0; k < 3; ++k) {
    if (fixed[k] != most) continue;
    const auto range = this->candidates(k, q);
    if (!found || range.size() < candidates.size()) candidates = range;
    found = true;
  }
  const Vec3 ab = b - a;
  std::vector<std::uint32_t> inside;
  for (std::uint32_t v : candidates) {
    const Vec3& p = vertices_[v];
    if (p == a || p == b) continue;
    bool in_box = true;
    for (std::size_t k = 0; k < 3 && in_box; ++k) {
      const int axis = static_cast<int>(k);
      in_box = compare(v, axis, *q.lo[k], q.near_lo[k]) >= 0 && compare(v, axis, *q.hi[k], q.near_hi[k]) <= 0;
    }
    if (in_box && is_parallel(ab, p - a)) inside.push_back(v);
  }
  // Vertex ids follow the lexicographic order.
  std::sort(inside.begin(), inside.end());
  if (b < a) std::reverse(inside.begin(), inside.end());
  std::uint32_t from = id(a);
  for (std::uint32_t v : inside) {
    edges.push_back({from, v});
    from = v;
  }
  edges.push_back({from, id(b)});
}

}  // namespace cvms::detail
