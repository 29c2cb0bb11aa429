// SPDX-License-Identifier: MIT
// The gcd-free dyadic operations against GMP's general rational arithmetic
// (the oracle), on dyadic and non-dyadic values, signs, zeros and extreme
// exponents.
#include "dyadic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "cvms/rational.hpp"
#include "power_of_two.hpp"

namespace cvms::detail {
namespace {

// The limb test against GMP's own bit counting (the oracle): one and several
// limbs, a set bit below the top limb, zero and negatives.
TEST(PowerOfTwo, AgreesWithPopcountAndScan) {
  std::vector<mpz_class> values = {0, 1, 2, 3, 6, -1, -4};
  for (unsigned k : {1u, 31u, 63u, 64u, 65u, 127u, 128u, 200u, 1074u}) {
    mpz_class p;
    mpz_setbit(p.get_mpz_t(), k);
    values.push_back(p);
    values.push_back(p + 1);         // a bit in the lowest limb
    values.push_back(p + (p >> 1));  // two bits, possibly in one limb
    values.push_back(p - 1);
    values.push_back(-p);
  }
  for (const mpz_class& x : values) {
    const bool expected = sgn(x) > 0 && mpz_popcount(x.get_mpz_t()) == 1;
    EXPECT_EQ(is_power_of_two(x.get_mpz_t()), expected) << x;
    if (expected) {
      EXPECT_EQ(log2_of_power_of_two(x.get_mpz_t()), mpz_scan1(x.get_mpz_t(), 0)) << x;
    }
  }
}

// Values covering every branch: zero, integers, equal and different
// power-of-two denominators, huge and tiny doubles, and non-dyadic rationals.
std::vector<Rational> samples(std::uint64_t seed) {
  std::vector<Rational> v = {Rational(0),     Rational(1),     Rational(-3),   Rational(1, 2),
                             Rational(-1, 2), Rational(3, 4),  Rational(5, 8), Rational(-7, 8),
                             Rational(1, 3),  Rational(-2, 5), Rational(7, 6), Rational(1, 1024)};
  v.push_back(rational_from_double(1e300));
  v.push_back(rational_from_double(-1e-300));
  v.push_back(rational_from_double(4.9406564584124654e-324));  // smallest subnormal
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> e(-80, 80);
  for (int i = 0; i < 40; ++i) v.push_back(rational_from_double(std::ldexp(u(rng), e(rng))));
  return v;
}

TEST(Dyadic, AddIntoEqualsRationalSum) {
  const std::uint64_t seed = 20261123;
  const auto v = samples(seed);
  for (const Rational& x : v)
    for (const Rational& y : v) {
      Rational sum;
      add_into(sum, x, y);
      Rational expected = x + y;
      ASSERT_EQ(sum, expected) << "seed " << seed << ": " << x << " + " << y;
      // Canonical: the same numerator and denominator as GMP's result.
      ASSERT_EQ(sum.get_den(), expected.get_den()) << x << " + " << y;
    }
}

TEST(Dyadic, SubtractIntoEqualsRationalDifference) {
  const std::uint64_t seed = 20261124;
  const auto v = samples(seed);
  for (const Rational& x : v)
    for (const Rational& y : v) {
      Rational difference;
      subtract_into(difference, x, y);
      const Rational expected = x - y;
      ASSERT_EQ(difference, expected) << "seed " << seed << ": " << x << " - " << y;
      ASSERT_EQ(difference.get_den(), expected.get_den()) << x << " - " << y;
    }
  const Vec3 p{Rational(1, 2), Rational(1, 3), Rational(-5, 4)};
  const Vec3 q{Rational(1, 2), Rational(1, 6), Rational(1, 64)};
  EXPECT_EQ(subtract(p, q), p - q);
}

TEST(Dyadic, AddIntoCancellationIsCanonical) {
  Rational sum;
  add_into(sum, Rational(3, 8), Rational(-3, 8));
  EXPECT_EQ(sum.get_num(), 0);
  EXPECT_EQ(sum.get_den(), 1);
  add_into(sum, Rational(3, 8), Rational(1, 8));  // 1/2: the common factor 4 must go
  EXPECT_EQ(sum.get_num(), 1);
  EXPECT_EQ(sum.get_den(), 2);
}

TEST(Dyadic, VectorAdd) {
  const Vec3 x{Rational(1, 2), Rational(1, 3), Rational(-5, 4)};
  const Vec3 y{Rational(1, 2), Rational(1, 6), Rational(1, 64)};
  EXPECT_EQ(add(x, y), x + y);
}

TEST(Dyadic, IntegerDotEqualsRationalDot) {
  const std::uint64_t seed = 77;
  const auto v = samples(seed);
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> coefficient(-1000000007L, 1000000007L);
  DotScratch scratch;
  for (std::size_t i = 0; i + 2 < v.size(); ++i) {
    const Vec3 p{v[i], v[i + 1], v[i + 2]};
    Vec3 n{Rational(coefficient(rng)), Rational(coefficient(rng)), Rational(0)};
    if (i % 3 == 0) n.z = Rational(mpz_class("123456789012345678901234567890"));
    Rational d(1, 3);  // overwritten, whatever it held
    integer_dot(n, p, scratch, d);
    const Rational expected = dot(n, p);
    ASSERT_EQ(d, expected) << "seed " << seed << " i " << i;
    ASSERT_EQ(d.get_den(), expected.get_den()) << "seed " << seed << " i " << i;
  }
}

}  // namespace
}  // namespace cvms::detail
