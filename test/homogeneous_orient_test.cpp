// SPDX-License-Identifier: MIT
// Tests of the integer orient3d on homogeneous points
// (lib/predicates/homogeneous_orient.hpp) against the rational evaluation of
// the points they stand for: random weights and coordinates of up to ~190
// bits, exactly coplanar points, and every permutation's sign; the
// farther-point comparison the same way, with ties.
#include "homogeneous_orient.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

#include "fixed_det4.hpp"
#include "predicates_exact.hpp"

namespace cvms {
namespace {

using Rng = std::mt19937_64;

mpz_class random_integer(Rng& rng, int words, bool positive) {
  mpz_class v = 0;
  for (int k = 0; k < words; ++k) v = (v << 63) + mpz_class(static_cast<unsigned long>(rng() >> 1));
  if (positive) return v + 1;
  return rng() % 2 == 0 ? mpz_class(-v) : v;
}

Vec3 standing_for(const HomogeneousPoint& p) {
  Vec3 q{Rational(p.x, p.w), Rational(p.y, p.w), Rational(p.z, p.w)};
  for (int k = 0; k < 3; ++k) q[k].canonicalize();
  return q;
}

HomogeneousPoint random_point(Rng& rng, int words) {
  return {random_integer(rng, words, false), random_integer(rng, words, false), random_integer(rng, words, false),
          random_integer(rng, 1 + static_cast<int>(rng() % words), true)};
}

TEST(HomogeneousOrient, MatchesRationalEvaluation) {
  Rng rng(1601);
  int zeros = 0;
  for (int round = 0; round < 2000; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    const int words = 1 + round % 3;
    std::array<HomogeneousPoint, 4> p;
    for (HomogeneousPoint& q : p) q = random_point(rng, words);
    if (round % 2 == 0) {
      // d = a + s (b − a) + t (c − a) with small integer s, t, written over
      // the weight w_a w_b w_c: coplanar, orient3d == 0.
      const long s = static_cast<long>(rng() % 7) - 3, t = static_cast<long>(rng() % 7) - 3;
      const mpz_class wa = p[0].w, wb = p[1].w, wc = p[2].w, w = wa * wb * wc;
      auto coord = [&](const mpz_class& a, const mpz_class& b, const mpz_class& c) {
        return mpz_class(a * wb * wc * (1 - s - t) + s * b * wa * wc + t * c * wa * wb);
      };
      p[3] = {coord(p[0].x, p[1].x, p[2].x), coord(p[0].y, p[1].y, p[2].y), coord(p[0].z, p[1].z, p[2].z), w};
    }
    const Vec3 q[4] = {standing_for(p[0]), standing_for(p[1]), standing_for(p[2]), standing_for(p[3])};
    const Sign expected = exact::orient3d(q[0], q[1], q[2], q[3]);
    zeros += expected == Sign::zero;
    EXPECT_EQ(homogeneous_orient3d(p[0], p[1], p[2], p[3]), expected);
    // An odd permutation flips the sign; scaling a point's coordinates and
    // weight by a positive factor changes nothing.
    EXPECT_EQ(homogeneous_orient3d(p[1], p[0], p[2], p[3]), -expected);
    HomogeneousPoint scaled{p[2].x * 7, p[2].y * 7, p[2].z * 7, p[2].w * 7};
    EXPECT_EQ(homogeneous_orient3d(p[0], p[1], scaled, p[3]), expected);
  }
  EXPECT_GE(zeros, 1000);
}

template <int E>
int fixed_compare(const std::array<HomogeneousPoint, 5>& p) {
  auto row = [](const HomogeneousPoint& x) {
    return detail::fixed_row<E>({x.x.get_mpz_t(), x.y.get_mpz_t(), x.z.get_mpz_t(), x.w.get_mpz_t()});
  };
  const detail::Cofactors<E> cof = detail::last_row_cofactors<E>(row(p[0]), row(p[1]), row(p[2]));
  return detail::fixed_det4_cross_sign<E>(cof, row(p[3]), row(p[4]));
}

// The farther-point comparison (homogeneous_compare_orient3d) against the
// rational compare_dot of the points with the triangle's normal, with ties:
// q = p + s (b − a) + t (c − a) lies as far above the plane as p. The
// fixed-width form the dual hull uses (fixed_det4_cross_sign on the
// cofactors of a, b, c, negated) must agree with both.
TEST(HomogeneousOrient, CompareMatchesRationalCompareDot) {
  Rng rng(1606);
  int ties = 0, fixed = 0;
  for (int round = 0; round < 2000; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    const int words = 1 + round % 3;
    std::array<HomogeneousPoint, 5> p;
    for (HomogeneousPoint& q : p) q = random_point(rng, words);
    if (round % 2 == 0) {
      const long s = static_cast<long>(rng() % 7) - 3, t = static_cast<long>(rng() % 7) - 3;
      const mpz_class wa = p[0].w, wb = p[1].w, wc = p[2].w, wp = p[3].w, w = wa * wb * wc * wp;
      auto coord = [&](const mpz_class& a, const mpz_class& b, const mpz_class& c, const mpz_class& x) {
        return mpz_class(x * wa * wb * wc + (s * (b * wa - a * wb) * wc + t * (c * wa - a * wc) * wb) * wp);
      };
      p[4] = {coord(p[0].x, p[1].x, p[2].x, p[3].x), coord(p[0].y, p[1].y, p[2].y, p[3].y),
              coord(p[0].z, p[1].z, p[2].z, p[3].z), w};
    }
    Vec3 q[5];
    for (int k = 0; k < 5; ++k) q[k] = standing_for(p[k]);
    const Sign expected = exact::compare_dot(q[3], q[4], cross(q[1] - q[0], q[2] - q[0]));
    ties += expected == Sign::zero;
    EXPECT_EQ(homogeneous_compare_orient3d(p[0], p[1], p[2], p[3], p[4]), expected);
    EXPECT_EQ(homogeneous_compare_orient3d(p[0], p[1], p[2], p[4], p[3]), -expected);
    EXPECT_EQ(homogeneous_compare_orient3d(p[1], p[0], p[2], p[3], p[4]), -expected);
    int limbs = 1;
    for (const HomogeneousPoint& x : p)
      for (const mpz_class* v : {&x.x, &x.y, &x.z, &x.w}) limbs = std::max(limbs, detail::signed_limbs(v->get_mpz_t()));
    if (limbs <= 4) {
      ++fixed;
      const int got = limbs == 1   ? fixed_compare<1>(p)
                      : limbs == 2 ? fixed_compare<2>(p)
                      : limbs == 3 ? fixed_compare<3>(p)
                                   : fixed_compare<4>(p);
      EXPECT_EQ(sign_of(-got), expected);
    }
  }
  EXPECT_GE(ties, 1000);
  EXPECT_GE(fixed, 1000);
}

TEST(HomogeneousOrient, UnitWeightsAreTheIntegerPoints) {
  // The unit tetrahedron: d = (0, 0, 1) is above the counterclockwise
  // triangle (0,0,0), (1,0,0), (0,1,0) seen from +z, so orient3d > 0.
  const HomogeneousPoint o{0, 0, 0, 1}, x{1, 0, 0, 1}, y{0, 1, 0, 1}, z{0, 0, 1, 1}, below{0, 0, -1, 3};
  EXPECT_EQ(homogeneous_orient3d(o, x, y, z), Sign::positive);
  EXPECT_EQ(homogeneous_orient3d(o, x, y, below), Sign::negative);
  EXPECT_EQ(homogeneous_orient3d(o, x, y, HomogeneousPoint{5, 7, 0, 2}), Sign::zero);
}

}  // namespace
}  // namespace cvms
