// SPDX-License-Identifier: MIT
// The crossing point of a segment and a plane on integers
// (lib/boundary/plane_crossing.hpp), against independent answers:
//  - a plane built through a known point a + w (b - a), w a random rational
//    in (0, 1): the crossing must be that point;
//  - planes whose crossing lies next to an end (w = 2^-k, 1 - 2^-k, and
//    non-dyadic w of tiny size): the near-plane cases;
//  - any integer normal and an offset strictly between the ends' values:
//    plain canonical Rational evaluation of a + t (b - a), t = s_a / (s_a - s_b);
// with coordinates as doubles, decimals, long fractions and huge or tiny
// non-dyadic values (test/support/random_numbers.hpp), ends sharing one
// denominator or not; every result is checked canonical (positive
// denominator, no common factor), as the library's rationals must be.
#include <gtest/gtest.h>

#include <cstdint>
#include <deque>

#include "plane_clip.hpp"
#include "plane_crossing.hpp"
#include "support/random_numbers.hpp"

namespace {

using cvms::Rational;
using cvms::Vec3;
using cvms::test::Rng;

bool canonical(const Rational& q) {
  if (mpz_sgn(q.get_den_mpz_t()) <= 0) return false;
  mpz_class g;
  mpz_gcd(g.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return g == 1;
}

// A random point: coordinates of the random kinds, or (one time in three)
// all over one shared denominator, as the corners of a sum often are.
Vec3 random_point(Rng& rng) {
  if (rng() % 3 == 0) {
    const mpz_class den = cvms::test::random_integer(rng, 90) * 2 + 1;
    Vec3 p;
    for (int k = 0; k < 3; ++k) p[k] = cvms::test::fraction(cvms::test::random_integer(rng, 120), abs(den));
    return p;
  }
  return {cvms::test::random_rational(rng), cvms::test::random_rational(rng), cvms::test::random_rational(rng)};
}

// A nonzero integer vector, small or large.
Vec3 random_integer_normal(Rng& rng) {
  for (;;) {
    const unsigned bits = rng() % 2 == 0 ? 4 : 100;
    Vec3 n{Rational(cvms::test::random_integer(rng, bits)), Rational(cvms::test::random_integer(rng, bits)),
           Rational(cvms::test::random_integer(rng, bits))};
    if (n.x != 0 || n.y != 0 || n.z != 0) return n;
  }
}

// A rational weight strictly inside (0, 1), including ones next to 0 and 1.
Rational random_weight(Rng& rng) {
  switch (rng() % 4) {
    case 0:
      return cvms::test::power_of_two(-static_cast<long>(rng() % 200) - 1);
    case 1:
      return 1 - cvms::test::power_of_two(-static_cast<long>(rng() % 200) - 1);
    case 2:
      return Rational(1, 3) * cvms::test::power_of_ten(-static_cast<long>(rng() % 40) - 1);
    default: {
      const mpz_class den = abs(cvms::test::random_integer(rng, 80)) + 2;
      const mpz_class num = abs(cvms::test::random_integer(rng, 80)) % (den - 1) + 1;
      return cvms::test::fraction(num, den);
    }
  }
}

void expect_crossing(const Vec3& a, const Vec3& b, const Vec3& n, const Rational& offset, const Vec3& expected,
                     std::uint64_t seed, int i) {
  Vec3 x;
  cvms::detail::plane_crossing(a, b, n, offset, x);
  for (int k = 0; k < 3; ++k) {
    ASSERT_TRUE(canonical(x[k])) << "seed " << seed << ", case " << i << ", coordinate " << k;
    ASSERT_EQ(x[k], expected[k]) << "seed " << seed << ", case " << i << ", coordinate " << k;
  }
}

TEST(PlaneCrossing, ThroughAKnownPoint) {
  for (const std::uint64_t seed : {11U, 12U, 13U}) {
    Rng rng(seed);
    for (int i = 0; i < 300; ++i) {
      const Vec3 a = random_point(rng);
      const Vec3 b = random_point(rng);
      if (a == b) continue;
      const Vec3 n = random_integer_normal(rng);
      if (dot(n, a) == dot(n, b)) continue;  // the segment is parallel to the plane
      const Rational w = random_weight(rng);
      const Vec3 expected{a.x + w * (b.x - a.x), a.y + w * (b.y - a.y), a.z + w * (b.z - a.z)};
      expect_crossing(a, b, n, dot(n, expected), expected, seed, i);
    }
  }
}

TEST(PlaneCrossing, AgainstRationalEvaluation) {
  for (const std::uint64_t seed : {21U, 22U}) {
    Rng rng(seed);
    for (int i = 0; i < 300; ++i) {
      const Vec3 a = random_point(rng);
      const Vec3 b = random_point(rng);
      const Vec3 n = random_integer_normal(rng);
      const Rational da = dot(n, a), db = dot(n, b);
      if (da == db) continue;
      // An offset strictly between the ends' values: a random rational one,
      // or the ends' mean.
      const Rational offset = rng() % 2 == 0 ? Rational((da + db) / 2) : Rational(da + random_weight(rng) * (db - da));
      const Rational sa = da - offset, sb = db - offset;
      const Rational t = sa / (sa - sb);
      const Vec3 expected{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
      expect_crossing(a, b, n, offset, expected, seed, i);
    }
  }
}

TEST(PlaneCrossing, HandChecked) {
  // The segment from (0, 0, 0) to (3, 3, 3) and the plane x + y + z = 3
  // meet at (1, 1, 1); from (1/3, 0, 7/10) to (1/3, 2, 7/10) and 5 y = 1,
  // at (1/3, 1/5, 7/10).
  Vec3 x;
  cvms::detail::plane_crossing({0, 0, 0}, {3, 3, 3}, {1, 1, 1}, 3, x);
  EXPECT_EQ(x, (Vec3{1, 1, 1}));
  cvms::detail::plane_crossing({Rational(1, 3), 0, Rational(7, 10)}, {Rational(1, 3), 2, Rational(7, 10)}, {0, 5, 0},
                               1, x);
  EXPECT_EQ(x, (Vec3{Rational(1, 3), Rational(1, 5), Rational(7, 10)}));
  // Ends swapped, a negative normal: the same point.
  cvms::detail::plane_crossing({3, 3, 3}, {0, 0, 0}, {-1, -1, -1}, -3, x);
  EXPECT_EQ(x, (Vec3{1, 1, 1}));
}

// split() with a plane whose normal is not an integer vector (the rational
// road) cuts as the integer multiple of that plane does.
TEST(PlaneCrossing, SplitByRationalAndIntegerNormalsAgree) {
  cvms::detail::ClipPoints points;
  for (const Vec3& p : {Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{2, 2, 0}, Vec3{0, 2, 0}})
    points.push_back({p, cvms::ApproxVec3::of(p)});
  const cvms::detail::ClipPolygon square = {0, 1, 2, 3};
  // 2 x + y <= 3 and (2/3) x + (1/3) y <= 1: the same half-space.
  struct Plane {
    Vec3 normal;
    cvms::ApproxVec3 approx;
    Rational offset;
  };
  std::deque<Plane> store;
  const auto plane = [&store](const Vec3& n, const Rational& o) {
    store.push_back({n, cvms::ApproxVec3::of(n), o});
    const Plane& p = store.back();
    return cvms::detail::ClipPlane{&p.normal, &p.approx, &p.offset, cvms::Approx::of(p.offset)};
  };
  const auto integer = cvms::detail::split(points, square, plane({2, 1, 0}, 3));
  const auto rational = cvms::detail::split(points, square, plane({Rational(2, 3), Rational(1, 3), 0}, 1));
  ASSERT_EQ(integer.inside.size(), rational.inside.size());
  ASSERT_EQ(integer.outside.size(), rational.outside.size());
  for (std::size_t i = 0; i < integer.inside.size(); ++i)
    EXPECT_EQ(points[integer.inside[i]].exact, points[rational.inside[i]].exact);
  // The crossings, by hand: (3/2, 0, 0) and (1/2, 2, 0).
  EXPECT_EQ(points[4].exact, (Vec3{Rational(3, 2), 0, 0}));
  EXPECT_EQ(points[5].exact, (Vec3{Rational(1, 2), 2, 0}));
}

}  // namespace
