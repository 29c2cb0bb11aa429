// SPDX-License-Identifier: MIT
// Two polygons in non-parallel planes: R = Q1 + (Q2 + [0, m]), with m the
// normal of Q2, is a polygon plus a polyhedron (polygon_sum.cpp), and
// Q1 + Q2 = X is recovered from R = X + [0, m] exactly by undoing the sweep.
//
// Undoing a sweep by s (unswept): the face of R in direction u is
// F_X(u) + F_S(u) with S = [0, s]. For a facet of R with dot(n, s) < 0 it is
// F_X(n) itself, with > 0 it is F_X(n) + s, and with = 0 it is F_X(n) + S.
// Every vertex of R is a + 0 or a + s for a vertex a of X (the second
// exactly when it lies on a facet with dot(n, s) > 0: a vertex's normal cone
// is the intersection of one of X and one of S, and S's two cones are the
// closed half-spaces dot(u, s) <= 0 and >= 0). So moving the vertices of the
// upper facets back by s gives X's vertices, the lower and upper facets
// give X's facets with dot(n, s) != 0, and a side facet F + S gives F once
// its two sides parallel to s are shortened by s: its cycle, moved back,
// repeats the ends of those sides. A side facet that collapses to a segment
// was an edge of X (and is dropped); nothing else of X is lost, because a
// facet of X with dot(n, s) = 0 is the side facet F + S less the sweep. When
// X is flat (one lower and one upper facet, all sides collapse), it is the
// lower facet. ConvexPolyhedron's checked construction merges and verifies.
// Cost: O(size of R) plus sorting its vertices.
#include <utility>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/predicates.hpp"
#include "first_use.hpp"
#include "representation_order.hpp"
#include "set_sum_parts.hpp"

namespace cvms::detail {

namespace {

// Cycle with consecutive repeats removed (cyclically).
std::vector<std::uint32_t> without_repeats(const std::vector<std::uint32_t>& cycle) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t v : cycle)
    if (out.empty() || out.back() != v) out.push_back(v);
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

}  // namespace

ConvexSet unswept(const ConvexPolyhedron& r, const Vec3& sweep) {
  const Mesh& m = r.mesh();
  std::vector<Sign> side(m.num_faces());
  std::vector<bool> moved(m.num_vertices(), false);
  for (FaceId f : m.faces()) {
    side[f.index()] = sign_dot(r.normal(f), sweep);
    if (side[f.index()] == Sign::positive)
      for (HalfedgeId h : m.face_halfedges(f)) moved[m.from(h).index()] = true;
  }
  // Moved back, vertices may coincide (the ends of sides parallel to the
  // sweep): merged by sorting, never hashing (first_use.hpp).
  std::vector<Vec3> points;
  points.reserve(m.num_vertices());
  for (VertexId v : m.vertices()) points.push_back(moved[v.index()] ? r.vertex(v) - sweep : r.vertex(v));
  const FirstUse merged = first_use(points, RepresentationLess{});
  PolygonSoup soup;
  for (std::size_t i : merged.first) soup.points.push_back(std::move(points[i]));
  const std::vector<std::uint32_t>& vertex_index = merged.index;
  std::size_t lower = 0, upper = 0, sides = 0;
  std::vector<std::uint32_t> lower_face;
  for (FaceId f : m.faces()) {
    std::vector<std::uint32_t> cycle;
    for (HalfedgeId h : m.face_halfedges(f)) cycle.push_back(vertex_index[m.from(h).index()]);
    cycle = without_repeats(cycle);
    if (cycle.size() < 3) continue;  // a side facet that was an edge of X
    const Sign s = side[f.index()];
    if (s == Sign::negative) {
      ++lower;
      lower_face = cycle;
    }
    upper += s == Sign::positive ? 1 : 0;
    sides += s == Sign::zero ? 1 : 0;
    soup.add_face(cycle);
  }
  if (lower == 1 && upper == 1 && sides == 0) {
    std::vector<Vec3> polygon;
    for (std::uint32_t i : lower_face) polygon.push_back(soup.points[i]);
    return ConvexSet::polygon(polygon);
  }
  return ConvexSet(ConvexPolyhedron::from_soup(std::move(soup)));
}

}  // namespace cvms::detail
