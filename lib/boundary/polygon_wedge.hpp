// SPDX-License-Identifier: MIT
// The interior of a polygon near one of its corners, for polygons that keep
// their inside on the left (counterclockwise outer boundaries, clockwise
// holes): the wedge swept counterclockwise from the ray to the next corner
// to the ray to the previous one.
#pragma once

#include "cvms/vec.hpp"
#include "planar_tests.hpp"

namespace cvms::detail {

/// Does the direction from v to q point strictly into the polygon's inside
/// at corner v, whose neighbours are prev and next? \pre q != v, prev and
/// next are not in the same direction from v.
inline bool into_wedge(const Vec2& prev, const Vec2& v, const Vec2& next, const Vec2& q) {
  const int turn = orient2(prev, v, next);
  if (turn > 0) return orient2(v, next, q) > 0 && orient2(v, q, prev) > 0;
  if (turn < 0) return !(orient2(v, prev, q) >= 0 && orient2(v, q, next) >= 0);
  return orient2(v, next, q) > 0;
}

}  // namespace cvms::detail
