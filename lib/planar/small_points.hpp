// SPDX-License-Identifier: MIT
// Exact rational points as small integers over one common denominator.
//
// Scaling every point of both planar operands by the same positive L (the
// lcm of all their coordinates' denominators) is a homothety: it keeps edge
// directions, their angular order, collinearity and the lowest vertex, so the
// planar sum's index pairs of the scaled polygons are those of the given
// ones. When L and every scaled coordinate stay below 2^62 in magnitude
// (short decimals: L divides 10^k; dyadic coordinates of a narrow exponent
// range: L is a power of two), an edge vector fits in 64 bits and a cross
// product of two edges in 128 bits, so the whole merge runs in machine
// integers, exactly, with neither filter nor GMP. Otherwise the caller keeps
// the rationals.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cvms/vec.hpp"

namespace cvms::detail {

/// A point with integer coordinates, |x|, |y| < 2^62.
struct SmallPoint2 {
  std::int64_t x;
  std::int64_t y;
};

/// Fills sp and sq with L * p and L * q for the least common denominator L
/// of all their coordinates and returns true, or returns false (sp and sq
/// unspecified) when L or a scaled coordinate reaches 2^62 in magnitude.
bool scale_to_small_points(std::span<const Vec2> p, std::span<const Vec2> q, std::vector<SmallPoint2>& sp,
                           std::vector<SmallPoint2>& sq);

}  // namespace cvms::detail
