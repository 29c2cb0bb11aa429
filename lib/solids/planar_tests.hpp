// SPDX-License-Identifier: MIT
// Exact tests on points of one plane, in a chart of it (plane_chart.hpp):
// closed segments and closed triangles, every decision an orient2d or an
// exact comparison of coordinates.
#pragma once

#include <algorithm>

#include "cvms/predicates.hpp"
#include "cvms/vec.hpp"

namespace cvms::detail {

inline int orient2(const Vec2& a, const Vec2& b, const Vec2& c) {
  return static_cast<int>(orient2d(a, b, c));
}

/// For p, q, r collinear: is r on the closed segment [p, q]?
inline bool between(const Vec2& p, const Vec2& q, const Vec2& r) {
  return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
         r.y <= std::max(p.y, q.y);
}

/// Do the closed segments [p, q] and [a, b] have a common point?
inline bool segments_meet(const Vec2& p, const Vec2& q, const Vec2& a, const Vec2& b) {
  const int d1 = orient2(p, q, a);
  const int d2 = orient2(p, q, b);
  const int d3 = orient2(a, b, p);
  const int d4 = orient2(a, b, q);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && between(p, q, a)) || (d2 == 0 && between(p, q, b)) || (d3 == 0 && between(a, b, p)) ||
         (d4 == 0 && between(a, b, q));
}

/// Is p on the closed triangle (a, b, c) of positive area, either orientation?
inline bool point_in_triangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  const int s = orient2(a, b, c);
  return orient2(a, b, p) * s >= 0 && orient2(b, c, p) * s >= 0 && orient2(c, a, p) * s >= 0;
}

}  // namespace cvms::detail
