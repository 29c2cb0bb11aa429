// SPDX-License-Identifier: MIT
// The exact sub-distance of GJK: the point of the convex hull of at most four
// affinely independent points nearest to the origin, and the smallest subset
// whose relative interior holds it (with its barycentric coordinates).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "cvms/vec.hpp"

namespace cvms::detail {

/// At most four points, viewed (the callers own them).
using SimplexPoints = std::array<const Vec3*, 4>;

/// The nearest point of conv(points[0..count)) to the origin.
struct SimplexNearest {
  Vec3 point;                      ///< the nearest point, exact
  Rational squared_norm;           ///< |point|^2
  std::uint32_t support_mask = 0;  ///< bit i: points[i] has a positive weight
  /// Barycentric weights weight_num[i] / weight_den (0 outside the mask),
  /// kept as integers: reducing them would cost a gcd each, and the caller
  /// needs them only to combine points (weighted_sum).
  std::array<mpz_class, 4> weight_num;
  mpz_class weight_den;  ///< > 0
};

/// \pre 1 <= count <= 4, the points are affinely independent, and the
///   nearest point's support contains points[count - 1] (GJK's newest point;
///   the proof that it does is in gjk.cpp). Only subsets containing it are tried.
SimplexNearest nearest_on_simplex(const SimplexPoints& points, int count);

/// The projection of the origin onto aff(points[0..count)) if it lies in
/// the relative interior of their hull (every weight positive): then it is
/// the nearest point of the hull. Nothing if a weight is not positive or the
/// points are affinely dependent (no precondition: the GJK's warm start
/// passes points proposed by floating point).
std::optional<SimplexNearest> project_inside(const SimplexPoints& points, int count);

/// sum weight_num[i] points[i] / weight_den, exact, for i < count: one
/// common denominator, one gcd per coordinate.
Vec3 weighted_sum(const Vec3* const points[], const mpz_class weight_num[], const mpz_class& weight_den, int count);

}  // namespace cvms::detail
