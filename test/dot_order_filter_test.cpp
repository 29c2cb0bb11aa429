// SPDX-License-Identifier: MIT
// Tests of the walk's semi-static dot-order filter
// (lib/numeric/dot_order_filter.hpp): every order it claims must be the
// exact compare_dot of the exact points, on near ties, at extreme scales,
// with inexact approximations of the points and of the direction, and it
// must claim nothing beyond its range.
#include "dot_order_filter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "approx.hpp"
#include "cvms/predicates.hpp"
#include "cvms/rational.hpp"

namespace cvms {
namespace {

struct Tally {
  int decided = 0, total = 0;
};

PlaneFilterExtent extent_of(const std::vector<ApproxVec3>& approx) {
  PlaneFilterExtent extent;
  for (const ApproxVec3& a : approx) extent.add(a);
  return extent;
}

// Every sign the filter claims for one point against the exact sign_dot.
void check_sign_claims(const std::vector<Vec3>& exact, const std::vector<ApproxVec3>& approx, const Vec3& n,
                       const ApproxVec3& n_approx, Tally& tally, std::uint64_t seed) {
  const DotOrderFilter filter(n_approx, extent_of(approx));
  for (std::size_t i = 0; i < exact.size(); ++i) {
    const std::optional<Sign> claim = filter.sign(filter.value(approx[i]));
    ++tally.total;
    if (!claim) continue;
    ++tally.decided;
    ASSERT_EQ(*claim, sign_dot(exact[i], n)) << "point " << i << " (seed " << seed << ")";
  }
}

// Every pair's claim against the exact compare_dot of the exact points,
// with the given approximations of them, and every point's sign claim.
void check_claims(const std::vector<Vec3>& exact, const std::vector<ApproxVec3>& approx, const Vec3& n,
                  const ApproxVec3& n_approx, Tally& tally, std::uint64_t seed) {
  Tally signs;
  check_sign_claims(exact, approx, n, n_approx, signs, seed);
  if (::testing::Test::HasFatalFailure()) return;
  const DotOrderFilter filter(n_approx, extent_of(approx));
  for (std::size_t i = 0; i < exact.size(); ++i)
    for (std::size_t j = 0; j < exact.size(); ++j) {
      const std::optional<Sign> claim = filter.compare(filter.value(approx[i]), filter.value(approx[j]));
      ++tally.total;
      if (!claim) continue;
      ++tally.decided;
      ASSERT_EQ(*claim, compare_dot(exact[i], exact[j], n))
          << "points " << i << ", " << j << " (seed " << seed << ")";
    }
}

// As above, with the points' own approximations (Approx::of).
void check_claims(const std::vector<Vec3>& exact, const Vec3& n, const ApproxVec3& n_approx, Tally& tally,
                  std::uint64_t seed) {
  std::vector<ApproxVec3> approx;
  for (const Vec3& p : exact) approx.push_back(ApproxVec3::of(p));
  check_claims(exact, approx, n, n_approx, tally, seed);
}

// Points of doubles on one plane dot(n, x) = c, c = offset * scale * n_z
// (rounded, so within a few ulps of it) nudged by 0..3 ulps per coordinate,
// with some off the plane: near ties are the hardest decisions for a filter
// (offset 0: near-zero values, the hardest signs).
std::vector<Vec3> near_ties(std::mt19937_64& rng, const Vec3& n, double scale, int count, double offset = 1.0) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double nx = to_double_nearest(n.x), ny = to_double_nearest(n.y), nz = to_double_nearest(n.z);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) {
    double x = scale * u(rng), y = scale * u(rng);
    // On the plane dot(n, p) = offset * scale * nz (n.z is never 0 below).
    double z = (offset * scale * nz - nx * x - ny * y) / nz;
    if (i % 5 == 0) z = scale * u(rng);
    for (double* c : {&x, &y, &z})
      for (int nudge = static_cast<int>(rng() % 4); nudge > 0; --nudge)
        *c = std::nextafter(*c, rng() % 2 ? INFINITY : -INFINITY);
    points.push_back({Rational(x), Rational(y), Rational(z)});
  }
  return points;
}

