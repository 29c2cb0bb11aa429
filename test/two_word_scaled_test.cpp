// SPDX-License-Identifier: MIT
// Points as two-word integers over a common denominator
// (two_word_scaled.hpp) and the binary gcd on 128-bit words (gcd128.hpp),
// against GMP (the oracle): gcd128 is mpz_gcd and divide_by_5 exact
// division of the multiples of 5 only, on random and extreme values;
// every scaled numerator over the denominator is the original coordinate;
// the denominator is the lcm of the coordinates' denominators; points at
// each bound are accepted and just past it refused (denominator and
// numerators 2^124, the sums' denominator 2^126 and numerators 2^125); sums
// made as the stitch makes them are the mpq sums; edge directions made
// primitive are the vectors divided by GMP's gcd of their coordinates. Random cases use fixed seeds,
// printed on failure.
#include "two_word_scaled.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "cvms/rational.hpp"
#include "cvms/vec.hpp"
#include "gcd128.hpp"
#include "limb_arena.hpp"
#include "scaled_points.hpp"
#include "small_direction.hpp"

namespace cvms::detail {
namespace {

using Int128 = TwoWordScaledPoints::Int128;
using Uint128 = TwoWordScaledPoints::Uint128;

mpz_class from_u128(Uint128 x) {
  const std::uint64_t limbs[2] = {static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(x >> 64)};
  mpz_class z;
  mpz_import(z.get_mpz_t(), 2, -1, sizeof(std::uint64_t), 0, 0, limbs);
  return z;
}

mpz_class from_i128(Int128 x) {
  const mpz_class m = from_u128(x < 0 ? -static_cast<Uint128>(x) : static_cast<Uint128>(x));
  return x < 0 ? mpz_class(-m) : m;
}

Uint128 random_u128(std::mt19937_64& rng) {
  const Uint128 x = (Uint128{rng()} << 64) | rng();
  return x >> (rng() % 128);  // every length
}

// n / d, canonical.
Rational fraction(const mpz_class& n, const mpz_class& d) {
  Rational q(n, d);
  q.canonicalize();
  return q;
}

TEST(Gcd128, IsGmpsGcdOnRandomAndExtremeValues) {
  const Uint128 max = ~Uint128{0};
  const Uint128 extremes[] = {0, 1, 2, 3, Uint128{1} << 63, Uint128{1} << 64, (Uint128{1} << 64) + 1,
                              Uint128{1} << 127, max, max - 1, max / 3, Uint128{100000000000000000} * 1000};
  for (const Uint128 a : extremes)
    for (const Uint128 b : extremes) {
      const mpz_class expected = gcd(from_u128(a), from_u128(b));
      EXPECT_EQ(from_u128(gcd128(a, b)), expected) << from_u128(a) << " " << from_u128(b);
    }
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    std::mt19937_64 rng(seed);
    for (int k = 0; k < 2000; ++k) {
      Uint128 a = random_u128(rng), b = random_u128(rng);
      if (k % 2 == 0) {  // a large common factor
        const Uint128 c = random_u128(rng) >> 64;
        a = (a >> 64) * c;
        b = (b >> 64) * c;
      }
      ASSERT_EQ(from_u128(gcd128(a, b)), gcd(from_u128(a), from_u128(b)))
          << "seed " << seed << ": " << from_u128(a) << " " << from_u128(b);
    }
  }
}

TEST(Gcd128, DivideBy5IsExactDivisionOfTheMultiplesOnly) {
  const Uint128 max = ~Uint128{0};
  std::mt19937_64 rng(11);
  std::vector<Uint128> values = {0, 1, 4, 5, 6, 25, max, max / 5, max / 5 * 5, max - 4, Uint128{1} << 127};
  for (int k = 0; k < 3000; ++k) values.push_back(k % 2 == 0 ? random_u128(rng) : random_u128(rng) / 5 * 5);
  for (const Uint128 x : values) {
    Uint128 y = x;
    const bool divided = divide_by_5(y);
    ASSERT_EQ(divided, from_u128(x) % 5 == 0) << "seed 11: " << from_u128(x);
    ASSERT_EQ(from_u128(y), divided ? mpz_class(from_u128(x) / 5) : from_u128(x)) << "seed 11: " << from_u128(x);
  }
}

// Random points whose coordinates are k / d for d drawn from `denominators`
// and |k| < d (below 1 in magnitude), so that the scaled ones stay below
// the common denominator.
std::vector<Vec3> random_points(std::mt19937_64& rng, const std::vector<mpz_class>& denominators,
                                std::size_t count) {
  gmp_randclass gmp(gmp_randinit_mt);
  gmp.seed(static_cast<unsigned long>(rng()));
  std::vector<Vec3> points(count);
  for (Vec3& p : points)
    for (int axis = 0; axis < 3; ++axis) {
      const mpz_class& d = denominators[rng() % denominators.size()];
      const mpz_class k = gmp.get_z_range(d);
      p[axis] = fraction(rng() % 2 == 0 ? k : mpz_class(-k), d);
    }
  return points;
}

// "" when scaled holds points exactly, over the lcm of their denominators.
std::string check_scaled(const std::vector<Vec3>& points, const TwoWordScaledPoints& scaled) {
  mpz_class lcm = 1, largest = 0;
  for (const Vec3& p : points)
    for (int axis = 0; axis < 3; ++axis) mpz_lcm(lcm.get_mpz_t(), lcm.get_mpz_t(), p[axis].get_den_mpz_t());
  if (from_u128(scaled.denominator) != lcm) return "denominator " + from_u128(scaled.denominator).get_str();
  for (std::size_t j = 0; j < points.size(); ++j)
    for (int axis = 0; axis < 3; ++axis) {
      if (fraction(from_i128(scaled.at(j, axis)), lcm) != points[j][axis])
        return "point " + std::to_string(j) + " axis " + std::to_string(axis);
      const mpz_class m = abs(from_i128(scaled.at(j, axis)));
      if (m > largest) largest = m;
    }
  if (from_u128(scaled.largest) != largest) return "largest " + from_u128(scaled.largest).get_str();
  return "";
}

const mpz_class ten17("100000000000000000"), ten19("10000000000000000000"), ten33("1" + std::string(33, '0'));
const mpz_class two61 = mpz_class(1) << 61, two122 = mpz_class(1) << 122, two123 = mpz_class(1) << 123, two124 = mpz_class(1) << 124;

TEST(TwoWordScaled, DecimalsMixedAndSmallRationalsScaleExactly) {
  const std::vector<std::vector<mpz_class>> families = {
      {10, 1000000, ten17, ten19, ten33},  // shortest decimals of tiny doubles
      {two61, ten17},                      // dyadic and decimal: lcm about 2^100
      {two124 - 1},                        // the largest denominator
      {two122, 3},                         // lcm 3 2^122 < 2^124
      {3, 7, 9, 21},                       // small rationals
  };
  for (std::uint64_t seed = 1; seed <= 15; ++seed) {
    std::mt19937_64 rng(seed);
    const std::vector<mpz_class>& denominators = families[seed % families.size()];
    const std::vector<Vec3> points = random_points(rng, denominators, 40);
    const std::optional<TwoWordScaledPoints> scaled = scale_to_two_words(points);
    ASSERT_TRUE(scaled.has_value()) << "seed " << seed;
    EXPECT_EQ(check_scaled(points, *scaled), "") << "seed " << seed;
  }
}

TEST(TwoWordScaled, AtAndPastTheBoundsOfTheOperand) {
  const auto point_over = [](const mpz_class& n, const mpz_class& d) {
    return std::vector<Vec3>{Vec3{fraction(n, d), Rational(0), Rational(0)}};
  };
  EXPECT_TRUE(scale_to_two_words(point_over(1, two124 - 1)));   // the largest denominator
  EXPECT_FALSE(scale_to_two_words(point_over(1, two124)));      // a denominator of 2^124
  EXPECT_FALSE(scale_to_two_words(point_over(1, two124 + 1)));  // just past it
  EXPECT_FALSE(scale_to_two_words(point_over(1, mpz_class(1) << 130)));  // three limbs
  // lcm(2^122, 3) < 2^124 but lcm(2^122, 3, 5) is not.
  EXPECT_TRUE(scale_to_two_words(std::vector<Vec3>{Vec3{fraction(1, two122), Rational(1, 3), Rational(0)}}));
  EXPECT_FALSE(
      scale_to_two_words(std::vector<Vec3>{Vec3{fraction(1, two122), Rational(1, 3), Rational(1, 5)}}));
  // Scaled numerators of 2^124 - 1 in magnitude (integers, and a fraction
  // times its denominator), and of 2^124.
  EXPECT_TRUE(scale_to_two_words(point_over(two124 - 1, 1)));
  EXPECT_TRUE(scale_to_two_words(point_over(-(two124 - 1), 1)));
  EXPECT_TRUE(scale_to_two_words(std::vector<Vec3>{Vec3{fraction(1, 3), fraction(two124 / 3, 1), Rational(0)}}));
  EXPECT_FALSE(scale_to_two_words(point_over(two124, 1)));
  EXPECT_FALSE(scale_to_two_words(point_over(-two124, 1)));
  // 2^123 / 1 with a third: 3 2^123 > 2^124 although every denominator fits.
  EXPECT_FALSE(scale_to_two_words(std::vector<Vec3>{Vec3{fraction(two123, 1), Rational(1, 3), Rational(0)}}));
  EXPECT_FALSE(scale_to_two_words(point_over(mpz_class(1) << 130, 3)));  // a numerator of three limbs
}

// The sum of two operands as the stitch makes it, against mpq sums, when
// two_word_sum_fits accepts them; and that bound at its edges.
TEST(TwoWordScaled, SumsAreTheRationalSumsWithinTheirBounds) {
  const std::vector<std::pair<mpz_class, mpz_class>> denominators = {
      {ten19, ten19}, {ten33, ten17}, {two61, ten17}, {ten19, 3}, {two123, two123 / 4}};
  for (std::uint64_t seed = 1; seed <= 5; ++seed)
    for (const auto& [da, db] : denominators) {
      std::mt19937_64 rng(seed);
      const std::vector<Vec3> a = random_points(rng, {da}, 20), b = random_points(rng, {db}, 20);
      const std::optional<TwoWordScaledPoints> sa = scale_to_two_words(a), sb = scale_to_two_words(b);
      ASSERT_TRUE(sa && sb) << "seed " << seed << " denominators " << da << ", " << db;
      const std::optional<TwoWordSum> fits = two_word_sum_fits(*sa, *sb);
      ASSERT_TRUE(fits) << "seed " << seed << " denominators " << da << ", " << db;
      ASSERT_EQ(from_u128(fits->denominator), lcm(da, db));
      ScaledPoints sum(fits->denominator, KeptAllocator<Int128>{});
      LimbArena arena;
      for (std::size_t i = 0; i < a.size(); ++i) {
        const std::size_t j = sum.append();
        for (int axis = 0; axis < 3; ++axis) {
          const Int128 n = sa->at(i, axis) * static_cast<Int128>(fits->factor_a) +
                           sb->at(i, axis) * static_cast<Int128>(fits->factor_b);
          sum.numerator(j, axis) = n;
          const Rational expected = a[i][axis] + b[i][axis];
          Rational stored;
          sum.store(j, axis, arena, stored);
          ASSERT_EQ(stored, expected) << "seed " << seed << " point " << i;
          const Approx x = sum.approx(n), oracle = Approx::of(expected);
          ASSERT_EQ(x.value, oracle.value) << "seed " << seed << " point " << i;
          ASSERT_GE(x.error, oracle.error) << "seed " << seed << " point " << i;
        }
      }
    }
}

TEST(TwoWordScaled, SumBoundsAtTheirEdges) {
  const auto operand = [](const mpz_class& n, const mpz_class& d) {
    return *scale_to_two_words(std::vector<Vec3>{Vec3{fraction(n, d), Rational(0), Rational(0)}});
  };
  // Numerators |a| f_A + |b| f_B: 2 (2^124 - 1) = 2^125 - 2 fits.
  EXPECT_TRUE(two_word_sum_fits(operand(two124 - 1, 1), operand(-(two124 - 1), 1)));
  // L = 4: 4 (2^123 - 1) + 1 = 2^125 - 3 fits; 4 2^123 + 1 = 2^125 + 1 does not.
  EXPECT_TRUE(two_word_sum_fits(operand(two123 - 1, 1), operand(1, 4)));
  EXPECT_FALSE(two_word_sum_fits(operand(two123, 1), operand(1, 4)));
  EXPECT_FALSE(two_word_sum_fits(operand(1, 4), operand(two123, 1)));
  // Denominators: lcm(2^123 - 1, 8) < 2^126 fits; (2^123 - 1) 16 > 2^126 does not.
  EXPECT_TRUE(two_word_sum_fits(operand(1, two123 - 1), operand(1, 8)));
  EXPECT_FALSE(two_word_sum_fits(operand(1, two123 - 1), operand(1, 16)));
  // Coprime denominators whose product overflows 128 bits.
  EXPECT_FALSE(two_word_sum_fits(operand(1, two123 - 1), operand(1, two123 + 1)));
}

// Approximations over two-word denominators, decimal (2^t 5^f, whose gcd
// with a numerator is counted) or not, of fractions whose reduced terms
// are below 2^53 (small fractions times the denominator), around them, and
// random: Approx::of's double and at least its bound.
TEST(TwoWordScaled, ApproximationsOverTwoWordDenominatorsAreApproxOf) {
  const Uint128 ten15 = 1000000000000000;
  const Uint128 denominators[] = {ten15 * ten15, (Uint128{1} << 90) * 9765625, ten15 * ten15 * 3, Uint128{1} << 125,
                                  ten15 * 100 * (Uint128{1} << 60), ten15 * ten15 * ten15 / 8};
  std::mt19937_64 rng(7);
  for (const Uint128 d : denominators) {
    ScaledPoints points(d, KeptAllocator<Int128>{});
    std::vector<Int128> numerators = {1, -1, static_cast<Int128>(d / 2), static_cast<Int128>(d / 4 * 3),
                                      static_cast<Int128>(d / 10), -static_cast<Int128>(d / 1000),
                                      static_cast<Int128>(d / 5 * 2) + 1, static_cast<Int128>(d / 5 * 2) - 1,
                                      static_cast<Int128>(d / 3), static_cast<Int128>(d / (Uint128{1} << 53)),
                                      static_cast<Int128>(d / 5 * 2), static_cast<Int128>(d / 3 * 2),
                                      -static_cast<Int128>(d / 10 * 7), static_cast<Int128>(d / 100000 * 3)};
    for (int k = 0; k < 200; ++k) numerators.push_back(static_cast<Int128>(random_u128(rng) % d));
    for (const Int128 n : numerators) {
      if (n == 0) continue;
      const Rational q = fraction(from_i128(n), from_u128(d));
      const Approx x = points.approx(n), oracle = Approx::of(q);
      ASSERT_EQ(x.value, oracle.value) << q << " over " << from_u128(d);
      ASSERT_GE(x.error, oracle.error) << q << " over " << from_u128(d);
    }
  }
}

// Edge directions of two-word operands: differences below 2^125 made
// primitive, against the vectors divided by GMP's gcd; small only below
// 2^62 in every coordinate.
TEST(TwoWordDirections, PrimitiveVectorsAreGmpsAndSmallOnlyWithinTheBound) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    std::mt19937_64 rng(seed);
    for (int k = 0; k < 500; ++k) {
      Int128 c[3];
      const Int128 factor = static_cast<Int128>(random_u128(rng) >> 70) + 1;  // a common factor below 2^58
      for (Int128& x : c) {
        x = static_cast<Int128>(random_u128(rng) >> 67) * factor;  // below 2^119
        if (rng() % 2 == 0) x = -x;
      }
      if (k % 7 == 0) c[k % 3] = 0;  // zero coordinates
      if (c[0] == 0 && c[1] == 0 && c[2] == 0) continue;
      const SmallNormal v = primitive_vector(c[0], c[1], c[2]);
      mpz_class g = gcd(gcd(from_i128(c[0]), from_i128(c[1])), from_i128(c[2]));
      const Vec3 expected{Rational(from_i128(c[0]) / g), Rational(from_i128(c[1]) / g),
                          Rational(from_i128(c[2]) / g)};
      const Vec3 actual{Rational(from_i128(v.c[0])), Rational(from_i128(v.c[1])), Rational(from_i128(v.c[2]))};
      ASSERT_EQ(actual, expected) << "seed " << seed << " case " << k;
      const std::optional<SmallDirection> small = as_small_direction(v);
      const mpz_class limit = mpz_class(1) << 62;
      const bool fits = abs(actual.x.get_num()) < limit && abs(actual.y.get_num()) < limit &&
                        abs(actual.z.get_num()) < limit;
      ASSERT_EQ(small.has_value(), fits) << "seed " << seed << " case " << k;
      if (small) {
        ASSERT_EQ(small->to_vec3(), expected) << "seed " << seed << " case " << k;
      }
      // A multiple of it (a factor of 10^k kept when some coordinate has
      // none) whenever the primitive vector fits.
      const std::optional<SmallDirection> multiple = small_multiple(c[0], c[1], c[2]);
      ASSERT_EQ(multiple.has_value(), fits) << "seed " << seed << " case " << k;
      if (multiple) {
        const Vec3 m = multiple->to_vec3();
        mpz_class h = gcd(gcd(m.x.get_num(), m.y.get_num()), m.z.get_num());
        ASSERT_EQ((Vec3{Rational(m.x.get_num() / h), Rational(m.y.get_num() / h), Rational(m.z.get_num() / h)}),
                  expected)
            << "seed " << seed << " case " << k;
      }
    }
  }
  const Int128 two62 = Int128{1} << 62;
  EXPECT_TRUE(as_small_direction(primitive_vector(two62 - 1, -(two62 - 1), 2)));
  EXPECT_FALSE(as_small_direction(primitive_vector(two62 + 1, 2, 0)));
  EXPECT_FALSE(as_small_direction(primitive_vector(1, -(two62 + 1), 0)));
  // A difference whose coordinates share 2^3 5^20 and 3: small_multiple
  // divides by the powers of 2 and 5 alone.
  const Int128 five20 = 95367431640625;
  const std::optional<SmallDirection> m = small_multiple(3 * 8 * five20 * five20, -9 * 8 * five20 * five20, 0);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->c[0], 3);
  EXPECT_EQ(m->c[1], -9);
  EXPECT_EQ(m->c[2], 0);
  EXPECT_FALSE(small_multiple(3 * (Int128{1} << 62) + 3, 1, 0));  // coprime past 2^62
  // A large difference whose coordinates share a power of ten: small once primitive.
  const Int128 ten20 = static_cast<Int128>(100000000000000000) * 1000;
  const std::optional<SmallDirection> d = as_small_direction(primitive_vector(3 * ten20, -7 * ten20, 0));
  ASSERT_TRUE(d);
  EXPECT_EQ(d->c[0], 3);
  EXPECT_EQ(d->c[1], -7);
}

}  // namespace
}  // namespace cvms::detail
