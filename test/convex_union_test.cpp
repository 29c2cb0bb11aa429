// SPDX-License-Identifier: MIT
// Tests of the queries on unions of convex pieces against brute force over
// every piece (pair), which does not use the box hierarchy
// (support/union_oracle.hpp), and against hand-checked values: contains on
// random exact points and on boundary points, intersects with every kind of
// operand, squared distance with its witnesses and pieces; concurrent
// queries on copies (the hierarchy is built once, by whichever comes first).
#include "cvms/convex_union.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <thread>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/proximity.hpp"
#include "cvms/shapes.hpp"
#include "support/oracle.hpp"
#include "support/union_oracle.hpp"

namespace cvms {
namespace {

using test::random_exact_point;
using test::random_union;

Vec3 v(long x, long y, long z) { return {Rational(x), Rational(y), Rational(z)}; }

ConvexUnion one(ConvexPolyhedron p) { return ConvexUnion(std::vector<ConvexPolyhedron>{std::move(p)}); }

ConvexUnion unit_cube_at(long x) { return one(shapes::box(v(x, 0, 0), v(x + 1, 1, 1))); }

// A witness is a point of its set, and the witnesses are the distance apart.
void expect_witnesses(const UnionDistance& d, const ConvexUnion& u, const ConvexUnion& other) {
  const Vec3 gap = d.distance.witness_a - d.distance.witness_b;
  EXPECT_EQ(dot(gap, gap), d.distance.squared_distance);
  EXPECT_TRUE(test::union_contains_brute_force(one(u.pieces()[d.piece]), d.distance.witness_a));
  EXPECT_TRUE(test::union_contains_brute_force(one(other.pieces()[d.other_piece]), d.distance.witness_b));
}

TEST(ConvexUnionQueries, TwoUnitCubesThreeApartAreNineApartSquared) {
  const ConvexUnion a = unit_cube_at(0), b = unit_cube_at(4);
  const UnionDistance d = a.squared_distance(b);
  EXPECT_EQ(d.distance.squared_distance, 9);
  EXPECT_FALSE(d.distance.intersect);
  EXPECT_EQ(d.distance.witness_a.x, 1);
  EXPECT_EQ(d.distance.witness_b.x, 4);
  EXPECT_EQ(a.squared_distance(b.pieces()[0]).distance.squared_distance, 9);
  EXPECT_EQ(a.squared_distance(ConvexSet::point(v(2, 3, 1))).distance.squared_distance, 1 + 4);
  EXPECT_FALSE(a.intersects(b));
  EXPECT_TRUE(a.intersects(unit_cube_at(1)));  // touching counts
}

TEST(ConvexUnionQueries, LShapeHandChecked) {
  // [0,3]x[0,1]x[0,1] and [0,1]x[0,1]x[1,3]: (2, 0, 2) is in the notch.
  const ConvexUnion l(std::vector<ConvexPolyhedron>{shapes::box(v(0, 0, 0), v(3, 1, 1)),
                                                    shapes::box(v(0, 0, 1), v(1, 1, 3))});
  EXPECT_TRUE(l.contains(v(0, 0, 0)));
  EXPECT_TRUE(l.contains(v(1, 1, 3)));
  EXPECT_TRUE(l.contains(Vec3{Rational(1), Rational(1, 2), Rational(2)}));
  EXPECT_FALSE(l.contains(v(2, 0, 2)));
  const ConvexSet notch = ConvexSet::point(v(2, 0, 2));
  const UnionDistance d = l.squared_distance(notch);
  EXPECT_EQ(d.distance.squared_distance, 1);  // to x = 1 and to z = 1 alike
  EXPECT_EQ(d.piece, 0U);                     // the first of the tied pieces
  EXPECT_FALSE(l.intersects(notch));
  EXPECT_TRUE(l.intersects(ConvexSet::segment(v(2, 0, 2), v(0, 0, 2))));
}

TEST(ConvexUnionQueries, ContainsAgreesWithBruteForce) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const ConvexUnion u = random_union(seed, 8, 10, 8);
    std::mt19937_64 rng(seed);
    std::vector<Vec3> points = test::boundary_points(u);
    for (int k = 0; k < 300; ++k) points.push_back(random_exact_point(rng, 14));
    int inside = 0;
    for (const Vec3& p : points) {
      const bool expected = test::union_contains_brute_force(u, p);
      ASSERT_EQ(u.contains(p), expected) << test::to_text(p);
      inside += expected ? 1 : 0;
    }
    EXPECT_GT(inside, 0);
    EXPECT_LT(inside, static_cast<int>(points.size()));
  }
}

