// SPDX-License-Identifier: MIT
// The gcd-free dyadic operations against GMP's general rational arithmetic
// (the oracle), on dyadic and non-dyadic values, signs, zeros and extreme
// exponents.
#include "dyadic.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "cvms/rational.hpp"
#include "limb_arena.hpp"
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

// Dyadic values at the fixed paths' bounds: numerators of one, two and three
// limbs, exponents from 0 to past 2^128 apart, both signs, zero, integers.
std::vector<Rational> fixed_path_samples(std::uint64_t seed) {
  std::vector<Rational> v = {Rational(0), Rational(1),    Rational(-1),
                             Rational(7), Rational(3, 4), Rational(-1, 1024)};
  std::mt19937_64 rng(seed);
  for (int limbs = 1; limbs <= 3; ++limbs)
    for (unsigned exponent : {0u, 1u, 52u, 63u, 64u, 65u, 127u, 128u, 129u, 130u, 200u}) {
      mpz_class num = 0;
      for (int i = 0; i < limbs; ++i) num = (num << 64) + mpz_class(std::to_string(rng() | 1));
      mpz_class den = 0;
      mpz_setbit(den.get_mpz_t(), exponent);
      Rational q(num, den);
      q.canonicalize();
      v.push_back(q);
      v.push_back(-q);
    }
  return v;
}

// Whether the fixed paths' documented bounds hold for a value: dyadic with a
// numerator and a denominator below 2^64 (the test's own reading, not the
// code's).
bool short_dyadic_value(const Rational& q) {
  return mpz_sizeinbase(q.get_num_mpz_t(), 2) <= 64 && mpz_popcount(q.get_den_mpz_t()) == 1 &&
         mpz_sizeinbase(q.get_den_mpz_t(), 2) <= 64;
}

TEST(Dyadic, FixedSumEqualsRationalSumWithinItsBounds) {
  const std::uint64_t seed = 20261204;
  const auto v = fixed_path_samples(seed);
  LimbArena arena;
  Rational scratch, reused;
  for (const Rational& x : v)
    for (const Rational& y : v) {
      const Rational expected = x + y;
      const bool in_bounds = short_dyadic_value(x) && short_dyadic_value(y);
      const auto fixed = fixed_sum(x, y);
      ASSERT_EQ(fixed.has_value(), in_bounds) << "seed " << seed << ": " << x << " + " << y;
      ASSERT_EQ(fixed_difference(x, y).has_value(), in_bounds) << "seed " << seed << ": " << x << " - " << y;
      // add_into and subtract_into take the same path, into a value reused
      // from pair to pair.
      add_into(reused, x, y);
      ASSERT_EQ(reused, expected) << "seed " << seed << ": " << x << " + " << y;
      ASSERT_EQ(reused.get_den(), expected.get_den()) << "canonical: " << x << " + " << y;
      subtract_into(reused, x, y);
      ASSERT_EQ(reused, x - y) << "seed " << seed << ": " << x << " - " << y;
      ASSERT_EQ(reused.get_den(), Rational(x - y).get_den()) << "canonical: " << x << " - " << y;
      Rational stored;
      store_sum(arena, stored, x, y, scratch);
      ASSERT_EQ(stored, expected) << "seed " << seed << ": " << x << " + " << y;
      ASSERT_EQ(stored.get_den(), expected.get_den()) << "canonical: " << x << " + " << y;
      ASSERT_EQ(stored.get_num(), expected.get_num()) << "canonical: " << x << " + " << y;
    }
}

TEST(Dyadic, FixedIntegerDotEqualsRationalDotWithinItsBounds) {
  const std::uint64_t seed = 20261205;
  const auto v = fixed_path_samples(seed);
  std::mt19937_64 rng(seed);
  const std::vector<mpz_class> coefficients = {
      0,
      1,
      -1,
      mpz_class("123456789012345678901"),
      mpz_class("-340282366920938463463374607431768211455"),
      mpz_class("340282366920938463463374607431768211456")};  // the last has three limbs
  LimbArena arena;
  DotScratch scratch;
  std::uniform_int_distribution<std::size_t> pick(0, v.size() - 1), pick_c(0, coefficients.size() - 1);
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec3 p{v[pick(rng)], v[pick(rng)], v[pick(rng)]};
    const Vec3 n{Rational(coefficients[pick_c(rng)]), Rational(coefficients[pick_c(rng)]),
                 Rational(coefficients[pick_c(rng)])};
    const Rational expected = n.x * p.x + n.y * p.y + n.z * p.z;
    bool in_bounds = true;
    for (int i = 0; i < 3; ++i) {
      in_bounds = in_bounds && mpz_sizeinbase(n[i].get_num_mpz_t(), 2) <= 128;
      if (sgn(n[i]) != 0) in_bounds = in_bounds && short_dyadic_value(p[i]);
    }
    ASSERT_EQ(fixed_integer_dot(n, p).has_value(), in_bounds) << "seed " << seed << " trial " << trial;
    Rational stored, plain(5, 3);
    store_integer_dot(arena, stored, n, p, scratch);
    integer_dot(n, p, scratch, plain);
    for (const Rational* d : {&stored, &plain}) {
      ASSERT_EQ(*d, expected) << "seed " << seed << " trial " << trial;
      ASSERT_EQ(d->get_den(), expected.get_den()) << "canonical, seed " << seed << " trial " << trial;
    }
  }
}

// store_dyadic into every kind of value: fresh, owning long limbs, and a
// view an arena made (with a long denominator) before.
TEST(Dyadic, StoreDyadicReducesIntoEveryKindOfValue) {
  LimbArena arena;
  Rational owning(mpz_class("1267650600228229401496703205377"), mpz_class("36893488147419103232"));
  Rational view;
  store_dyadic(arena, view, FixedDyadic<2>{FixedInt<2>{{3, 0}, true}, 100});
  EXPECT_EQ(view, Rational(mpz_class(-3), mpz_class(1) << 100));
  struct Case {
    FixedDyadic<3> value;
    Rational expected;
  };
  const std::vector<Case> cases = {
      {{FixedInt<3>{{0, 0, 0}, true}, 77}, Rational(0)},
      {{FixedInt<3>{{8, 0, 0}, false}, 3}, Rational(1)},
      {{FixedInt<3>{{8, 0, 0}, true}, 2}, Rational(-2)},
      {{FixedInt<3>{{0, 0, 1}, false}, 128}, Rational(1)},
      {{FixedInt<3>{{0, 0, 1}, false}, 130}, Rational(1, 4)},
      {{FixedInt<3>{{0, 2, 0}, false}, 200}, Rational(mpz_class(1), mpz_class(1) << 135)},
      {{FixedInt<3>{{6, 0, 0}, true}, 64}, Rational(mpz_class(-3), mpz_class(1) << 63)},
      {{FixedInt<3>{{~std::uint64_t{0}, 5, 0}, false}, 0},
       Rational((mpz_class(5) << 64) + mpz_class("18446744073709551615"))},
  };
  for (const Case& c : cases)
    for (Rational* out : {&owning, &view}) {
      store_dyadic(arena, *out, c.value);
      EXPECT_EQ(*out, c.expected);
      EXPECT_EQ(out->get_den(), c.expected.get_den());
      EXPECT_EQ(out->get_num(), c.expected.get_num());
    }
}

}  // namespace
}  // namespace cvms::detail
