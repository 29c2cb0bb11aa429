// SPDX-License-Identifier: MIT
// A point set's coordinates as machine integers over one common
// denominator. Files hold decimals (-0.9999510991904915 is
// 9999510991904915 / 10^16), 6-digit scans, small rationals: not dyadic, so
// the word paths built on doubles' bits (dyadic.hpp) decline them, though
// all the coordinates of one operand usually share a denominator below
// 2^63 (10^17 for shortest round-trip decimals of magnitude at most one).
// Scaled to it once, every coordinate is one machine integer: a vertex of
// A + B is then an integer over the product of two such denominators
// (scaled_points.hpp) and an edge direction a difference of integers, with
// no GMP value read or made.
//
// The bounds: the common denominator D is below 2^63 and every scaled
// numerator below 2^61 in magnitude, so a difference of two is below 2^62
// (SmallDirection's bound, small_direction.hpp) and a numerator times the
// other operand's denominator below 2^124.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "cvms/vec.hpp"

namespace cvms::detail {

/// Points as integers over one positive common denominator in machine words.
struct WordScaledPoints {
  std::uint64_t denominator = 1;         ///< D: the lcm of every coordinate's denominator, below 2^63
  std::vector<std::int64_t> numerators;  ///< coordinate `axis` of point j times D at 3 j + axis, below 2^61

  /// The scaled coordinate `axis` (0, 1, 2) of point j.
  [[nodiscard]] std::int64_t at(std::size_t j, int axis) const noexcept {
    return numerators[3 * j + static_cast<std::size_t>(axis)];
  }
  /// Whether D is a power of two (every coordinate dyadic).
  [[nodiscard]] bool dyadic() const noexcept { return (denominator & (denominator - 1)) == 0; }
};

/// The points scaled to their common denominator, when it and the scaled
/// numerators fit the bounds of the file comment; nullopt otherwise (the
/// general rational paths apply then). \pre the coordinates are canonical.
[[nodiscard]] std::optional<WordScaledPoints> scale_to_words(std::span<const Vec3> points);

}  // namespace cvms::detail