TEST(ConvexUnionQueries, IntersectsAndDistanceAgreeWithBruteForce) {
  int meeting = 0, apart = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const ConvexUnion u = random_union(seed, 6, 15, 5);
    const ConvexUnion other = random_union(500 + seed, 1 + static_cast<int>(seed % 4), 15, 5);
    const bool expected = test::intersects_brute_force(u, other);
    (expected ? meeting : apart) += 1;
    EXPECT_EQ(u.intersects(other), expected);
    EXPECT_EQ(other.intersects(u), expected);
    const test::BruteNearest brute = test::nearest_brute_force(u, other);
    const UnionDistance d = u.squared_distance(other);
    EXPECT_EQ(d.distance.squared_distance, brute.squared_distance);
    EXPECT_EQ(d.piece, brute.piece);
    EXPECT_EQ(d.other_piece, brute.other_piece);
    EXPECT_EQ(d.distance.intersect, expected);
    expect_witnesses(d, u, other);

    // The other union's first piece as a polyhedron, a convex set and a
    // placed polyhedron (moved by a translation given in doubles).
    const ConvexPolyhedron& first = other.pieces()[0];
    const ConvexUnion first_only = one(first);
    const bool meets_first = test::intersects_brute_force(u, first_only);
    EXPECT_EQ(u.intersects(first), meets_first);
    EXPECT_EQ(u.intersects(ConvexSet(first)), meets_first);
    EXPECT_EQ(u.intersects(PlacedPolyhedron(first)), meets_first);
    const test::BruteNearest to_first = test::nearest_brute_force(u, first_only);
    const UnionDistance d1 = u.squared_distance(first);
    EXPECT_EQ(d1.distance.squared_distance, to_first.squared_distance);
    EXPECT_EQ(d1.piece, to_first.piece);
    EXPECT_EQ(u.squared_distance(ConvexSet(first)).piece, to_first.piece);

    Placement shift;
    shift.translation = {0.5, -1.25, 3.0};
    const PlacedPolyhedron placed(first, shift);
    const ConvexUnion moved = one(first.translated(Vec3{Rational(1, 2), Rational(-5, 4), Rational(3)}));
    EXPECT_EQ(u.intersects(placed), test::intersects_brute_force(u, moved));
  }
  EXPECT_GT(meeting, 0);
  EXPECT_GT(apart, 0);
}

TEST(ConvexUnionQueries, LowerDimensionalOperandsAgreeWithBruteForce) {
  const ConvexUnion u = random_union(77, 10, 12, 6);
  std::mt19937_64 rng(77);
  for (int k = 0; k < 40; ++k) {
    SCOPED_TRACE("draw " + std::to_string(k));
    const Vec3 p = random_exact_point(rng, 14), q = random_exact_point(rng, 14),
               r = random_exact_point(rng, 14);
    std::vector<ConvexSet> sets{ConvexSet::point(p)};
    if (p != q) sets.push_back(ConvexSet::segment(p, q));
    const std::vector<Vec3> triangle{p, q, r};
    try {
      sets.push_back(convex_hull_set(triangle));
    } catch (const Error&) {
      // collinear: a segment or a point is already in the list
    }
    for (const ConvexSet& s : sets) {
      bool expected = false;
      Rational best;
      std::size_t best_piece = 0;
      for (std::size_t i = 0; i < u.size(); ++i) {
        const DistanceResult d = squared_distance(ConvexSet(u.pieces()[i]), s);
        expected = expected || d.intersect;
        if (i == 0 || d.squared_distance < best) {
          best = d.squared_distance;
          best_piece = i;
        }
      }
      EXPECT_EQ(u.intersects(s), expected) << s.dimension();
      const UnionDistance d = u.squared_distance(s);
      EXPECT_EQ(d.distance.squared_distance, best) << s.dimension();
      EXPECT_EQ(d.piece, best_piece) << s.dimension();
    }
  }
}

