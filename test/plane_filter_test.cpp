// SPDX-License-Identifier: MIT
// Tests of the quickhull's semi-static plane filter (lib/numeric/plane_filter.hpp):
// every sign it claims must be the exact orient3d of the exact points, on
// nearly coplanar points, at extreme scales, and with inexact approximations.
#include "plane_filter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "approx.hpp"
#include "cvms/predicates.hpp"
#include "cvms/rational.hpp"

namespace cvms {
namespace {

Vec3 exact_of(const Coords& c) { return {Rational(c[0]), Rational(c[1]), Rational(c[2])}; }

struct Tally {
  int decided = 0, total = 0;
};

// Checks every claim of the filter for triangle a, b, c against the exact
// orient3d of the exact points (whose approximations are given).
void check_claims(const std::vector<Vec3>& exact, const std::vector<Coords>& approx,
                  const PlaneFilterScale& scale, Tally& tally) {
  const PlaneFilter plane = PlaneFilter::of(approx[0], approx[1], approx[2], scale);
  for (std::size_t i = 3; i < exact.size(); ++i) {
    const double s = plane.value(approx[i]);
    const Sign truth = orient3d(exact[0], exact[1], exact[2], exact[i]);
    ++tally.total;
    if (plane.above(s)) {
      ++tally.decided;
      ASSERT_EQ(truth, Sign::positive) << "point " << i << " value " << s << " bound " << plane.bound;
    } else if (plane.below(s)) {
      ++tally.decided;
      ASSERT_EQ(truth, Sign::negative) << "point " << i << " value " << s << " bound " << plane.bound;
    }
  }
}

// A triangle of doubles at the given scale and offset, and points on its
// plane (rounded to double, so within a few ulps of it) nudged by 0..3 ulps
// per coordinate: the hardest decisions for a filter.
std::vector<Coords> near_coplanar(std::mt19937_64& rng, double scale, double offset, int n) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Coords> pts;
  for (int i = 0; i < 3; ++i)
    pts.push_back({offset + scale * u(rng), offset + scale * u(rng), offset + scale * u(rng)});
  for (int i = 0; i < n; ++i) {
    const double s = u(rng), t = u(rng);
    Coords p;
    for (int k = 0; k < 3; ++k) {
      p[k] = pts[0][k] + s * (pts[1][k] - pts[0][k]) + t * (pts[2][k] - pts[0][k]);
      for (int nudge = static_cast<int>(rng() % 4); nudge > 0; --nudge)
        p[k] = std::nextafter(p[k], rng() % 2 ? INFINITY : -INFINITY);
    }
    pts.push_back(p);
    // Some points well off the plane too, which the filter must decide.
    if (i % 4 == 0)
      pts.push_back({offset + scale * u(rng), offset + scale * u(rng), offset + scale * u(rng)});
  }
  return pts;
}

PlaneFilterScale scale_of(const std::vector<Coords>& pts, double error) {
  double m = 0;
  for (const Coords& c : pts)
    for (double x : c) m = std::max(m, std::fabs(x));
  return PlaneFilterScale::of(m, error);
}

TEST(PlaneFilter, ClaimsAreExactOnDoubles) {
  std::mt19937_64 rng(7);
  // Scales from subnormal products to the filter's limit of 2^300.
  const double scales[] = {1.0, 1e-5, 1e5, 0x1p290, 1e-150, 1e-300, 0x1p-1060};
  for (double scale : scales) {
    SCOPED_TRACE("scale " + std::to_string(scale));
    Tally tally;
    for (int round = 0; round < 40; ++round) {
      const double offset = round % 2 ? 0.0 : scale * 100.0;
      auto pts = near_coplanar(rng, scale, offset, 30);
      std::vector<Vec3> exact;
      for (const Coords& c : pts) exact.push_back(exact_of(c));
      check_claims(exact, pts, scale_of(pts, 0.0), tally);
      if (HasFatalFailure()) return;
    }
    // The points well off the plane are decided except where the values
    // underflow (they are below 2^-1000 there and the filter gives up).
    if (scale >= 1e-5) {
      EXPECT_GT(tally.decided, tally.total / 5) << tally.decided << " of " << tally.total;
    }
  }
}

TEST(PlaneFilter, BeyondTheLimitDecidesNothing) {
  std::mt19937_64 rng(8);
  auto pts = near_coplanar(rng, 1e300, 0.0, 30);
  const PlaneFilterScale scale = scale_of(pts, 0.0);
  EXPECT_TRUE(std::isinf(scale.slack));
  const PlaneFilter plane = PlaneFilter::of(pts[0], pts[1], pts[2], scale);
  for (std::size_t i = 3; i < pts.size(); ++i) {
    const double s = plane.value(pts[i]);
    EXPECT_FALSE(plane.above(s) || plane.below(s));
  }
}

TEST(PlaneFilter, ClaimsAreExactWithInexactApproximations) {
  // Points with thirds and sevenths: their doubles are only approximations,
  // and points exactly on the plane (orient3d == 0) have nonzero values.
  std::mt19937_64 rng(9);
  Tally tally;
  for (int round = 0; round < 60; ++round) {
    auto r = [&] { return Rational(static_cast<long>(rng() % 2001) - 1000, round % 2 ? 3 : 7); };
    std::vector<Vec3> exact;
    for (int i = 0; i < 3; ++i) exact.push_back({r(), r(), r()});
    for (int i = 0; i < 30; ++i) {
      if (i % 3 == 0) {
        exact.push_back({r(), r(), r()});
      } else {
        const Rational s(static_cast<long>(rng() % 21) - 10, 11), t(static_cast<long>(rng() % 21) - 10, 13);
        exact.push_back(exact[0] + s * (exact[1] - exact[0]) + t * (exact[2] - exact[0]));
      }
    }
    std::vector<Coords> approx;
    double error = 0;
    for (const Vec3& p : exact) {
      const ApproxVec3 a = ApproxVec3::of(p);
      approx.push_back({a.x.value, a.y.value, a.z.value});
      error = std::max({error, a.x.error, a.y.error, a.z.error});
    }
    ASSERT_GT(error, 0.0);
    check_claims(exact, approx, scale_of(approx, error), tally);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.decided, tally.total / 5) << tally.decided << " of " << tally.total;
}

TEST(PlaneFilter, ClaimsAreExactWithCoarseApproximations) {
  // Approximations far coarser than a double (multiples of 2^-12, error
  // 2^-13): the input error, not rounding, dominates the bound here.
  std::mt19937_64 rng(10);
  Tally tally;
  for (int round = 0; round < 60; ++round) {
    auto r = [&] { return Rational(static_cast<long>(rng() % 2001) - 1000, 300); };
    std::vector<Vec3> exact;
    for (int i = 0; i < 3; ++i) exact.push_back({r(), r(), r()});
    for (int i = 0; i < 40; ++i) {
      const Rational s(static_cast<long>(rng() % 21) - 10, 11), t(static_cast<long>(rng() % 21) - 10, 13);
      Vec3 p = exact[0] + s * (exact[1] - exact[0]) + t * (exact[2] - exact[0]);
      p.z += Rational(static_cast<long>(rng() % 201) - 100, 8);  // up to 12.5 off the plane
      exact.push_back(p);
    }
    std::vector<Coords> approx;
    for (const Vec3& p : exact) {
      Coords c;
      for (int k = 0; k < 3; ++k) c[k] = std::round(to_double_nearest(p[k]) * 4096.0) / 4096.0;
      approx.push_back(c);
    }
    check_claims(exact, approx, scale_of(approx, 1.0 / 8192 + 1e-12), tally);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.decided, tally.total / 10) << tally.decided << " of " << tally.total;
}

}  // namespace
}  // namespace cvms
