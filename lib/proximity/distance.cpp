// SPDX-License-Identifier: MIT
// intersects() and squared_distance(): the exact GJK of gjk.cpp, and the
// witnesses from its final simplex. With v = sum w_i (a_i - b_i) the nearest
// point of A + (-B) (weights positive, sum 1), a = sum w_i a_i is in A and
// b = sum w_i b_i is in B (convex combinations of their vertices), and
// a - b = v (so b is computed as a - v): so |a - b|^2 = |v|^2 is the distance, and a = b when they
// intersect. The same for polyhedra and for convex sets of any dimension:
// both are SupportOperands.
#include <array>
#include <optional>

#include "cvms/proximity.hpp"
#include "gjk.hpp"
#include "nearest_on_simplex.hpp"
#include "query_operands.hpp"

namespace cvms {

bool intersects(const PlacedPolyhedron& a, const PlacedPolyhedron& b) {
  detail::check_operands(a, b, "intersects");
  return detail::exact_gjk(detail::SupportOperand(a), detail::SupportOperand(b), detail::GjkGoal::intersection)
      .intersect;
}

bool intersects(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  detail::check_operands(a, b, "intersects");
  return detail::exact_gjk(detail::SupportOperand(a), detail::SupportOperand(b), detail::GjkGoal::intersection)
      .intersect;
}

bool intersects(const ConvexSet& a, const ConvexSet& b) {
  detail::check_operands(a, b, "intersects");
  return detail::exact_gjk(detail::SupportOperand(a), detail::SupportOperand(b), detail::GjkGoal::intersection)
      .intersect;
}

namespace detail {

DistanceResult distance_with_offset(const SupportOperand& a, const SupportOperand& b, const Vec3* b_offset) {
  return distance_from(a, exact_gjk(a, b, GjkGoal::distance, b_offset));
}

DistanceResult distance_from(const SupportOperand& a, const GjkOutcome& g) {
  DistanceResult r;
  r.squared_distance = g.squared_norm;
  r.intersect = g.intersect;
  r.iterations = g.iterations;
  std::array<std::optional<Vec3>, 4> moved;  // A's positions when A is moved
  const Vec3* a_points[4];
  for (int i = 0; i < g.size; ++i) a_points[i] = &a.position_view(g.simplex[i].vertex_a, moved[i]);
  r.witness_a = weighted_sum(a_points, g.weight_num.data(), g.weight_den, g.size);
  r.witness_b = g.intersect ? r.witness_a : r.witness_a - g.nearest;  // a - b = v: one weighted sum, not two
  return r;
}

}  // namespace detail

DistanceResult squared_distance(const PlacedPolyhedron& a, const PlacedPolyhedron& b) {
  detail::check_operands(a, b, "squared_distance");
  return detail::distance_with_offset(detail::SupportOperand(a), detail::SupportOperand(b), nullptr);
}

DistanceResult squared_distance(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  detail::check_operands(a, b, "squared_distance");
  return detail::distance_with_offset(detail::SupportOperand(a), detail::SupportOperand(b), nullptr);
}

DistanceResult squared_distance(const ConvexSet& a, const ConvexSet& b) {
  detail::check_operands(a, b, "squared_distance");
  return detail::distance_with_offset(detail::SupportOperand(a), detail::SupportOperand(b), nullptr);
}

}  // namespace cvms
