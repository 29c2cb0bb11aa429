// SPDX-License-Identifier: MIT
// Tests of the box hierarchy's internals: the outward rounding of exact
// bounds (checked by exact comparison with the neighbouring doubles), the
// lower bound of box distances (against the exact distance of the rounded
// boxes), and the pruning itself: on 1,000 unit cubes in a row, a query
// near one end runs few exact piece tests (the thread's counter), while its
// answer stays the brute-force one.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "cvms/convex_union.hpp"
#include "cvms/proximity.hpp"
#include "cvms/shapes.hpp"
#include "outward_box.hpp"
#include "pair_tests.hpp"

namespace cvms {
namespace {

using unions::exact_piece_tests;
using unions::OutwardBox;

constexpr double inf = std::numeric_limits<double>::infinity();

Vec3 v(long x, long y, long z) { return {Rational(x), Rational(y), Rational(z)}; }

Rational power_of_ten(long e) {
  Rational q;
  mpz_ui_pow_ui(q.get_num_mpz_t(), 10, static_cast<unsigned long>(e < 0 ? -e : e));
  return e < 0 ? 1 / q : q;
}

// round_down(q) is a double <= q whose upper neighbour is > q.
void expect_tight(const Rational& q) {
  const double lo = unions::round_down(q), hi = unions::round_up(q);
  if (std::isfinite(lo)) {
    EXPECT_LE(Rational(lo), q);
    const double up = std::nextafter(lo, inf);
    if (std::isfinite(up)) {
      EXPECT_GT(Rational(up), q);
    }
  } else {
    EXPECT_LT(q, -DBL_MAX);
  }
  if (std::isfinite(hi)) {
    EXPECT_GE(Rational(hi), q);
    const double down = std::nextafter(hi, -inf);
    if (std::isfinite(down)) {
      EXPECT_LT(Rational(down), q);
    }
  } else {
    EXPECT_GT(q, DBL_MAX);
  }
}

TEST(OutwardBox, RoundingIsOutwardAndTight) {
  std::vector<Rational> values{0,
                               1,
                               -1,
                               Rational(1, 3),
                               Rational(-1, 3),
                               Rational(1, 10),
                               Rational(2, 3),
                               power_of_ten(400),
                               -power_of_ten(400),
                               power_of_ten(-400),
                               -power_of_ten(-400),
                               power_of_ten(-320),
                               Rational(DBL_MAX),
                               -Rational(DBL_MAX),
                               Rational(DBL_MIN)};
  std::mt19937_64 rng(11);
  for (int k = 0; k < 500; ++k) {
    values.push_back(
        Rational(static_cast<long>(rng() >> 1) - (1L << 62), static_cast<long>(rng() % 1000003 + 1)));
  }
  for (Rational& q : values) {
    q.canonicalize();
    SCOPED_TRACE(q.get_str());
    expect_tight(q);
  }
  EXPECT_EQ(unions::round_down(power_of_ten(400)), DBL_MAX);
  EXPECT_EQ(unions::round_up(power_of_ten(400)), inf);
  EXPECT_EQ(unions::round_down(-power_of_ten(400)), -inf);
}

// The exact squared distance of two boxes given in doubles.
Rational exact_box_distance(const OutwardBox& a, const OutwardBox& b) {
  Rational sum = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    Rational gap = 0;
    if (Rational(b.lo[i]) > Rational(a.hi[i])) gap = Rational(b.lo[i]) - Rational(a.hi[i]);
    if (Rational(a.lo[i]) > Rational(b.hi[i])) gap = Rational(a.lo[i]) - Rational(b.hi[i]);
    sum += gap * gap;
  }
  return sum;
}

TEST(OutwardBox, DistanceBoundIsBelowTheExactOne) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> coordinate(-1e6, 1e6);
  std::uniform_int_distribution<int> exponent(-300, 300);
  for (int k = 0; k < 2000; ++k) {
    OutwardBox a, b;
    const double scale = std::ldexp(1.0, exponent(rng) / 4);
    for (std::size_t i = 0; i < 3; ++i) {
      for (OutwardBox* box : {&a, &b}) {
        const double x = coordinate(rng) * scale, y = coordinate(rng) * scale;
        box->lo[i] = std::min(x, y);
        box->hi[i] = std::max(x, y);
      }
    }
    const double bound = unions::lower_squared_distance(a, b);
    EXPECT_GE(bound, 0.0);
    EXPECT_LE(Rational(bound), exact_box_distance(a, b)) << "draw " << k;
    if (unions::overlaps(a, b)) {
      EXPECT_EQ(bound, 0.0);
    }
  }
  OutwardBox whole{{-inf, -inf, -inf}, {inf, inf, inf}};
  EXPECT_EQ(unions::lower_squared_distance(whole, whole), 0.0);
  OutwardBox far{{DBL_MAX, 0, 0}, {inf, 1, 1}};
  OutwardBox near_origin{{-DBL_MAX, 0, 0}, {0, 1, 1}};
  // A gap of DBL_MAX: its square overflows, and the bound stays the largest
  // finite doubles (the exact value is far above them).
  EXPECT_GE(unions::lower_squared_distance(far, near_origin), DBL_MAX / 2);
}