// Runs check(scale) for each scale under a trace that names it, until one
// fails fatally.
template <class Check>
void at_each_scale(std::initializer_list<double> scales, Check&& check) {
  for (const double scale : scales) {
    std::ostringstream trace;
    trace << "scale " << std::hexfloat << scale;
    SCOPED_TRACE(trace.str());
    check(scale);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

TEST(DotOrderFilter, ClaimsAreExactOnDoubles) {
  // Scales from subnormal products to the filter's limit of 2^300.
  at_each_scale({1.0, 1e-5, 1e5, 0x1p290, 1e-150, 1e-300, 0x1p-1060}, [](double scale) {
    Tally tally;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      std::mt19937_64 rng(seed);
      // An integer normal (what the walk's directions are) and a double one.
      const Vec3 n =
          seed % 2 ? Vec3{static_cast<long>(rng() % 2001) - 1000, static_cast<long>(rng() % 2001) - 1000,
                          static_cast<long>(rng() % 1000) + 1}
                   : Vec3{Rational(0.3 + 1e-9 * static_cast<double>(seed)), Rational(-0.7), Rational(1.1)};
      check_claims(near_ties(rng, n, scale, 25), n, ApproxVec3::of(n), tally, seed);
      if (HasFatalFailure()) return;
    }
    if (scale >= 1e-5 && scale <= 1e5) {
      EXPECT_GT(tally.decided, tally.total / 5) << tally.decided << " of " << tally.total;
    }
  });
}

TEST(DotOrderFilter, ClaimsAreExactWithInexactPointsAndDirection) {
  // Points with thirds and sevenths and a direction of huge integers (above
  // 2^53, so that its approximation has an error too); exact ties (points of
  // one plane) have nonzero values.
  Tally tally;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    std::mt19937_64 rng(seed);
    auto r = [&] { return Rational(static_cast<long>(rng() % 2001) - 1000, seed % 2 ? 3 : 7); };
    const mpz_class big = mpz_class(1) << 70;
    const Vec3 n{Rational(big + static_cast<long>(rng() % 1000)), Rational(-big / 3 + 1),
                 Rational(static_cast<long>(rng() % 100) + 1)};
    const ApproxVec3 n_approx = ApproxVec3::of(n);
    ASSERT_GT(n_approx.x.error, 0.0);
    std::vector<Vec3> exact;
    const Vec3 base{r(), r(), r()};
    for (int i = 0; i < 20; ++i) {
      if (i % 3 == 0) {
        exact.push_back({r(), r(), r()});
      } else {
        // base + s u with u orthogonal to n: ties with base, exactly.
        const Rational s(static_cast<long>(rng() % 21) - 10, 11);
        const Vec3 along = cross(n, Vec3{1, 2, 3});
        exact.push_back(base + (s / Rational(big)) * along);
      }
    }
    check_claims(exact, n, n_approx, tally, seed);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.decided, tally.total / 5) << tally.decided << " of " << tally.total;
}

TEST(DotOrderFilter, ClaimsAreExactWithCoarseApproximations) {
  // Approximations far coarser than a double (multiples of 2^-12, error
  // 2^-13): the points' error, not rounding, dominates the bound here, and
  // the exact ties (points of one plane orthogonal to n) have values that
  // differ by far more than a rounding.
  Tally tally;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    std::mt19937_64 rng(seed);
    const Vec3 n{static_cast<long>(rng() % 7) + 1, -static_cast<long>(rng() % 7),
                 static_cast<long>(rng() % 7) + 1};
    const Vec3 along = cross(n, Vec3{1, 2, 4});
    std::vector<Vec3> exact;
    const Vec3 base{Rational(static_cast<long>(rng() % 2001) - 1000, 300), 1, 2};
    for (int i = 0; i < 24; ++i) {
      const Rational s(static_cast<long>(rng() % 2001) - 1000, 997);
      Vec3 p = base + s * along;
      if (i % 3 == 0)
        p.z += Rational(static_cast<long>(rng() % 201) - 100, 64);  // off the plane by up to 1.6
      exact.push_back(p);
    }
    std::vector<ApproxVec3> approx;
    for (const Vec3& p : exact) {
      ApproxVec3 a;
      Approx* c[3] = {&a.x, &a.y, &a.z};
      for (int k = 0; k < 3; ++k)
        *c[k] = {std::round(to_double_nearest(p[k]) * 4096.0) / 4096.0, 1.0 / 8192 + 1e-12};
      approx.push_back(a);
    }
    check_claims(exact, approx, n, ApproxVec3::of(n), tally, seed);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.decided, tally.total / 10) << tally.decided << " of " << tally.total;
}

