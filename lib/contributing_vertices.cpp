// SPDX-License-Identifier: MIT
// Contributing vertices by linear scan (paper Section 4.2, Eq. 3).
#include "contributing_vertices.hpp"

#include <algorithm>

#include "cvms/predicates.hpp"

namespace cvms::detail {

void maximising_vertices(const ConvexPolyhedron& q, Vec3Ref n, std::vector<VertexId>& out) {
  out.clear();
  for (VertexId v : q.mesh().vertices()) {
    if (out.empty()) {
      out.push_back(v);
      continue;
    }
    // Compare with the current maximiser only: all kept vertices tie with it.
    const Sign s = compare_dot(q.vertex_ref(v), q.vertex_ref(out.front()), n);
    if (s == Sign::positive) {
      out.clear();
      out.push_back(v);
    } else if (s == Sign::zero) {
      out.push_back(v);
    }
  }
}

FaceId facet_with_normal(const ConvexPolyhedron& q, VertexId v, const Vec3& n) {
  const Mesh& m = q.mesh();
  for (HalfedgeId h : m.outgoing_halfedges(v)) {
    const FaceId f = m.face(h);
    if (q.normal(f) == n) return f;
  }
  return {};
}

void sorted_facet_vertices(const ConvexPolyhedron& p, FaceId f, std::vector<VertexId>& out) {
  out.clear();
  const Mesh& m = p.mesh();
  for (HalfedgeId h : m.face_halfedges(f)) out.push_back(m.from(h));
  std::sort(out.begin(), out.end());
}

bool disjoint_sorted(std::span<const VertexId> x, std::span<const VertexId> y) noexcept {
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < x.size() && j < y.size()) {
    if (x[i] == y[j]) return false;
    if (x[i] < y[j]) {
      ++i;
    } else {
      ++j;
    }
  }
  return true;
}

}  // namespace cvms::detail
