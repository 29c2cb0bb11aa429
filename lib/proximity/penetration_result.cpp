// SPDX-License-Identifier: MIT
// penetration_result.hpp: the fields of a PenetrationResult.
#include "penetration_result.hpp"

#include <utility>

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

void set_depth(PenetrationResult& r, Vec3 direction, Rational offset) {
  r.direction = std::move(direction);
  r.offset = std::move(offset);
  r.squared_depth = r.offset * r.offset / dot(r.direction, r.direction);
}

}  // namespace detail
}  // namespace cvms
