// SPDX-License-Identifier: MIT
// Proximity queries on convex sets of every dimension (cvms/proximity.hpp's
// ConvexSet overloads): hand-checked flat and segment cases, the support walk
// on a polygon's cycle against a scan, and seeded random pairs of flattened
// and collapsed sets against the brute-force oracle
// (support/set_proximity_oracle.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/proximity.hpp"
#include "support/hand_solids.hpp"
#include "support/oracle.hpp"
#include "support/random_sets.hpp"
#include "support/set_proximity_oracle.hpp"

namespace cvms {
namespace {

using test::v3;

Vec3 q3(const Rational& x, const Rational& y, const Rational& z) { return {x, y, z}; }

ConvexSet unit_cube() { return ConvexSet(ConvexPolyhedron::from_soup(test::cube_quads())); }

ConvexSet square_polygon(std::vector<Vec3> cycle) { return ConvexSet::polygon(cycle); }

void expect_oracle(const ConvexSet& a, const ConvexSet& b) {
  EXPECT_EQ(test::check_set_queries(a, b), "");
  EXPECT_EQ(test::check_set_queries(b, a), "");
}

// --- support -----------------------------------------------------------------

TEST(SetProximitySupport, PolygonWalkEqualsScan) {
  std::mt19937_64 rng(17);
  for (int i = 0; i < 200; ++i) {
    const ConvexSet s = test::random_set(rng, i % 3, v3(1, -1, 0), 3, 12);
    const std::vector<Vec3> v = s.vertices();
    const Vec3 u{Rational(static_cast<long>(rng() % 7) - 3), Rational(static_cast<long>(rng() % 7) - 3),
                 Rational(static_cast<long>(rng() % 3) - 1)};
    if (is_zero(u)) continue;
    const VertexId start(static_cast<std::uint32_t>(rng() % v.size()));
    const SupportResult r = support(s, u, start, true);
    Rational best = dot(v[0], u);
    for (const Vec3& x : v) best = std::max(best, dot(x, u));
    std::vector<VertexId> maximisers;
    for (std::uint32_t k = 0; k < v.size(); ++k)
      if (dot(v[k], u) == best) maximisers.push_back(VertexId(k));
    ASSERT_EQ(r.value, best) << "case " << i;
    EXPECT_EQ(r.point, v[r.vertex.index()]);
    EXPECT_EQ(r.face.vertices, maximisers) << "case " << i;
    EXPECT_EQ(r.face.dimension, std::min<int>(2, static_cast<int>(maximisers.size()) - 1));
  }
}

TEST(SetProximitySupport, SquareVertexEdgeAndWholeFace) {
  const ConvexSet sq = square_polygon({v3(0, 0, 0), v3(1, 0, 0), v3(1, 1, 0), v3(0, 1, 0)});
  EXPECT_EQ(support(sq, v3(1, 2, 0)).point, v3(1, 1, 0));
  const SupportResult edge = support(sq, v3(1, 0, 5), VertexId(0), true);
  EXPECT_EQ(edge.value, 1);
  EXPECT_EQ(edge.face.dimension, 1);
  const SupportResult face = support(sq, v3(0, 0, -2), VertexId(2), true);
  EXPECT_EQ(face.value, 0);
  EXPECT_EQ(face.face.dimension, 2);
  EXPECT_EQ(face.face.vertices.size(), 4u);
  EXPECT_FALSE(face.face.facet.is_valid());
  EXPECT_EQ(support(ConvexSet::segment(v3(0, 0, 0), v3(2, 1, 0)), v3(-1, 0, 0)).point, v3(0, 0, 0));
  EXPECT_EQ(support(ConvexSet::point(v3(3, 4, 5)), v3(0, 1, 0)).value, 4);
  EXPECT_EQ(support(unit_cube(), v3(1, 1, 1)).point, v3(1, 1, 1));
  const SupportResult top = support(unit_cube(), v3(0, 0, 3), VertexId(0), true);
  EXPECT_EQ(top.face.dimension, 2);
  EXPECT_TRUE(top.face.facet.is_valid());  // a polyhedron's facet, as its own overload names it
}

TEST(SetProximitySupport, BadArguments) {
  const ConvexSet sq = square_polygon({v3(0, 0, 0), v3(1, 0, 0), v3(1, 1, 0)});
  EXPECT_THROW((void)support(ConvexSet(), v3(1, 0, 0)), Error);
  EXPECT_THROW((void)support(sq, v3(0, 0, 0)), Error);
  EXPECT_THROW((void)support(sq, v3(1, 0, 0), VertexId(3)), Error);
}

TEST(SetProximity, EmptyOperandIsNamed) {
  for (int which = 0; which < 2; ++which) {
    const ConvexSet a = which == 0 ? ConvexSet() : unit_cube();
    const ConvexSet b = which == 0 ? unit_cube() : ConvexSet();
    const std::string name = which == 0 ? "operand A" : "operand B";
    try {
      (void)squared_distance(a, b);
      FAIL() << "no error";
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
    EXPECT_THROW((void)intersects(a, b), Error);
    EXPECT_THROW((void)penetration(a, b), Error);
  }
}

// --- hand-checked ----------------------------------------------------------------

TEST(SetProximity, PointAtOneThirdFromACubeFace) {
  const ConvexSet p = ConvexSet::point(q3(Rational(1, 2), Rational(1, 4), Rational(4, 3)));
  const DistanceResult d = squared_distance(unit_cube(), p);
  EXPECT_EQ(d.squared_distance, Rational(1, 9));
  EXPECT_FALSE(d.intersect);
  EXPECT_EQ(d.witness_a, q3(Rational(1, 2), Rational(1, 4), 1));
  EXPECT_EQ(d.witness_b, q3(Rational(1, 2), Rational(1, 4), Rational(4, 3)));
  EXPECT_FALSE(intersects(p, unit_cube()));
  const PenetrationResult pen = penetration(p, unit_cube());
  EXPECT_FALSE(pen.intersect);
  EXPECT_TRUE(is_zero(pen.direction));
  expect_oracle(unit_cube(), p);
}

TEST(SetProximity, SegmentParallelToACubeFace) {
  const ConvexSet s = ConvexSet::segment(q3(-1, Rational(1, 2), Rational(3, 2)), q3(2, Rational(1, 2), Rational(3, 2)));
  const DistanceResult d = squared_distance(unit_cube(), s);
  EXPECT_EQ(d.squared_distance, Rational(1, 4));
  EXPECT_EQ(d.witness_b - d.witness_a, q3(0, 0, Rational(1, 2)));
  expect_oracle(unit_cube(), s);
}

TEST(SetProximity, SquareTouchingACubeAlongAnEdge) {
  // In the plane z = x, meeting the cube only along its edge x = z = 1.
  const ConvexSet sq = square_polygon({v3(1, 0, 1), v3(1, 1, 1), v3(2, 1, 2), v3(2, 0, 2)});
  const DistanceResult d = squared_distance(unit_cube(), sq);
  EXPECT_TRUE(d.intersect);
  EXPECT_EQ(d.squared_distance, 0);
  EXPECT_EQ(d.witness_a.x, 1);
  EXPECT_EQ(d.witness_a.z, 1);
  const PenetrationResult p = penetration(unit_cube(), sq);
  EXPECT_TRUE(p.intersect);
  EXPECT_EQ(p.squared_depth, 0);
  expect_oracle(unit_cube(), sq);
}

TEST(SetProximity, CoplanarPolygonsOverlapping) {
  const ConvexSet sq = square_polygon({v3(0, 0, 0), v3(2, 0, 0), v3(2, 2, 0), v3(0, 2, 0)});
  const ConvexSet tri = square_polygon({v3(1, 1, 0), v3(3, 1, 0), v3(1, 3, 0)});
  EXPECT_TRUE(intersects(sq, tri));
  const PenetrationResult p = penetration(sq, tri);
  EXPECT_TRUE(p.intersect);
  EXPECT_EQ(p.squared_depth, 0);  // A + (-B) is flat: no interior (proximity.hpp)
  EXPECT_EQ(p.direction, v3(0, 0, 1));
  EXPECT_TRUE(is_zero(p.translation()));
  EXPECT_EQ(p.witness_a, p.witness_b);
  expect_oracle(sq, tri);
}

TEST(SetProximity, ParallelPolygonsInDistinctPlanes) {
  const ConvexSet sq = square_polygon({v3(0, 0, 0), v3(2, 0, 0), v3(2, 2, 0), v3(0, 2, 0)});
  const ConvexSet tri = square_polygon(
      {q3(1, 1, Rational(1, 3)), q3(3, 1, Rational(1, 3)), q3(1, 3, Rational(1, 3))});
  const DistanceResult d = squared_distance(sq, tri);
  EXPECT_EQ(d.squared_distance, Rational(1, 9));
  EXPECT_FALSE(intersects(sq, tri));
  const PenetrationResult p = penetration(sq, tri);
  EXPECT_FALSE(p.intersect);
  EXPECT_TRUE(is_zero(p.direction));
  expect_oracle(sq, tri);
  // Side by side in the plane z = 5: apart by 1 along x.
  const ConvexSet left = square_polygon({v3(0, 0, 5), v3(1, 0, 5), v3(1, 1, 5), v3(0, 1, 5)});
  const ConvexSet right = left.translated(v3(2, 0, 0));
  EXPECT_EQ(squared_distance(left, right).squared_distance, 1);
  expect_oracle(left, right);
}

TEST(SetProximity, SegmentThroughACube) {
  const ConvexSet s = ConvexSet::segment(q3(Rational(1, 2), Rational(1, 2), -1), q3(Rational(1, 2), Rational(1, 2), 2));
  EXPECT_TRUE(intersects(unit_cube(), s));
  // A + (-B) = [-1/2, 1/2]^2 x [-2, 2]: the nearest facets are x = -1/2, x = 1/2,
  // y = -1/2, y = 1/2; the smallest normal is (-1, 0, 0).
  const PenetrationResult p = penetration(unit_cube(), s);
  EXPECT_TRUE(p.intersect);
  EXPECT_EQ(p.squared_depth, Rational(1, 4));
  EXPECT_EQ(p.direction, v3(-1, 0, 0));
  EXPECT_EQ(p.translation(), q3(Rational(-1, 2), 0, 0));
  EXPECT_EQ(p.witness_a - p.witness_b, p.translation());
  expect_oracle(unit_cube(), s);
}

TEST(SetProximity, SegmentsAndPoints) {
  // Skew segments: x axis piece and a y-parallel piece at height 2.
  const ConvexSet s1 = ConvexSet::segment(v3(-1, 0, 0), v3(1, 0, 0));
  const ConvexSet s2 = ConvexSet::segment(v3(0, -1, 2), v3(0, 1, 2));
  EXPECT_EQ(squared_distance(s1, s2).squared_distance, 4);
  expect_oracle(s1, s2);
  // Crossing in a plane: M is a parallelogram containing the origin.
  const ConvexSet s3 = ConvexSet::segment(v3(0, -1, 0), v3(0, 1, 0));
  const PenetrationResult p = penetration(s1, s3);
  EXPECT_TRUE(p.intersect);
  EXPECT_EQ(p.direction, v3(0, 0, 1));
  expect_oracle(s1, s3);
  // Collinear overlapping: M is a segment, no direction.
  const ConvexSet s4 = ConvexSet::segment(v3(0, 0, 0), v3(3, 0, 0));
  const PenetrationResult q = penetration(s1, s4);
  EXPECT_TRUE(q.intersect);
  EXPECT_TRUE(is_zero(q.direction));
  expect_oracle(s1, s4);
  // Points: equal and apart.
  expect_oracle(ConvexSet::point(v3(1, 2, 3)), ConvexSet::point(v3(1, 2, 3)));
  EXPECT_EQ(squared_distance(ConvexSet::point(v3(1, 2, 3)), ConvexSet::point(v3(0, 0, 3))).squared_distance, 5);
}

// --- seeded random pairs ---------------------------------------------------------

TEST(SetProximityRandomPairs, SeededFlatAndCollapsedPairsAgreeWithTheOracle) {
  constexpr int count = 1024;  // 64 of each of the 16 pairs of dimensions
  int intersecting = 0, touching = 0;
  for (std::uint64_t seed = 1; seed <= count; ++seed) {
    const test::RandomSetPairCheck c = test::check_random_set_pair(seed);
    ASSERT_EQ(c.failure, "") << "seed " << seed << ": " << c.description;
    intersecting += c.intersect;
    touching += c.touching;
  }
  EXPECT_GT(intersecting, count / 2);
  EXPECT_LT(intersecting, count - count / 5);
  EXPECT_GT(touching, count / 4);
}

}  // namespace
}  // namespace cvms
