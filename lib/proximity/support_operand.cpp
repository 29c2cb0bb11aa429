// SPDX-License-Identifier: MIT
// SupportOperand (support_operand.hpp): which graph the support walk climbs.
// A placement x -> R x + t is applied to the direction, not to the
// polyhedron: max over x in P of <R x + t, u> is reached where <x, R^T u> is,
// for any linear R (support.cpp says more).
#include "support_operand.hpp"

namespace cvms::detail {

VertexCycle::VertexCycle(const ConvexSet& s) : points(s.vertices()) {
  approx.reserve(points.size());
  for (const Vec3& x : points) approx.push_back(ApproxVec3::of(x));
}

SupportOperand::SupportOperand(const ConvexSet& s) {
  if (s.dimension() == 3)
    polyhedron_.emplace(s.polyhedron());
  else
    cycle_ = VertexCycle(s);
}

VertexId SupportOperand::support(Vec3Ref u, Sign sense, VertexId start) const {
  if (!polyhedron_) return climb_to_maximum(cycle_.graph(), u, start, sense);
  const PolyhedronGraph graph{polyhedron_->polyhedron()};
  if (!polyhedron_->is_placed()) return climb_to_maximum(graph, u, start, sense);
  const Vec3 local = polyhedron_->linear_transposed() * u.exact;
  const ApproxVec3 approx = ApproxVec3::of(local);
  return climb_to_maximum(graph, Vec3Ref{local, approx}, start, sense);
}

Vec3 SupportOperand::position(VertexId v) const {
  return polyhedron_ ? polyhedron_->position(v) : cycle_.points[v.index()];
}

}  // namespace cvms::detail
