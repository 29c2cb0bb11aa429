// SPDX-License-Identifier: MIT
// Tests of the contributing-vertex search (paper Eq. 3) against a brute-force
// maximum of <v, n> in plain rational arithmetic.
#include "contributing_vertices.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/shapes.hpp"
#include "filtered_predicates.hpp"
#include "polyhedron_builder.hpp"
#include "support/random_clouds.hpp"

namespace cvms::detail {
namespace {

std::vector<VertexId> brute_force_maximisers(const ConvexPolyhedron& q, const Vec3& n) {
  Rational best;
  std::vector<VertexId> out;
  for (VertexId v : q.mesh().vertices()) {
    const Rational d = dot(q.vertex(v), n);
    if (out.empty() || d > best) {
      best = d;
      out.assign(1, v);
    } else if (d == best) {
      out.push_back(v);
    }
  }
  return out;
}

TEST(ContributingVertices, MaximisersMatchBruteForceForFacetNormalsAndRandomDirections) {
  const std::vector<ConvexPolyhedron> polys = {shapes::cube(),           shapes::octahedron(),
                                               shapes::truncated_cube(), shapes::geodesic_sphere(2),
                                               shapes::prism(7, 2),      shapes::random_hull(3, 40, 5)};
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> small(-2, 2);
  std::vector<VertexId> got;
  std::size_t ties = 0;
  for (const auto& p : polys) {
    for (const auto& q : polys) {
      for (FaceId f : p.mesh().faces()) {
        maximising_vertices(q, detail::normal_ref(p, f), got);
        ASSERT_EQ(got, brute_force_maximisers(q, p.normal(f)));
        ties += got.size() > 1;
      }
    }
    for (int i = 0; i < 200; ++i) {
      const Vec3 n{small(rng), small(rng), small(rng)};
      if (is_zero(n)) continue;
      const ApproxVec3 na = ApproxVec3::of(n);
      maximising_vertices(p, Vec3Ref{n, na}, got);
      ASSERT_EQ(got, brute_force_maximisers(p, n));
    }
  }
  EXPECT_GT(ties, 0u);
}

TEST(ContributingVertices, ThreeOrMoreMaximisersAreAParallelFacet) {
  const auto c = shapes::cube();
  const auto t = shapes::truncated_cube();
  std::vector<VertexId> cv;
  std::vector<VertexId> facet;
  for (FaceId f : c.mesh().faces()) {
    maximising_vertices(t, detail::normal_ref(c, f), cv);
    ASSERT_GE(cv.size(), 3u);
    const FaceId g = facet_with_normal(t, cv[0], detail::normal_ref(c, f));
    ASSERT_TRUE(g.is_valid());
    EXPECT_EQ(t.normal(g), c.normal(f));
    sorted_facet_vertices(t, g, facet);
    EXPECT_EQ(facet, cv);
  }
  const Vec3 diagonal{1, 1, 1};
  EXPECT_FALSE(facet_with_normal(c, VertexId(0), {diagonal, ApproxVec3::of(diagonal)}).is_valid());

  // The approximations only let it skip facets that cannot match: with a
  // useless approximation (infinite error) the facet is still found, and a
  // vector equal to a facet's normal in double alone is not taken for it.
  const VertexId v = c.mesh().from(*c.mesh().face_halfedges(FaceId(0)).begin());
  const Vec3& n = c.normal(FaceId(0));
  const double inf = std::numeric_limits<double>::infinity();
  const ApproxVec3 useless{{0.0, inf}, {0.0, inf}, {0.0, inf}};
  EXPECT_EQ(facet_with_normal(c, v, {n, useless}), FaceId(0));
  Vec3 nearly = n;
  for (int i = 0; i < 3; ++i)
    if (sgn(nearly[i]) != 0) nearly[i] += Rational(1, 1) / (mpz_class(1) << 80);
  const ApproxVec3 nearly_approx = ApproxVec3::of(nearly);
  const ApproxVec3& n_approx = detail::normal_approx(c, FaceId(0));
  ASSERT_FALSE(provably_different(nearly_approx.x, n_approx.x));  // so the exact comparison decides
  ASSERT_FALSE(provably_different(nearly_approx.y, n_approx.y));
  ASSERT_FALSE(provably_different(nearly_approx.z, n_approx.z));
  EXPECT_FALSE(facet_with_normal(c, v, {nearly, nearly_approx}).is_valid());
}

TEST(ContributingVertices, DisjointSorted) {
  const std::vector<VertexId> a = {VertexId(1), VertexId(4), VertexId(9)};
  const std::vector<VertexId> b = {VertexId(2), VertexId(5)};
  const std::vector<VertexId> c = {VertexId(0), VertexId(9)};
  EXPECT_TRUE(disjoint_sorted(a, b));
  EXPECT_FALSE(disjoint_sorted(a, c));
  EXPECT_TRUE(disjoint_sorted(b, c));
  EXPECT_TRUE(disjoint_sorted({}, a));
}

TEST(ContributingVertices, StoredPerFacet) {
  ContributingVertices cv(3);
  const std::vector<VertexId> x = {VertexId(3)};
  const std::vector<VertexId> y = {VertexId(1), VertexId(2)};
  cv.append(x);
  cv.append(y);
  cv.append(x);
  ASSERT_EQ(cv.num_facets(), 3u);
  EXPECT_EQ(cv.of(FaceId(1)).size(), 2u);
  EXPECT_EQ(cv.of(FaceId(2))[0], VertexId(3));
}

// The walk (BFS over facets + hill-climbing) against the brute-force maxima,
// on tie-heavy pairs: every facet of p with the maximisers of its normal.
void expect_walk_matches_brute_force(const ConvexPolyhedron& p, const ConvexPolyhedron& q,
                                     WalkSplit split = {}) {
  ContributingVertices cv(p.num_facets());
  contributing_vertices_walk(p, q, {}, cv, split);
  ASSERT_EQ(cv.num_facets(), p.num_facets());
  for (FaceId f : p.mesh().faces()) {
    const std::vector<VertexId> expected = brute_force_maximisers(q, p.normal(f));
    const std::span<const VertexId> got = cv.of(f);
    ASSERT_EQ(std::vector<VertexId>(got.begin(), got.end()), expected) << "facet " << f.index();
  }
}

Mat3 quarter_turn_x() {  // (x, y, z) -> (x, -z, y)
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m.m[i][j] = 0;
  m.m[0][0] = 1;
  m.m[1][2] = -1;
  m.m[2][1] = 1;
  return m;
}

TEST(ContributingVerticesWalk, TieHeavyPairsMatchBruteForce) {
  const auto cube = shapes::cube();
  const auto s2 = shapes::geodesic_sphere(2);
  const auto p6 = shapes::prism(6, 1);
  const auto p8 = shapes::prism(8, 3);
  const auto side = shapes::prism(5, 2).transformed(quarter_turn_x(), {});
  const auto tc = shapes::truncated_cube();
  const std::vector<std::pair<const ConvexPolyhedron*, const ConvexPolyhedron*>> pairs = {
      {&cube, &cube}, {&s2, &s2},   {&p6, &p6},   {&p6, &p8},   {&p8, &side},
      {&side, &p6},   {&cube, &tc}, {&tc, &cube}, {&cube, &s2}, {&s2, &cube}};
  for (const auto& [p, q] : pairs) expect_walk_matches_brute_force(*p, *q);
  const auto r3 = shapes::rotated_geodesic_sphere(3);
  const auto s3 = shapes::geodesic_sphere(3);
  expect_walk_matches_brute_force(s3, r3);
  expect_walk_matches_brute_force(r3, s3);
}

// The climbs' semi-static filter (dot_order_filter.hpp) on an operand of
// large, inexact coordinates (a sheared sphere scaled by 2^40 with
// non-dyadic offsets, so every approximation has an error) against a small
// copy of itself: every facet's climb ends on a whole parallel facet, ties
// the filter must leave to the exact test, whose values differ by the
// approximations' errors. A filter bounded by the wrong operand's extent,
// or one ignoring the points' errors, claims an order among tied vertices.
TEST(ContributingVerticesWalk, LargeInexactOperandsKeepTheirTies) {
  Mat3 big = Mat3::identity();
  for (int i = 0; i < 3; ++i) big.m[i][i] = Rational(mpz_class(1) << 40);
  big.m[0][1] = Rational(mpz_class(1) << 40, 3);
  big.m[2][0] = Rational(-(mpz_class(1) << 38), 7);
  const auto q =
      shapes::geodesic_sphere(3).transformed(big, {Rational(1, 3), Rational(1, 7), Rational(-1, 11)});
  Mat3 small = Mat3::identity();
  for (int i = 0; i < 3; ++i) small.m[i][i] = Rational(1, 1 << 20);
  const auto p = q.transformed(small, {Rational(5, 3), 0, 0});
  double largest_error = 0;
  for (VertexId v : q.mesh().vertices()) largest_error = std::max(largest_error, vertex_approx(q, v).x.error);
  ASSERT_GT(largest_error, 0.0);
  expect_walk_matches_brute_force(p, q);
  expect_walk_matches_brute_force(q, p);
  expect_walk_matches_brute_force(q, q);
}

TEST(ContributingVerticesWalk, RandomPairsMatchBruteForce) {
  for (std::uint64_t seed = 1; seed <= 150; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const test::RandomPair p = test::random_pair(seed);
    expect_walk_matches_brute_force(p.a, p.b);
    expect_walk_matches_brute_force(p.b, p.a);
  }
}

// The walk cut into pieces (each climbing from its own seeds) on several
// threads: the same lists as the brute force, and for a given cut the same
// predicates evaluated on any number of threads (4 and 8 oversubscribe).
TEST(ContributingVerticesWalk, PiecesOnThreadsMatchBruteForceAndCountAlike) {
  const auto s3 = shapes::geodesic_sphere(3);
  const auto r3 = shapes::rotated_geodesic_sphere(3);
  const auto p8 = shapes::prism(8, 3);
  const auto side = shapes::prism(5, 2).transformed(quarter_turn_x(), {});
  const test::RandomPair random = test::random_pair(7);
  const std::vector<std::pair<const ConvexPolyhedron*, const ConvexPolyhedron*>> pairs = {
      {&s3, &r3}, {&r3, &s3}, {&s3, &s3}, {&p8, &side}, {&random.a, &random.b}};
  for (const auto& [p, q] : pairs) {
    for (unsigned pieces : {2u, 3u, 5u, 8u, 1000u}) {
      std::uint64_t one_thread = 0;
      for (unsigned threads : {1u, 2u, 4u, 8u}) {
        SCOPED_TRACE("pieces " + std::to_string(pieces) + ", threads " + std::to_string(threads));
        const PredicateCounters before = predicate_counters();
        expect_walk_matches_brute_force(*p, *q, {pieces, threads});
        const PredicateCounters& after = predicate_counters();
        const std::uint64_t evaluated = after.filtered + after.exact - before.filtered - before.exact;
        if (threads == 1) one_thread = evaluated;
        EXPECT_EQ(evaluated, one_thread);
      }
    }
  }
}

TEST(ContributingVerticesWalk, PiecesFollowTheSizeAlone) {
  EXPECT_EQ(walk_pieces(0, 8192), 1u);
  EXPECT_EQ(walk_pieces(16383, 8192), 1u);
  EXPECT_EQ(walk_pieces(16384, 8192), 2u);
  EXPECT_EQ(walk_pieces(20480, 8192), 2u);
  EXPECT_EQ(walk_pieces(1u << 30, 8192), max_walk_pieces);
  EXPECT_EQ(walk_pieces(1u << 30, 0), 1u);
}

TEST(ContributingVerticesWalk, PartnersAreTakenWithoutClimbing) {
  // Each facet of the cube partnered with the same facet of the cube: the
  // list is that facet's vertices.
  const auto cube = shapes::cube();
  std::vector<FaceId> partner;
  for (FaceId f : cube.mesh().faces()) partner.push_back(f);
  ContributingVertices cv(cube.num_facets());
  contributing_vertices_walk(cube, cube, partner, cv);
  std::vector<VertexId> expected;
  for (FaceId f : cube.mesh().faces()) {
    sorted_facet_vertices(cube, f, expected);
    const std::span<const VertexId> got = cv.of(f);
    EXPECT_EQ(std::vector<VertexId>(got.begin(), got.end()), expected);
  }
}

}  // namespace
}  // namespace cvms::detail
