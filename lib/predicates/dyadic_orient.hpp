// SPDX-License-Identifier: MIT
// Exact orient3d for points whose coordinates are dyadic rationals (every
// double, and sums of doubles such as CHMS's pairwise vertex sums): scaled to
// a common power-of-two denominator they are integers, and the determinant
// is evaluated in integers, with no gcd and, once the per-thread scratch has
// grown, no allocation: several times faster than the rational evaluation on
// sums of doubles in [-1, 1] and +-1 (the CHMS inputs of Cube + Sphere_k,
// the quickhull's exact fallbacks). Private to the
// library.
#pragma once

#include <optional>

#include "filtered_predicates.hpp"
#include "cvms/vec.hpp"

namespace cvms {

/// The exact sign of orient3d(a, b, c, d) (see predicates.hpp) if every
/// coordinate's reduced denominator is a power of two; nothing otherwise.
std::optional<Sign> dyadic_orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace cvms
