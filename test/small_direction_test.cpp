// SPDX-License-Identifier: MIT
// Machine-integer directions and primitive cross products against the
// rational primitive_direction (the oracle), including the cases that must
// fall back: non-doubles, exponents too far apart, coincident points.
#include "small_direction.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <random>
#include <string_view>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/rational.hpp"
#include "limb_arena.hpp"

namespace cvms::detail {
namespace {

Vec3 exact(double x, double y, double z) {
  return {rational_from_double(x), rational_from_double(y), rational_from_double(z)};
}

TEST(SmallDirection, MatchesRationalPrimitiveDirectionOnRandomDoubles) {
  const std::uint64_t seed = 4242;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> e(-20, 20);
  int small = 0;
  for (int i = 0; i < 2000; ++i) {
    const int scale = e(rng);
    const Vec3 p = exact(std::ldexp(u(rng), scale), u(rng), i % 7 == 0 ? 0.0 : u(rng));
    const Vec3 q = exact(std::ldexp(u(rng), scale), i % 5 == 0 ? to_double_nearest(p.y) : u(rng), u(rng));
    const auto d = small_integer_direction(ApproxVec3::of(p), ApproxVec3::of(q));
    if (!d) continue;  // a fallback is always allowed; a wrong answer never
    ++small;
    // A positive multiple of q - p: the same primitive direction.
    ASSERT_EQ(primitive_direction(d->to_vec3()), primitive_direction(q - p)) << "seed " << seed << " i " << i;
  }
  EXPECT_GT(small, 1000) << "the fast path should cover most moderate doubles";
}

TEST(SmallDirection, FallsBackWhereMachineIntegersCannotHoldIt) {
  const ApproxVec3 origin = ApproxVec3::of(exact(0, 0, 0));
  EXPECT_FALSE(small_integer_direction(origin, origin)) << "coincident points have no direction";
  // 1/3 is not a double: its approximation is not exact.
  const Vec3 third{Rational(1, 3), Rational(0), Rational(0)};
  EXPECT_FALSE(small_integer_direction(origin, ApproxVec3::of(third)));
  // Exponents 2^100 apart do not fit in 128 bits.
  EXPECT_FALSE(small_integer_direction(ApproxVec3::of(exact(1e-30, 0, 0)), ApproxVec3::of(exact(0, 1.0, 0))));
  // Along an axis the primitive direction is a unit vector whatever the scale.
  const auto axis = small_integer_direction(origin, ApproxVec3::of(exact(0, 0, -1e300)));
  ASSERT_TRUE(axis);
  EXPECT_EQ(primitive_direction(axis->to_vec3()), (Vec3{Rational(0), Rational(0), Rational(-1)}));
}

TEST(SmallDirection, CrossMatchesRationalPrimitiveCross) {
  const std::uint64_t seed = 99;
  std::mt19937_64 rng(seed);
  // Near the 2^62 limit so that the products need all of 128 bits.
  std::uniform_int_distribution<std::int64_t> c(-(std::int64_t{1} << 62) + 1, (std::int64_t{1} << 62) - 1);
  for (int i = 0; i < 500; ++i) {
    SmallDirection u{{c(rng), c(rng), i % 4 == 0 ? 0 : c(rng)}};
    SmallDirection v{{c(rng), c(rng), c(rng)}};
    if (i % 9 == 0) v.c = {u.c[0] / 3 * 3, u.c[1], 7};  // a common factor in the cross product
    const Vec3 uv = u.to_vec3(), vv = v.to_vec3();
    const Vec3 expected_cross = cross(uv, vv);
    if (is_zero(expected_cross)) continue;
    Vec3 c{Rational(5), Rational(-1, 3), Rational(7)};  // overwritten, whatever it held
    primitive_cross(u, v).assign_to(c);
    ASSERT_EQ(c, primitive_direction(expected_cross)) << "seed " << seed << " i " << i;
  }
}

// The same cross products as integers, before they become rationals: the
// vector assign_to and store write, and the approximations approx() reads
// off the integers, against ApproxVec3::of of the rational vector (same
// doubles, same bounds), also negated and for magnitudes of every size.
TEST(SmallDirection, SmallNormalsMatchTheirRationalsAndApproximations) {
  const std::uint64_t seed = 2612;
  std::mt19937_64 rng(seed);
  LimbArena arena;
  for (int i = 0; i < 3000; ++i) {
    const int bits = 1 + static_cast<int>(rng() % 62);  // coordinates of 1 to 62 bits: products of 2 to 125
    const std::int64_t limit = (std::int64_t{1} << bits) - 1;
    std::uniform_int_distribution<std::int64_t> c(-limit, limit);
    const SmallDirection u{{c(rng), c(rng), i % 5 == 0 ? 0 : c(rng)}};
    const SmallDirection v{{c(rng), c(rng), c(rng)}};
    const Vec3 expected_cross = cross(u.to_vec3(), v.to_vec3());
    if (is_zero(expected_cross)) continue;
    SmallNormal small = primitive_cross(u, v);
    Vec3 expected = primitive_direction(expected_cross);
    if (i % 2 == 1) {
      small.negate();
      expected = -expected;
    }
    SCOPED_TRACE("seed " + std::to_string(seed) + " i " + std::to_string(i));
    Vec3 assigned{Rational(5), Rational(-1, 3), Rational(7)};  // overwritten, whatever it held
    small.assign_to(assigned);
    ASSERT_EQ(assigned, expected);
    Vec3 stored{Rational(1, 2), Rational(3), Rational(-4, 9)};
    small.store(arena, stored);
    ASSERT_EQ(stored, expected);
    const ApproxVec3 approx = small.approx(), oracle = ApproxVec3::of(expected);
    const Approx* got[3] = {&approx.x, &approx.y, &approx.z};
    const Approx* want[3] = {&oracle.x, &oracle.y, &oracle.z};
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(got[k]->value, want[k]->value) << to_string(expected[k]);
      ASSERT_EQ(got[k]->error, want[k]->error) << to_string(expected[k]);
    }
  }
}

// Cross products with large common factors, odd and even: the gcd that
// makes them primitive runs the 128-bit binary gcd and, once both operands
// fit in 64 bits, its 64-bit tail; a common factor beyond 2^64 stays in 128
// bits to the end.
TEST(SmallDirection, CrossRemovesLargeCommonFactors) {
  const std::uint64_t seed = 1414;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::int64_t> small(-(std::int64_t{1} << 20), std::int64_t{1} << 20);
  std::uniform_int_distribution<int> bits(0, 35);  // shifts of 28 to 63 bits: factors of 1 to 36 bits
  for (int i = 0; i < 2000; ++i) {
    // u = k 2^s u', v = m v': cross(u, v) = k m 2^s cross(u', v').
    const std::int64_t k = (static_cast<std::int64_t>(rng() >> (28 + bits(rng))) | 1);
    const std::int64_t m = (static_cast<std::int64_t>(rng() >> (28 + bits(rng))) | 1);
    const int s = bits(rng) % 4;
    SmallDirection u{{small(rng), small(rng), small(rng)}};
    SmallDirection v{{small(rng), small(rng), small(rng)}};
    for (std::int64_t& x : u.c) x *= k << s;
    for (std::int64_t& x : v.c) x *= m;
    const Vec3 expected_cross = cross(u.to_vec3(), v.to_vec3());
    if (is_zero(expected_cross)) continue;
    Vec3 c;
    primitive_cross(u, v).assign_to(c);
    ASSERT_EQ(c, primitive_direction(expected_cross)) << "seed " << seed << " i " << i;
  }
}

// Short decimals and small fractions with different denominators: the two
// directions are the same positive multiple of b - a and c - a, so their
// primitive cross product is the rational one (the oracle).
TEST(SmallDirection, FractionDirectionsMatchRationalDifferences) {
  const std::uint64_t seed = 606;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> numerator(-1000000, 1000000);
  const long denominators[] = {1, 3, 7, 10, 1000000, 1 << 20, 999983};
  std::uniform_int_distribution<std::size_t> pick(0, std::size(denominators) - 1);
  int small = 0;
  for (int i = 0; i < 3000; ++i) {
    Vec3 p[3];
    for (Vec3& q : p)
      for (int k = 0; k < 3; ++k) q[k] = Rational(numerator(rng), denominators[i % 5 == 0 ? pick(rng) : 4]);
    for (Vec3& q : p)
      for (int k = 0; k < 3; ++k) q[k].canonicalize();
    if (i % 11 == 0) p[2] = p[0];  // coincident: no direction
    const auto d = small_fraction_directions(p[0], p[1], p[2]);
    if (p[0] == p[1] || p[0] == p[2]) {
      EXPECT_FALSE(d) << "seed " << seed << " i " << i;
      continue;
    }
    if (!d) continue;  // a fallback is always allowed; a wrong answer never
    ++small;
    const Vec3 u = (*d)[0].to_vec3(), v = (*d)[1].to_vec3();
    const Vec3 ab = p[1] - p[0], ac = p[2] - p[0];
    ASSERT_EQ(primitive_direction(u), primitive_direction(ab)) << "seed " << seed << " i " << i;
    ASSERT_EQ(primitive_direction(v), primitive_direction(ac)) << "seed " << seed << " i " << i;
    // The same multiple of both: u ab-component ratios agree with v's.
    ASSERT_EQ(u.x * ac.x, v.x * ab.x) << "seed " << seed << " i " << i;
    const Vec3 n = cross(ab, ac);
    if (is_zero(n)) continue;
    Vec3 c;
    primitive_cross((*d)[0], (*d)[1]).assign_to(c);
    ASSERT_EQ(c, primitive_direction(n)) << "seed " << seed << " i " << i;
  }
  EXPECT_GT(small, 2000) << "short decimals should take the fast path";
}

TEST(SmallDirection, FractionDirectionsFallBackBeyondTheirLimits) {
  const Vec3 a{Rational(0), Rational(0), Rational(0)};
  const Vec3 b{Rational(1), Rational(0), Rational(0)};
  const Vec3 c{Rational(0), Rational(1), Rational(0)};
  EXPECT_TRUE(small_fraction_directions(a, b, c));
  // A denominator of two limbs, a common denominator of 2^63 and more, and a
  // numerator that scales beyond 2^61.
  const Vec3 huge_den{Rational(1, mpz_class(1) << 70), Rational(0), Rational(0)};
  EXPECT_FALSE(small_fraction_directions(a, huge_den, c));
  EXPECT_FALSE(small_fraction_direction(a, huge_den));
  // (2^32 + 1)(2^32 + 3) > 2^64: two odd numbers 2 apart are coprime.
  const Vec3 coprime{Rational(1, (1L << 32) + 1), Rational(1, (1L << 32) + 3), Rational(0)};
  EXPECT_FALSE(small_fraction_directions(a, coprime, c));
  EXPECT_FALSE(small_fraction_direction(a, coprime));
  // A common denominator just below 2^40 (the product of two coprime ones)
  // is well within the limit.
  const Vec3 below_2_40{Rational(1, (1L << 20) + 7), Rational(1, (1L << 20) + 9), Rational(0)};
  EXPECT_TRUE(small_fraction_directions(a, below_2_40, c));
  const Vec3 big{Rational(mpz_class(1) << 62), Rational(0), Rational(0)};
  EXPECT_FALSE(small_fraction_directions(a, big, c));
  EXPECT_FALSE(small_fraction_direction(a, big));
}

// The word-size bounds of the common denominator: 10^18 < 2^63 <= 10^19
// (both one limb), 2^62 < 2^63, and 2^61 * 5 (the lcm of 2^61 and 10) past it.
TEST(SmallDirection, FractionDirectionAtTheWordSizeBounds) {
  const Vec3 origin{Rational(0), Rational(0), Rational(0)};
  const auto point = [](const Rational& x) {
    Vec3 p{x, Rational(1, 4), Rational(-1, 8)};  // scaled by 2^62: below 2^61
    return p;
  };
  const mpz_class ten_18("1000000000000000000"), ten_19("10000000000000000000");
  const Rational at_10_18(mpz_class("123456789012345678"), ten_18);
  const Rational at_10_19(mpz_class("1234567890123456789"), ten_19);
  const Rational at_2_62(mpz_class(1), mpz_class(1) << 62);
  const Rational at_2_61_times_10 = Rational(1, 10) + Rational(mpz_class(1), mpz_class(1) << 61);
  for (const Rational& x : {at_10_18, at_2_62}) {
    const auto d = small_fraction_direction(origin, point(x));
    ASSERT_TRUE(d) << x;
    EXPECT_EQ(primitive_direction(d->to_vec3()), primitive_direction(point(x) - origin)) << x;
  }
  EXPECT_FALSE(small_fraction_direction(origin, point(at_10_19)));
  EXPECT_FALSE(small_fraction_direction(origin, point(at_2_61_times_10)));
}

// Shortest round-trip decimals of doubles (up to 17 significant digits, the
// form numpy and most exporters write), mixed with the doubles' own dyadic
// values: every direction the fast path gives is a positive multiple of the
// rational difference (the oracle), and most decimal pairs take it.
TEST(SmallDirection, FractionDirectionOfShortestDecimals) {
  const std::uint64_t seed = 5252;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto decimal = [&](double d) {
    char digits[32];
    const auto r = std::to_chars(digits, digits + sizeof digits, d);
    return parse_rational(std::string_view(digits, static_cast<std::size_t>(r.ptr - digits)));
  };
  int small = 0, decimal_pairs = 0;
  for (int i = 0; i < 3000; ++i) {
    Vec3 p[2];
    const bool mixed = i % 3 == 0;
    for (int q = 0; q < 2; ++q)
      for (int k = 0; k < 3; ++k) {
        const double d = unit(rng);
        p[q][k] = mixed && q == 1 ? rational_from_double(d) : decimal(d);
      }
    if (i % 13 == 0) p[1] = p[0];
    const auto d = small_fraction_direction(p[0], p[1]);
    if (p[0] == p[1]) {
      EXPECT_FALSE(d) << "seed " << seed << " i " << i;
      continue;
    }
    if (!mixed) ++decimal_pairs;
    if (!d) continue;  // a fallback is always allowed; a wrong answer never
    if (!mixed) ++small;
    ASSERT_EQ(primitive_direction(d->to_vec3()), primitive_direction(p[1] - p[0])) << "seed " << seed << " i " << i;
  }
  EXPECT_GT(small, decimal_pairs * 9 / 10) << "shortest decimals should take the fast path";
}

}  // namespace
}  // namespace cvms::detail
