// SPDX-License-Identifier: MIT
// A point set's coordinates as two-word integers over one common
// denominator: the sibling of word_scaled.hpp for operands whose common
// denominator does not fit one word. Shortest round-trip decimals keep 17
// significant digits, so a coordinate below 0.01 has a denominator of 10^19
// or more (10^33 for 1e-17), beyond 2^63; mixed denominators such as 2^61
// and 10^17 have an lcm of about 2^100. Such operands still share one
// denominator below 2^124 with numerators below 2^124: every coordinate one
// signed 128-bit integer, an edge direction a difference of two (below 2^125
// in magnitude, so it cannot overflow), and a vertex of A + B an integer
// over the lcm of the two denominators whenever the bound of
// two_word_sum_fits() holds (scaled_points.hpp's 128-bit numerators).
//
// The bounds: D < 2^124 and |numerators| < 2^124 keep every difference of
// two numerators within a signed 128-bit integer with a bit to spare, and
// leave the sums' own bound to be checked per pair of operands, since it
// depends on the other operand's denominator.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "cvms/vec.hpp"

namespace cvms::detail {

/// Points as signed 128-bit integers over one positive common denominator.
struct TwoWordScaledPoints {
  __extension__ using Int128 = __int128;
  __extension__ using Uint128 = unsigned __int128;

  Uint128 denominator = 1;         ///< D: the lcm of every coordinate's denominator, below 2^124
  Uint128 largest = 0;             ///< the largest |numerator|, below 2^124
  std::vector<Int128> numerators;  ///< coordinate `axis` of point j times D at 3 j + axis

  /// The scaled coordinate `axis` (0, 1, 2) of point j.
  [[nodiscard]] Int128 at(std::size_t j, int axis) const noexcept {
    return numerators[3 * j + static_cast<std::size_t>(axis)];
  }
  /// Whether D is a power of two (every coordinate dyadic).
  [[nodiscard]] bool dyadic() const noexcept { return (denominator & (denominator - 1)) == 0; }
};

/// The bound below which two_word_scaled's denominator and numerators stay.
inline constexpr TwoWordScaledPoints::Uint128 two_word_limit = TwoWordScaledPoints::Uint128{1} << 124;

/// The points scaled to their common denominator, when it and the scaled
/// numerators are below 2^124; nullopt otherwise (the general rational
/// paths apply then). \pre the coordinates are canonical.
[[nodiscard]] std::optional<TwoWordScaledPoints> scale_to_two_words(std::span<const Vec3> points);

/// The denominator L = lcm(D_A, D_B) of sums a / D_A + b / D_B of points of
/// a and b, with each operand's factor to it (L / D_A, L / D_B).
struct TwoWordSum {
  TwoWordScaledPoints::Uint128 denominator;  ///< L
  TwoWordScaledPoints::Uint128 factor_a;     ///< L / D_A
  TwoWordScaledPoints::Uint128 factor_b;     ///< L / D_B
};

/// The common denominator of a and b's sums when L < 2^126 and every sum's
/// numerator a (L / D_A) + b (L / D_B) is below 2^125 in magnitude (checked
/// on the largest numerators: |a| f_A + |b| f_B bounds every one), which is
/// ScaledPoints' bound; nullopt otherwise.
[[nodiscard]] std::optional<TwoWordSum> two_word_sum_fits(const TwoWordScaledPoints& a, const TwoWordScaledPoints& b);

}  // namespace cvms::detail
