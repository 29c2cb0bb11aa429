// SPDX-License-Identifier: MIT
// The bound functions of lib/numeric/error_bounds.hpp, checked exactly
// against rationals: truncation_error (Approx::of's, and the stitching's
// output vertices), sum_error (the filtered sum a_i + b_j of CHMS), and the
// dot-product scan's bound with the difference margin (the quickhull's
// initial simplex), at every scale the filters claim and with inexact
// approximations.
#include "error_bounds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "support/random_numbers.hpp"

namespace cvms {
namespace {

using filtered::difference_margin;
using filtered::dot_filter_bound;
using filtered::sum_error;
using filtered::truncation_error;

TEST(ErrorBounds, TruncationErrorCoversTheTruncation) {
  test::Rng rng(21);
  for (int i = 0; i < 20000; ++i) {
    // Random rationals of every kind, and non-dyadic ones in the subnormal range.
    const Rational q =
        i % 4 == 0 ? Rational(test::random_magnitude(rng, -1074, -1000)) / 3 : test::random_rational(rng);
    const double d = q.get_d();  // truncation toward zero
    if (!std::isfinite(d)) continue;
    ASSERT_LE(abs(q - Rational(d)), Rational(truncation_error(d))) << to_string(q);
  }
}

TEST(ErrorBounds, SumErrorCoversSumsOfApproximations) {
  test::Rng rng(22);
  for (int i = 0; i < 20000; ++i) {
    Rational x, y;
    if (i % 3 == 0) {  // sums that cancel or underflow
      x = Rational(test::random_magnitude(rng, -1074, -1015)) / 3;
      y = -x + Rational(test::random_magnitude(rng, -1074, -1020));
    } else {
      x = test::random_rational(rng);
      y = test::random_rational(rng);
    }
    Approx a = Approx::of(x), b = Approx::of(y);
    if (i % 2 == 0) b.error = b.error * 4 + 0x1p-1070;  // a coarser (still valid) approximation
    const double c = a.value + b.value;
    const double e = sum_error(a.error, b.error, c);
    if (!std::isfinite(c) || !std::isfinite(e)) {
      EXPECT_FALSE(std::isfinite(e)) << "finite bound for a non-finite sum";
      continue;
    }
    ASSERT_LE(abs(Rational(c) - (x + y)), Rational(e)) << to_string(x) << " + " << to_string(y);
  }
}

// A point set at the given scale: exact points, their approximations (exact
// doubles, or decimals whose doubles are off), and the largest magnitude and
// error of the approximations, as the quickhull computes them.
struct PointSet {
  std::vector<Vec3> exact;
  std::vector<ApproxVec3> approx;
  double max_abs = 0, max_error = 0;
};

PointSet random_points(test::Rng& rng, double scale, bool inexact) {
  PointSet set;
  for (int i = 0; i < 60; ++i) {
    Vec3 p;
    for (int k = 0; k < 3; ++k) {
      p[k] = Rational(scale * test::random_uniform(rng, -1.0, 1.0));
      if (inexact) p[k] = p[k] * Rational(1000001, 1000000);
    }
    // Near ties: copies nudged by one unit of the last place.
    if (i % 5 == 4) {
      p = set.exact.back();
      p.x += Rational(std::nextafter(to_double_nearest(p.x), INFINITY)) - Rational(to_double_nearest(p.x));
    }
    set.exact.push_back(p);
    const ApproxVec3& a = set.approx.emplace_back(ApproxVec3::of(p));
    for (const Approx& c : {a.x, a.y, a.z}) {
      set.max_abs = std::max(set.max_abs, std::fabs(c.value));
      set.max_error = std::max(set.max_error, c.error);
    }
  }
  return set;
}

TEST(ErrorBounds, QuotientBoundsHoldTheQuotient) {
  test::Rng rng(23);
  for (int i = 0; i < 20000; ++i) {
    Rational c = test::random_rational(rng);
    Rational n = test::random_rational(rng);
    if (sgn(c) < 0) c = -c;
    if (sgn(n) < 0) n = -n;
    if (i % 5 == 0) c += Rational(std::fabs(test::random_magnitude(rng, -1074, -900)));  // near underflow
    if (sgn(n) == 0) n = 1;
    Approx a = Approx::of(c), b = Approx::of(n);
    if (i % 2 == 0) a.error = a.error * 4 + 0x1p-1070;  // coarser, still valid
    const filtered::QuotientBounds q = filtered::quotient_bounds(a, b);
    const Rational exact = c / n;
    EXPECT_LE(Rational(q.low), exact) << to_string(c) << " / " << to_string(n);
    if (std::isfinite(q.high)) {
      EXPECT_GE(Rational(q.high), exact) << to_string(c) << " / " << to_string(n);
    }
  }
}

TEST(ErrorBounds, DotFilterBoundCoversEveryPointAndTheMarginDecides) {
  test::Rng rng(23);
  const double scales[] = {1.0, 1e-5, 1e5, 0x1p290, 1e-150, 1e-300};
  int decided = 0, total = 0;
  for (double scale : scales) {
    SCOPED_TRACE("scale " + std::to_string(scale));
    for (int round = 0; round < 20; ++round) {
      const PointSet set = random_points(rng, scale, round % 2 == 1);
      // Directions with exact and with inexact approximations (thirds).
      const Vec3 n{Rational(static_cast<long>(rng() % 201) - 100, round % 3 == 0 ? 1 : 3),
                   Rational(static_cast<long>(rng() % 201) - 100, 7),
                   Rational(static_cast<long>(rng() % 3) - 1)};
      const ApproxVec3 na = ApproxVec3::of(n);
      const double bound = dot_filter_bound(na, set.max_abs, set.max_error);
      ASSERT_TRUE(bound < std::numeric_limits<double>::infinity());
      std::vector<double> v;
      for (const ApproxVec3& p : set.approx)
        v.push_back(p.x.value * na.x.value + p.y.value * na.y.value + p.z.value * na.z.value);
      for (std::size_t i = 0; i < v.size(); ++i) {
        ASSERT_LE(abs(Rational(v[i]) - dot(set.exact[i], n)), Rational(bound)) << "point " << i;
        for (std::size_t j = 0; j < v.size(); ++j) {
          ++total;
          if (v[i] - v[j] > difference_margin * bound) {
            ++decided;
            ASSERT_GT(dot(set.exact[i], n), dot(set.exact[j], n)) << "points " << i << ", " << j;
          }
        }
      }
    }
  }
  EXPECT_GT(decided, total / 4) << decided << " of " << total;
}

TEST(ErrorBounds, DotFilterBoundIsInfiniteBeyondItsRange) {
  const ApproxVec3 n = ApproxVec3::of(Vec3{1, 2, 3});
  EXPECT_TRUE(std::isinf(dot_filter_bound(n, 0x1p301, 0.0)));
  EXPECT_TRUE(std::isinf(dot_filter_bound(n, 1.0, 0x1p301)));
  EXPECT_TRUE(std::isinf(dot_filter_bound(n, std::numeric_limits<double>::quiet_NaN(), 0.0)));
  const ApproxVec3 huge = ApproxVec3::of(Vec3{Rational(0x1p601), 0, 0});
  EXPECT_TRUE(std::isinf(dot_filter_bound(huge, 1.0, 0.0)));
  EXPECT_TRUE(std::isfinite(dot_filter_bound(n, 0x1p300, 0x1p300)));
}

}  // namespace
}  // namespace cvms