// 1,000 unit cubes [2k, 2k + 1] x [0, 1] x [0, 1].
ConvexUnion row_of_cubes(long count, long y = 0) {
  std::vector<ConvexPolyhedron> cubes;
  for (long k = 0; k < count; ++k) cubes.push_back(shapes::box(v(2 * k, y, 0), v(2 * k + 1, y + 1, 1)));
  return ConvexUnion(std::move(cubes));
}

// The exact piece tests the query runs on this thread.
template <class Query>
std::uint64_t tests_of(Query&& query) {
  const std::uint64_t before = exact_piece_tests();
  query();
  return exact_piece_tests() - before;
}

TEST(BoxHierarchy, AQueryNearOneEndVisitsFewPieces) {
  const ConvexUnion row = row_of_cubes(1000);
  (void)row.contains(v(0, 0, 0));  // builds the hierarchy
  const Vec3 inside{Rational(1, 2), Rational(1, 2), Rational(1, 2)};
  const Vec3 in_gap{Rational(3, 2), Rational(1, 2), Rational(1, 2)};
  EXPECT_LE(tests_of([&] { EXPECT_TRUE(row.contains(inside)); }), 1U);
  EXPECT_EQ(tests_of([&] { EXPECT_FALSE(row.contains(in_gap)); }), 0U);

  const ConvexPolyhedron probe = shapes::box(v(-3, 0, 0), v(-2, 1, 1));
  std::uint64_t tests = tests_of([&] {
    const UnionDistance d = row.squared_distance(probe);
    EXPECT_EQ(d.distance.squared_distance, 4);
    EXPECT_EQ(d.piece, 0U);
  });
  EXPECT_LE(tests, 3U);
  tests = tests_of([&] { EXPECT_FALSE(row.intersects(probe)); });
  EXPECT_EQ(tests, 0U);

  // Union against union: a short row just above the far end of the long one.
  const ConvexUnion other = row_of_cubes(3, 3);
  tests = tests_of([&] {
    const UnionDistance d = row.squared_distance(other);
    EXPECT_EQ(d.distance.squared_distance, 4);
    EXPECT_EQ(d.piece, 0U);
    EXPECT_EQ(d.other_piece, 0U);
  });
  EXPECT_LE(tests, 20U);
  EXPECT_EQ(tests_of([&] { EXPECT_FALSE(row.intersects(other)); }), 0U);
}

TEST(BoxHierarchy, BruteForceWouldVisitEveryPair) {
  // What the counter saves: the brute force runs 3,000 tests on the same
  // query, and gets the same answer.
  const ConvexUnion row = row_of_cubes(1000);
  const ConvexUnion other = row_of_cubes(3, 3);
  Rational best;
  for (std::size_t i = 0; i < row.size(); ++i) {
    for (std::size_t j = 0; j < other.size(); ++j) {
      const Rational d = squared_distance(row.pieces()[i], other.pieces()[j]).squared_distance;
      if ((i == 0 && j == 0) || d < best) best = d;
    }
  }
  EXPECT_EQ(best, row.squared_distance(other).distance.squared_distance);
}

}  // namespace
}  // namespace cvms
