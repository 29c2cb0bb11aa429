// SPDX-License-Identifier: MIT
// The dimension of the affine hull of a point set, and the points that
// witness it, found with one predicate per point and stage (convex_set_hull.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "cvms/vec.hpp"

namespace cvms::detail {

struct AffineSpan {
  int dimension = -1;  ///< -1 for no points, else 0 to 3
  /// Indices of dimension + 1 affinely independent points: the first point,
  /// the first one different from it, the first off their line, the first
  /// off their plane.
  std::array<std::size_t, 4> witness{};
};

AffineSpan affine_span(std::span<const Vec3> points);

}  // namespace cvms::detail
