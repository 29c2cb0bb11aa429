// SPDX-License-Identifier: MIT
// The choice of cvms/solid_sum.hpp's road, by the fewest pieces: a convex
// operand is summed whole, so only the other one's faces are cut into
// convex polygons; only when neither is convex are both decomposed.
#include "cvms/solid_sum.hpp"

namespace cvms {

SolidSumRoad solid_sum_road(const Solid& a, const Solid& b) noexcept {
  if (a.is_convex() && b.is_convex()) return SolidSumRoad::convex;
  if (a.is_convex() || b.is_convex()) return SolidSumRoad::faces_with_convex;
  return SolidSumRoad::pieces;
}

}  // namespace cvms
