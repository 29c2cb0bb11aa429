// SPDX-License-Identifier: MIT
// Points as machine integers over a common denominator (word_scaled.hpp) and
// sums of them as 128-bit integers over one denominator (scaled_points.hpp),
// against plain mpq arithmetic (the oracle): every scaled numerator over the
// denominator is the original coordinate; the denominator is the lcm of the
// coordinates' denominators; points past the word-size bounds (a
// denominator of 2^63 or more, a scaled numerator of 2^61 or more) are
// refused; a stored coordinate is the canonical rational of its fraction;
// an approximation has Approx::of's double of the canonical value and a
// bound at least Approx::of's that covers it, also for values that are
// doubles or midpoints between two. Random cases use fixed
// seeds, printed on failure.
#include "scaled_points.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "approx.hpp"
#include "cvms/rational.hpp"
#include "cvms/vec.hpp"
#include "limb_arena.hpp"
#include "word_scaled.hpp"

namespace cvms::detail {
namespace {

using Int128 = ScaledPoints::Int128;
using Uint128 = ScaledPoints::Uint128;

mpz_class from_u64(std::uint64_t x) {
  mpz_class z;
  mpz_import(z.get_mpz_t(), 1, -1, sizeof x, 0, 0, &x);
  return z;
}

mpz_class from_i128(Int128 x) {
  const bool negative = x < 0;
  const Uint128 m = negative ? -static_cast<Uint128>(x) : static_cast<Uint128>(x);
  const std::uint64_t limbs[2] = {static_cast<std::uint64_t>(m), static_cast<std::uint64_t>(m >> 64)};
  mpz_class z;
  mpz_import(z.get_mpz_t(), 2, -1, sizeof(std::uint64_t), 0, 0, limbs);
  return negative ? mpz_class(-z) : z;
}

mpz_class from_u128(Uint128 x) { return from_i128(static_cast<Int128>(x)); }

// n / d, canonical.
Rational fraction(const mpz_class& n, const mpz_class& d) {
  Rational q(n, d);
  q.canonicalize();
  return q;
}

// Random points whose coordinates are k / d, d drawn from `denominators`,
// below 1 in magnitude (|k| < min(d, 2^40)) or integers below 1000, so that
// scaled to a common denominator below 2^61 they stay below it.
std::vector<Vec3> random_points(std::mt19937_64& rng, const std::vector<std::uint64_t>& denominators,
                                std::size_t count) {
  std::vector<Vec3> points(count);
  for (Vec3& p : points)
    for (int axis = 0; axis < 3; ++axis) {
      const std::uint64_t d = denominators[rng() % denominators.size()];
      const std::uint64_t bound = d == 1 ? 1000 : std::min<std::uint64_t>(d, std::uint64_t{1} << 40);
      const auto k = static_cast<std::int64_t>(rng() % bound);
      p[axis] = fraction(mpz_class(static_cast<long>(rng() % 2 == 0 ? k : -k)), from_u64(d));
    }
  return points;
}

// "" when scaled holds points exactly, over the lcm of their denominators.
std::string check_scaled(const std::vector<Vec3>& points, const WordScaledPoints& scaled) {
  mpz_class lcm = 1;
  for (const Vec3& p : points)
    for (int axis = 0; axis < 3; ++axis) mpz_lcm(lcm.get_mpz_t(), lcm.get_mpz_t(), p[axis].get_den_mpz_t());
  if (from_u64(scaled.denominator) != lcm) return "denominator " + from_u64(scaled.denominator).get_str();
  for (std::size_t j = 0; j < points.size(); ++j)
    for (int axis = 0; axis < 3; ++axis)
      if (fraction(mpz_class(static_cast<long>(scaled.at(j, axis))), lcm) != points[j][axis])
        return "point " + std::to_string(j) + " axis " + std::to_string(axis);
  return "";
}

TEST(WordScaled, DecimalsAndSmallRationalsScaleExactly) {
  const std::vector<std::vector<std::uint64_t>> families = {
      {1},                                                        // integers
      {10, 100, 1000000, 10000000000000000, 100000000000000000},  // decimals, as files write them
      {1000000000000000000},           // 10^18, the largest power of ten below 2^63
      {std::uint64_t{1} << 62},        // 2^62
      {(std::uint64_t{1} << 63) - 1},  // 2^63 - 1
      {3, 7, 9, 21},                   // small rationals
  };
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    std::mt19937_64 rng(seed);
    const std::vector<std::uint64_t>& denominators = families[seed % families.size()];
    const std::vector<Vec3> points = random_points(rng, denominators, 50);
    const std::optional<WordScaledPoints> scaled = scale_to_words(points);
    ASSERT_TRUE(scaled.has_value()) << "seed " << seed;
    EXPECT_EQ(check_scaled(points, *scaled), "") << "seed " << seed;
  }
}

TEST(WordScaled, PastTheWordBoundsIsRefused) {
  const auto point_over = [](const mpz_class& n, const mpz_class& d) {
    return std::vector<Vec3>{Vec3{fraction(n, d), Rational(0), Rational(0)}};
  };
  const mpz_class two63 = mpz_class(1) << 63;
  EXPECT_FALSE(scale_to_words(point_over(1, two63)));                              // a denominator of 2^63
  EXPECT_FALSE(scale_to_words(point_over(1, two63 + 1)));                          // just past it
  EXPECT_FALSE(scale_to_words(point_over(1, mpz_class("10000000000000000000"))));  // 10^19
  // lcm(2^62, 3) > 2^63: each fits, their common denominator does not.
  EXPECT_FALSE(
      scale_to_words(std::vector<Vec3>{Vec3{fraction(1, mpz_class(1) << 62), Rational(1, 3), Rational(0)}}));
  // A scaled numerator of 2^61, and one just below.
  EXPECT_FALSE(scale_to_words(point_over(mpz_class(1) << 61, 1)));
  EXPECT_TRUE(scale_to_words(point_over((mpz_class(1) << 61) - 1, 1)));
  EXPECT_TRUE(scale_to_words(point_over(1, two63 - 1)));
  // A numerator of two limbs.
  EXPECT_FALSE(scale_to_words(point_over(mpz_class(1) << 64, 3)));
}

// A sum of two scaled operands as the stitch builds it, against mpq sums.
TEST(ScaledPoints, SumsAreTheCanonicalRationalsWithinTheirBounds) {
  const std::vector<std::pair<std::uint64_t, std::uint64_t>> denominators = {
      {100000000000000000, 100000000000000000},      // shortest decimals, both operands
      {1000000, 100000000000000000},                 // 6 digits and shortest
      {std::uint64_t{1} << 61, 100000000000000000},  // dyadic 2^61 and decimal 10^17: about 120 bits
      {(std::uint64_t{1} << 63) - 1, (std::uint64_t{1} << 63) - 25},  // two denominators just below 2^63
      {3, 1},                                                         // thirds and integers
      {7, 9},                                                         // sevenths and ninths
  };
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    for (const auto& [da, db] : denominators) {
      std::mt19937_64 rng(seed);
      const std::vector<Vec3> a = random_points(rng, {da}, 20);
      const std::vector<Vec3> b = random_points(rng, {db}, 20);
      const std::optional<WordScaledPoints> sa = scale_to_words(a), sb = scale_to_words(b);
      ASSERT_TRUE(sa && sb) << "seed " << seed << " denominators " << da << ", " << db;
      const std::uint64_t g = std::gcd(sa->denominator, sb->denominator);
      const std::uint64_t fa = sb->denominator / g, fb = sa->denominator / g;
      ScaledPoints sum(Uint128{sa->denominator} * fa, KeptAllocator<Int128>{});
      LimbArena arena;
      for (std::size_t i = 0; i < a.size(); ++i) {
        const std::size_t j = sum.append();
        for (int axis = 0; axis < 3; ++axis) {
          const Int128 n = Int128{sa->at(i, axis)} * Int128{fa} + Int128{sb->at(i, axis)} * Int128{fb};
          sum.numerator(j, axis) = n;
          const Rational expected = a[i][axis] + b[i][axis];
          Rational stored;
          sum.store(j, axis, arena, stored);
          ASSERT_EQ(stored, expected) << "seed " << seed << " point " << i;
          ASSERT_EQ(fraction(from_i128(n), from_u128(sum.denominator())), expected);
          const Approx x = sum.approx(n), oracle = Approx::of(expected);
          ASSERT_EQ(x.value, oracle.value) << "seed " << seed << " point " << i;
          ASSERT_GE(x.error, oracle.error) << "seed " << seed << " point " << i;
          ASSERT_LE(abs(Rational(x.value) - expected), Rational(x.error))
              << "seed " << seed << " point " << i;
          ASSERT_EQ(sum.point(j)[axis], expected);
        }
      }
    }
  }
}