TEST(ConvexUnionQueries, EmptySetsAndUnions) {
  const ConvexUnion empty;
  EXPECT_FALSE(empty.contains(v(0, 0, 0)));
  EXPECT_FALSE(empty.intersects(shapes::cube()));
  EXPECT_FALSE(empty.intersects(unit_cube_at(0)));
  EXPECT_FALSE(unit_cube_at(0).intersects(ConvexUnion(std::vector<ConvexPolyhedron>{})));
  EXPECT_THROW((void)empty.squared_distance(shapes::cube()), Error);
  EXPECT_THROW((void)unit_cube_at(0).squared_distance(empty), Error);
  EXPECT_THROW((void)unit_cube_at(0).intersects(ConvexSet()), Error);
  EXPECT_THROW((void)unit_cube_at(0).intersects(ConvexPolyhedron()), Error);
  EXPECT_THROW((void)unit_cube_at(0).squared_distance(ConvexSet()), Error);
}

TEST(ConvexUnionQueries, HugeAndTinyCoordinatesKeepExactAnswers) {
  // Coordinates beyond the doubles' range and below their resolution: the
  // boxes round outward (to infinity or to the neighbouring doubles), and
  // the answers are still the exact ones.
  Rational huge;
  mpz_ui_pow_ui(huge.get_num_mpz_t(), 10, 400);
  const Rational tiny = 1 / huge;
  const Vec3 far{huge, 0, 0};
  const ConvexUnion u(std::vector<ConvexPolyhedron>{shapes::box(v(0, 0, 0), Vec3{tiny, tiny, tiny}),
                                                    shapes::box(far, far + v(1, 1, 1))});
  EXPECT_TRUE(u.contains(Vec3{tiny, 0, tiny}));
  EXPECT_FALSE(u.contains(Vec3{2 * tiny, 0, 0}));
  EXPECT_TRUE(u.contains(far + v(1, 1, 1)));
  EXPECT_FALSE(u.contains(far + v(2, 0, 0)));
  const UnionDistance d = u.squared_distance(ConvexSet::point(Vec3{-tiny, 0, 0}));
  EXPECT_EQ(d.distance.squared_distance, tiny * tiny);
  EXPECT_EQ(d.piece, 0U);
  EXPECT_EQ(u.squared_distance(ConvexSet::point(far + v(3, 0, 0))).piece, 1U);
}

TEST(ConvexUnionQueries, CopiesQueriedFromSeveralThreadsAgree) {
  const ConvexUnion u = random_union(5, 40, 30, 6);
  std::mt19937_64 rng(5);
  std::vector<Vec3> points;
  for (int k = 0; k < 200; ++k) points.push_back(random_exact_point(rng, 34));
  std::vector<bool> expected;
  for (const Vec3& p : points) expected.push_back(test::union_contains_brute_force(u, p));
  std::vector<std::vector<bool>> answers(4);
  {
    std::vector<std::jthread> threads;
    for (std::size_t t = 0; t < answers.size(); ++t) {
      threads.emplace_back([&, t, copy = u] {
        for (const Vec3& p : points) answers[t].push_back(copy.contains(p));
      });
    }
  }
  for (const auto& a : answers) EXPECT_EQ(a, expected);
}

}  // namespace
}  // namespace cvms
