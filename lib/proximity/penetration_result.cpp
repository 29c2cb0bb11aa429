// SPDX-License-Identifier: MIT
// penetration_result.hpp: the fields of a PenetrationResult from the nearest
// facet. The witnesses: after moving B by the translation p the operands
// touch, and the exact GJK of A against the moved B returns a common point
// x; then x is in A, x - p is in B, and their difference is p.
#include "penetration_result.hpp"

#include <utility>

#include "query_operands.hpp"

namespace cvms {

Vec3 PenetrationResult::translation() const {
  if (is_zero(direction)) return Vec3{0, 0, 0};
  return (offset / dot(direction, direction)) * direction;
}

namespace detail {

PenetrationResult penetration_from_distance(const DistanceResult& d) {
  PenetrationResult r;
  r.intersect = d.intersect;
  r.direction = Vec3{0, 0, 0};
  r.witness_a = d.witness_a;
  r.witness_b = d.witness_b;
  return r;
}

void set_nearest_facet(PenetrationResult& r, Vec3 direction, Rational offset, const SupportOperand& a,
                       const SupportOperand& b) {
  r.direction = std::move(direction);
  r.offset = std::move(offset);
  r.squared_depth = r.offset * r.offset / dot(r.direction, r.direction);
  const Vec3 t = r.translation();
  const DistanceResult contact = distance_with_offset(a, b, &t);
  r.witness_a = contact.witness_a;
  r.witness_b = contact.witness_b - t;
}

}  // namespace detail
}  // namespace cvms