// Values where the long double quotient cannot decide: doubles, midpoints
// between two doubles, and fractions whose reduced terms are below 2^53
// although the stored ones are not.
TEST(ScaledPoints, ApproximationsOfDoublesAndMidpointsAreApproxOf) {
  const Int128 ten17 = 100000000000000000;
  const Uint128 denominators[] = {Uint128{100000000000000000}, Uint128{1} << 70, Uint128{300000000000000000},
                                  7};
  const Int128 numerators[] = {ten17 / 2,
                               ten17 / 4 * 3,
                               ten17 + 1,
                               -(ten17 / 8),
                               Int128{1} << 69,
                               (Int128{1} << 69) + 1,
                               3 * (Int128{1} << 60),
                               12345678901234567,
                               1,
                               -7};
  for (const Uint128 d : denominators) {
    ScaledPoints points(d, KeptAllocator<Int128>{});
    for (const Int128 n : numerators) {
      const Rational q = fraction(from_i128(n), from_u128(d));
      const Approx x = points.approx(n), oracle = Approx::of(q);
      EXPECT_EQ(x.value, oracle.value) << q;
      EXPECT_GE(x.error, oracle.error) << q;
      EXPECT_LE(abs(Rational(x.value) - q), Rational(x.error)) << q;
    }
  }
}

}  // namespace
}  // namespace cvms::detail
