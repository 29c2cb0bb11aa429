// SPDX-License-Identifier: MIT
// Exact points as 128-bit integers over one common denominator: the
// vertices of A + B when the operands' coordinates are integers over
// denominators in machine words (word_scaled.hpp). With a / D_A and b / D_B
// and L = lcm(D_A, D_B) < 2^126, the sum is (a (L / D_A) + b (L / D_B)) / L,
// a numerator below 2^125 in magnitude: one 16-byte value per coordinate,
// made by two multiplications and an addition, as a dyadic vertex is one
// packed 16-byte value (dyadic_points.hpp). The fractions are not reduced:
// the canonical rationals (one gcd per coordinate) are made only when a
// caller asks for Vec3s.
#pragma once

#include <cstddef>
#include <vector>

#include "approx.hpp"
#include "cvms/vec.hpp"
#include "kept_allocator.hpp"
#include "limb_arena.hpp"
#include "result_slab.hpp"

namespace cvms::detail {

class ScaledPoints {
 public:
  __extension__ using Int128 = __int128;
  __extension__ using Uint128 = unsigned __int128;

  ScaledPoints() = default;
  /// No points yet, over `denominator` (positive, below 2^126); coordinates
  /// carved from allocator's slab, if any.
  ScaledPoints(Uint128 denominator, const KeptAllocator<Int128>& allocator)
      : denominator_(denominator),
        denominator_value_(static_cast<double>(denominator)),
        denominator_long_(static_cast<long double>(denominator)),
        decimal_(DecimalDenominator::of(denominator)),
        numerators_(allocator) {}
  /// count points at the origin, as above.
  ScaledPoints(std::size_t count, Uint128 denominator, const KeptAllocator<Int128>& allocator = {})
      : denominator_(denominator),
        denominator_value_(static_cast<double>(denominator)),
        denominator_long_(static_cast<long double>(denominator)),
        decimal_(DecimalDenominator::of(denominator)),
        numerators_(3 * count, allocator) {}
  /// Adds to plan the room for count points (result_slab.hpp).
  static void plan(SlabPlan& plan, std::size_t count) { plan.add<Int128>(3 * count); }

  [[nodiscard]] std::size_t size() const noexcept { return numerators_.size() / 3; }
  [[nodiscard]] Uint128 denominator() const noexcept { return denominator_; }
  /// Room for count points without reallocating.
  void reserve(std::size_t count) { numerators_.reserve(3 * count); }
  /// A new point at the origin after the others; its index.
  std::size_t append() {
    numerators_.resize(numerators_.size() + 3);
    return size() - 1;
  }
  /// The numerator of coordinate `axis` (0, 1, 2) of point j, below 2^125 in magnitude.
  [[nodiscard]] Int128 numerator(std::size_t j, int axis) const noexcept {
    return numerators_[3 * j + static_cast<std::size_t>(axis)];
  }
  [[nodiscard]] Int128& numerator(std::size_t j, int axis) noexcept {
    return numerators_[3 * j + static_cast<std::size_t>(axis)];
  }
  /// The double of Approx::of(numerator / denominator()), read off the
  /// integers (no GMP value, and a gcd only when the nearest double is not
  /// the truncation), with Approx::of's bound or, where telling which bound
  /// applies would take a gcd, the larger one (the proof in the source).
  [[nodiscard]] Approx approx(Int128 numerator) const;
  /// Coordinate `axis` of point j, canonical, its limbs in arena.
  void store(std::size_t j, int axis, LimbArena& arena, Rational& out) const;
  /// Point j as exact rationals (each owning its limbs).
  [[nodiscard]] Vec3 point(std::size_t j) const;
  /// n / denominator(), canonical, its limbs in arena.
  void store_fraction(Int128 n, LimbArena& arena, Rational& out) const;

 private:
  // The denominator as 2^twos 5^fives when it is one (decimals, doubles and
  // sums of the two), else fives = -1: the gcd of such a denominator with a
  // numerator is found by counting the numerator's factors 2 and 5.
  struct DecimalDenominator {
    int twos = 0;
    int fives = 0;
    static DecimalDenominator of(Uint128 d) noexcept;
  };
  // Whether n / denominator() reduced has a numerator and a denominator
  // below 2^53. \pre n > 0.
  [[nodiscard]] bool reduces_below_2_53(Uint128 n) const noexcept;

  Uint128 denominator_ = 1;
  double denominator_value_ = 1.0;       // denominator_ as a double (exact when below 2^53)
  long double denominator_long_ = 1.0L;  // and as a long double (within 2^-64 relative)
  DecimalDenominator decimal_;
  KeptVector<Int128> numerators_;        // 3 per point
};

}  // namespace cvms::detail
