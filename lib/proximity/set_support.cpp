// SPDX-License-Identifier: MIT
// support() on a ConvexSet. A polyhedron is the polyhedron's query. A
// polygon's vertices are in cyclic order and each is joined to its two
// neighbours: the walk of support_walk.hpp on that cycle (CycleGraph) is
// correct for the reason given there, the polygon minus a vertex lying in the
// cone of its two edges. A segment is a two-vertex cycle, a point a
// one-vertex one. The maximising face is the tied run of the cycle around
// the maximiser: one vertex, an edge, or (u orthogonal to the plane) all of it.
#include <string>

#include "cvms/error.hpp"
#include "cvms/proximity.hpp"
#include "support_operand.hpp"

namespace cvms {
namespace {

void check_query(const ConvexSet& s, const Vec3& u, VertexId start) {
  if (s.empty()) throw Error(ErrorCategory::invalid_argument, "support: the set is empty");
  if (is_zero(u)) throw Error(ErrorCategory::invalid_argument, "support: zero direction");
  if (!start.is_valid() || start.index() >= s.num_vertices())
    throw Error(ErrorCategory::invalid_argument, "support: start vertex " + std::to_string(start.index()) +
                                                     " is not a vertex (the set has " +
                                                     std::to_string(s.num_vertices()) + ")");
}

}  // namespace

SupportResult support(const ConvexPolyhedron& p, const Vec3& u, VertexId start, bool want_face) {
  return support(PlacedPolyhedron(p), u, start, want_face);
}

SupportResult support(const ConvexSet& s, const Vec3& u, VertexId start, bool want_face) {
  check_query(s, u, start);
  if (s.dimension() == 3) return support(s.polyhedron(), u, start, want_face);
  const detail::VertexCycle cycle(s);
  const detail::CycleGraph graph = cycle.graph();
  const ApproxVec3 u_approx = ApproxVec3::of(u);
  const Vec3Ref dir{u, u_approx};
  SupportResult r;
  r.vertex = detail::climb_to_maximum(graph, dir, start);
  r.point = cycle.points[r.vertex.index()];
  r.value = dot(r.point, u);
  if (want_face) {
    r.face.vertices = detail::maximising_face(graph, dir, r.vertex);
    r.face.dimension = r.face.vertices.size() >= 3 ? 2 : static_cast<int>(r.face.vertices.size()) - 1;
  }
  return r;
}

}  // namespace cvms