TEST(DotOrderFilter, ClaimsAreExactWithACoarseDirection) {
  // An exact direction known only roughly (errors of 2^-7 per coordinate):
  // the direction's error, not rounding or the points', dominates the bound,
  // and points tied exactly along N have values that differ along n.
  const Vec3 n{1, 2, 3};
  const ApproxVec3 coarse{{1.0 + 0x1p-8, 0x1p-7}, {2.0 - 0x1p-8, 0x1p-7}, {3.0, 0x1p-7}};
  Tally tally;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    std::mt19937_64 rng(seed);
    const Vec3 along = cross(n, Vec3{1, 0, 0});  // orthogonal to n
    const Vec3 base{static_cast<long>(rng() % 2001) - 1000, 3, -7};
    std::vector<Vec3> exact;
    for (int i = 0; i < 24; ++i) {
      Vec3 p = base + Rational(static_cast<long>(rng() % 2001) - 1000, 16) * along;
      if (i % 3 == 0) p.x += static_cast<long>(rng() % 201) - 100;  // off the tie
      exact.push_back(p);
    }
    check_claims(exact, n, coarse, tally, seed);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.decided, tally.total / 10) << tally.decided << " of " << tally.total;
}

TEST(DotOrderFilter, SignClaimsAreExactNearThePlaneThroughTheOrigin) {
  // Points within a few ulps of dot(n, x) = 0, exact zeros among them
  // (multiples of a vector orthogonal to n), at every scale, with exact
  // and with coarse approximations (multiples of 2^-12, error 2^-13, under
  // which exact zeros have nonzero values).
  at_each_scale({1.0, 1e-5, 1e5, 0x1p290, 1e-150, 0x1p-1060}, [](double scale) {
    Tally tally;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      std::mt19937_64 rng(seed);
      const Vec3 n{static_cast<long>(rng() % 2001) - 1000, static_cast<long>(rng() % 2001) - 1000,
                   static_cast<long>(rng() % 1000) + 1};
      std::vector<Vec3> exact = near_ties(rng, n, scale, 20, 0.0);
      const Vec3 along = cross(n, Vec3{1, 2, 3});
      for (int i = 0; i < 5; ++i)
        exact.push_back((Rational(scale) * Rational(static_cast<long>(rng() % 33) - 16, 16)) * along);
      std::vector<ApproxVec3> approx;
      for (const Vec3& p : exact) approx.push_back(ApproxVec3::of(p));
      check_sign_claims(exact, approx, n, ApproxVec3::of(n), tally, seed);
      if (HasFatalFailure()) return;
      if (scale != 1.0) continue;
      for (ApproxVec3& a : approx) {
        Approx* c[3] = {&a.x, &a.y, &a.z};
        for (Approx* k : c) *k = {std::round(k->value * 4096.0) / 4096.0, 1.0 / 8192 + 1e-12};
      }
      check_sign_claims(exact, approx, n, ApproxVec3::of(n), tally, seed);
      if (HasFatalFailure()) return;
    }
    // Below 2^-1000 the bound's underflow term leaves every sign to the exact predicate.
    if (scale > 0x1p-900) {
      EXPECT_GT(tally.decided, 0) << "of " << tally.total;
    }
  });
}

TEST(DotOrderFilter, BeyondItsRangeItClaimsNothing) {
  std::mt19937_64 rng(3);
  const Vec3 n{1, 2, 3};
  std::vector<Vec3> exact = near_ties(rng, n, 1e300, 10);
  std::vector<ApproxVec3> approx;
  for (const Vec3& p : exact) approx.push_back(ApproxVec3::of(p));
  const DotOrderFilter filter(ApproxVec3::of(n), extent_of(approx));
  for (const ApproxVec3& a : approx)
    for (const ApproxVec3& b : approx)
      EXPECT_FALSE(filter.compare(filter.value(a), filter.value(b)).has_value());
  // A non-finite extent (a NaN would be folded into it) decides nothing either.
  PlaneFilterExtent nan_extent;
  nan_extent.add_value(std::nan(""));
  const DotOrderFilter blind(ApproxVec3::of(n), nan_extent);
  EXPECT_FALSE(blind.compare(1.0, -1.0).has_value());
  EXPECT_FALSE(blind.sign(1.0).has_value());
  for (const ApproxVec3& a : approx) EXPECT_FALSE(filter.sign(filter.value(a)).has_value());
  // Nor does a direction whose approximation is not finite, or beyond the
  // bound's range.
  PlaneFilterExtent unit;
  unit.add_value(1.0);
  const double inf = std::numeric_limits<double>::infinity();
  for (const ApproxVec3& direction :
       {ApproxVec3{{inf, 0}, {0, 0}, {0, 0}}, ApproxVec3{{1, std::nan("")}, {0, 0}, {0, 0}},
        ApproxVec3{{0x1p700, 0}, {0, 0}, {0, 0}}}) {
    const DotOrderFilter filter(direction, unit);
    EXPECT_FALSE(filter.compare(1.0, -1.0).has_value());
    EXPECT_FALSE(filter.compare(-1e300, 1e300).has_value());
    EXPECT_FALSE(filter.sign(1e300).has_value());
  }
}

}  // namespace
}  // namespace cvms
