// SPDX-License-Identifier: MIT
// The operands of cvms_set_bench, shared by its peer rows (set_peers.cpp):
// Sphere6, a circle polygon in a tilted plane (so that no facet of the
// sphere is parallel to it) and a segment in a direction of small rationals.
#pragma once

#include <vector>

#include "cvms/convex_set.hpp"
#include "cvms/shapes.hpp"

namespace cvms_bench {

inline const cvms::ConvexSet& sphere6_set() {
  static const cvms::ConvexSet s(cvms::shapes::geodesic_sphere(6));
  return s;
}

/// circle_polygon(n) in the tilted plane spanned by (1, 0, 1) and (0, 1, 2).
inline cvms::ConvexSet tilted_polygon(int n) {
  std::vector<cvms::Vec3> cycle;
  for (const cvms::Vec2& p : cvms::shapes::circle_polygon(n))
    cycle.push_back(cvms::Vec3{p.x, p.y, p.x + cvms::Rational(2) * p.y});
  return cvms::ConvexSet::polygon(cycle);
}

inline cvms::ConvexSet bench_segment() {
  return cvms::ConvexSet::segment(cvms::Vec3{0, 0, 0}, cvms::Vec3{cvms::Rational(1, 3), cvms::Rational(2, 7), 1});
}

}  // namespace cvms_bench
