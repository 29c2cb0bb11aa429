// SPDX-License-Identifier: MIT
// Tests of the integer orient3d for dyadic coordinates (lib/predicates/dyadic_orient.hpp)
// against the rational evaluation: random and exactly coplanar points, at
// every scale from subnormal to huge, and the refusal of other rationals.
#include "dyadic_orient.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "predicates_exact.hpp"

namespace cvms {
namespace {

TEST(DyadicOrient, MatchesRationalEvaluation) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int exponents[] = {0, -30, 40, -1074, 1000, -600};
  int zeros = 0, checked = 0;
  for (int round = 0; round < 3000; ++round) {
    // Mixed exponents per point, so the common denominator differs from
    // every coordinate's own.
    auto coord = [&]() -> Rational {  // not a gmpxx expression of dead temporaries
      const int e = exponents[rng() % 6];
      return Rational(std::ldexp(u(rng), e)) +
             (rng() % 3 == 0 ? Rational(static_cast<long>(rng() % 5) - 2) : 0);
    };
    Vec3 p[4];
    for (Vec3& q : p) q = {coord(), coord(), coord()};
    if (round % 3 == 0) {
      // d on the plane of a, b, c, with dyadic weights: orient3d == 0.
      Rational s(static_cast<long>(rng() % 17) - 8, 4), t(static_cast<long>(rng() % 17) - 8, 8);
      s.canonicalize();  // gmpxx does not reduce p/q on construction
      t.canonicalize();
      p[3] = p[0] + s * (p[1] - p[0]) + t * (p[2] - p[0]);
    } else if (round % 3 == 1) {
      p[3] = p[0] + (p[1] - p[0]) * Rational(1, 2) + Vec3{0, 0, Rational(std::ldexp(1.0, -1074))};
    }
    const auto s = dyadic_orient3d(p[0], p[1], p[2], p[3]);
    ASSERT_TRUE(s.has_value());
    const Sign expected = exact::orient3d(p[0], p[1], p[2], p[3]);
    ASSERT_EQ(*s, expected) << "round " << round;
    zeros += expected == Sign::zero;
    ++checked;
  }
  EXPECT_GE(zeros, 900);
  EXPECT_EQ(checked, 3000);
}

TEST(DyadicOrient, RefusesOtherRationals) {
  const Vec3 a{1, 2, 3}, b{4, 5, 6}, c{Rational(1, 3), 0, 0}, d{0, 1, 0};
  EXPECT_FALSE(dyadic_orient3d(a, b, c, d).has_value());
  EXPECT_FALSE(dyadic_orient3d(d, Vec3{0, Rational(3, 10), 1}, a, b).has_value());
  EXPECT_EQ(dyadic_orient3d(a, b, Vec3{0, 0, 1}, d), exact::orient3d(a, b, Vec3{0, 0, 1}, d));
}

}  // namespace
}  // namespace cvms
