// SPDX-License-Identifier: MIT
// An exact chart of a plane in 3D: drop one coordinate. For a plane with
// normal n and n[a] != 0, (x, y, z) -> the two other coordinates is an affine
// bijection of the plane onto R^2 (its inverse solves dot(n, x) = d for x[a]),
// so convexity, extreme points and planar Minkowski sums computed in the
// chart are those of the plane. The coordinates are taken in cyclic order
// (a+1, a+2), which keeps orientation when n[a] > 0 (e_{a+1} x e_{a+2} =
// e_a); when n[a] < 0 they are swapped, so that a cycle counterclockwise seen
// from n is counterclockwise in the chart in both cases. The axis of the
// largest |n[a]| is chosen only to keep the chart's coordinates well scaled.
#pragma once

#include "cvms/vec.hpp"

namespace cvms::detail {

class PlaneChart {
 public:
  /// \pre n != 0.
  explicit PlaneChart(const Vec3& n) : axis_(dominant_axis(n)), swap_(sgn(n[axis_]) < 0) {}

  [[nodiscard]] Vec2 operator()(const Vec3& p) const {
    const Rational& u = p[(axis_ + 1) % 3];
    const Rational& v = p[(axis_ + 2) % 3];
    return swap_ ? Vec2{v, u} : Vec2{u, v};
  }

 private:
  static int dominant_axis(const Vec3& n) {
    int best = 0;
    for (int k = 1; k < 3; ++k)
      if (cmp(abs(n[k]), abs(n[best])) > 0) best = k;
    return best;
  }
  int axis_;
  bool swap_;
};

/// The primitive integer direction of v != 0 whose first nonzero coordinate
/// is positive: the one normal a polygon's plane is given (so that two
/// polygons in parallel planes have equal normals).
Vec3 canonical_normal(const Vec3& v);

}  // namespace cvms::detail
