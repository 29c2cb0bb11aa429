// SPDX-License-Identifier: MIT
// The exact sub-distance of GJK: the point of the convex hull of at most four
// affinely independent points nearest to the origin, and the smallest subset
// whose relative interior holds it (with its barycentric coordinates).
#pragma once

#include <array>
#include <cstdint>

#include "cvms/vec.hpp"

namespace cvms::detail {

/// The nearest point of conv(points[0..count)) to the origin.
struct SimplexNearest {
  Vec3 point;                      ///< the nearest point, exact
  Rational squared_norm;           ///< |point|^2
  std::uint32_t support_mask = 0;  ///< bit i: points[i] has a positive weight
  std::array<Rational, 4> weight;  ///< barycentric weights (0 outside the mask), sum 1
};

/// \pre 1 <= count <= 4, the points are affinely independent, and the
///   nearest point's support contains points[count - 1] (GJK's newest point;
///   the proof that it does is in gjk.cpp). Only subsets containing it are tried.
SimplexNearest nearest_on_simplex(const std::array<Vec3, 4>& points, int count);

}  // namespace cvms::detail
