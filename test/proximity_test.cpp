// SPDX-License-Identifier: MIT
// Proximity queries (cvms/proximity.hpp) against independent oracles: a scan
// for support, and for distance and penetration the exact hull of the
// pairwise differences with a brute-force projection of the origin onto
// each of its facets, edges and vertices (support/proximity_oracle.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/proximity.hpp"
#include "cvms/shapes.hpp"
#include "support/hand_solids.hpp"
#include "support/oracle.hpp"
#include "support/proximity_oracle.hpp"
#include "support/random_clouds.hpp"

namespace cvms {
// Exact coordinates in failure messages.
void PrintTo(const Vec3& v, std::ostream* out) { *out << test::to_text(v); }

namespace {

using test::v3;

Vec3 q3(const Rational& x, const Rational& y, const Rational& z) { return {x, y, z}; }

ConvexPolyhedron unit_cube() { return ConvexPolyhedron::from_soup(test::cube_quads()); }

// The cube [0,1]^3 moved by t.
ConvexPolyhedron cube_at(const Vec3& t) { return unit_cube().translated(t); }

void expect_distance(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const DistanceResult& d) {
  EXPECT_EQ(test::check_distance(a, b, d, test::proximity_oracle(a, b)), "");
}

void expect_penetration(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const PenetrationResult& p) {
  EXPECT_EQ(test::check_penetration(a, b, p, test::proximity_oracle(a, b)), "");
}

// --- support ---------------------------------------------------------------

// The maximum of <x, u> over the vertices, by a scan (the oracle of the walk).
Rational scan_max(const ConvexPolyhedron& p, const Vec3& u) {
  Rational best = dot(p.vertex(VertexId(0)), u);
  for (VertexId v : p.mesh().vertices()) best = std::max(best, dot(p.vertex(v), u));
  return best;
}

TEST(ProximitySupport, CubeVertexEdgeAndFacet) {
  ASSERT_EQ(unit_cube().vertex(VertexId(0)), v3(0, 0, 0));
  const ConvexPolyhedron c = unit_cube();
  SupportResult r = support(c, v3(1, 2, 3), VertexId(0), true);
  EXPECT_EQ(r.point, v3(1, 1, 1));
  EXPECT_EQ(r.value, 6);
  EXPECT_EQ(r.face.dimension, 0);
  EXPECT_EQ(r.face.vertices.size(), 1u);

  r = support(c, v3(1, 1, 0), VertexId(0), true);
  EXPECT_EQ(r.value, 2);
  EXPECT_EQ(r.face.dimension, 1);
  ASSERT_EQ(r.face.vertices.size(), 2u);
  for (VertexId v : r.face.vertices) EXPECT_EQ(dot(c.vertex(v), v3(1, 1, 0)), 2);

  r = support(c, v3(0, 0, -5), VertexId(7), true);
  EXPECT_EQ(r.value, 0);
  EXPECT_EQ(r.face.dimension, 2);
  EXPECT_EQ(r.face.vertices.size(), 4u);
  ASSERT_TRUE(r.face.facet.is_valid());
  EXPECT_EQ(c.normal(r.face.facet), v3(0, 0, -1));

  r = support(c, v3(1, 0, 0));  // no face asked: empty
  EXPECT_EQ(r.value, 1);
  EXPECT_TRUE(r.face.vertices.empty());
}

TEST(ProximitySupport, WalkEqualsScanOnRandomHullsAndDirections) {
  std::mt19937_64 rng(17);
  for (int trial = 0; trial < 60; ++trial) {
    SCOPED_TRACE("seed 17, trial " + std::to_string(trial));
    const ConvexPolyhedron p = shapes::random_hull(100 + static_cast<std::uint64_t>(trial), 50, 100);
    for (int k = 0; k < 20; ++k) {
      const Vec3 u = v3(static_cast<long>(rng() % 7) - 3, static_cast<long>(rng() % 7) - 3,
                        static_cast<long>(rng() % 7) - 3);
      if (is_zero(u)) continue;
      const VertexId start(static_cast<std::uint32_t>(rng() % p.num_vertices()));
      const SupportResult r = support(p, u, start, true);
      const Rational m = scan_max(p, u);
      EXPECT_EQ(r.value, m);
      EXPECT_EQ(dot(r.point, u), m);
      std::vector<VertexId> all;
      for (VertexId v : p.mesh().vertices())
        if (dot(p.vertex(v), u) == m) all.push_back(v);
      EXPECT_EQ(r.face.vertices, all);
    }
  }
}

TEST(ProximitySupport, PlacedEqualsMaterialized) {
  const ConvexPolyhedron s = shapes::geodesic_sphere(2);
  const double c = std::cos(0.3), sn = std::sin(0.3);
  Placement pl;
  pl.rotation = {{{c, -sn, 0.0}, {sn, c, 0.0}, {0.0, 0.0, 1.0}}};
  pl.translation = {0.5, -2.25, 1e-9};
  const PlacedPolyhedron placed(s, pl);
  const ConvexPolyhedron moved = placed.materialized();
  for (const Vec3& u : {v3(1, 0, 0), v3(1, 2, 3), v3(-3, 1, -1), v3(0, 0, 1)}) {
    const SupportResult r = support(placed, u);
    EXPECT_EQ(r.value, scan_max(moved, u));
    EXPECT_EQ(r.point, moved.vertex(r.vertex));
  }
}

TEST(ProximitySupport, BadArguments) {
  const ConvexPolyhedron c = unit_cube();
  EXPECT_THROW((void)support(c, v3(0, 0, 0)), Error);
  EXPECT_THROW((void)support(c, v3(1, 0, 0), VertexId(8)), Error);
  EXPECT_THROW((void)support(c, v3(1, 0, 0), VertexId()), Error);
  const ConvexPolyhedron empty;
  EXPECT_THROW((void)support(empty, v3(1, 0, 0)), Error);
  EXPECT_THROW((void)squared_distance(empty, c), Error);
  EXPECT_THROW((void)intersects(c, empty), Error);
  EXPECT_THROW((void)penetration(empty, empty), Error);
  Placement nan;
  nan.translation[1] = std::nan("");
  EXPECT_THROW(PlacedPolyhedron(c, nan), Error);
  // A singular placement that maps u to zero would make every vertex tie and
  // report a facet that does not exist: refused.
  Placement flat;
  flat.rotation = {{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 0.0}}};
  EXPECT_THROW((void)support(PlacedPolyhedron(c, flat), v3(0, 0, 1), VertexId(0), true), Error);
  EXPECT_EQ(support(PlacedPolyhedron(c, flat), v3(1, 0, 0)).value, Rational(1));
  try {
    (void)support(c, v3(0, 0, 0));
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
    EXPECT_NE(std::string(e.what()).find("zero direction"), std::string::npos);
  }
}

// --- hand-checked distance and penetration ----------------------------------

TEST(ProximityDistance, CubesAtDistanceOneThird) {
  const ConvexPolyhedron a = unit_cube();
  const ConvexPolyhedron b = cube_at(q3(Rational(4, 3), 0, 0));
  const DistanceResult d = squared_distance(a, b);
  EXPECT_EQ(d.squared_distance, Rational(1, 9));
  EXPECT_FALSE(d.intersect);
  EXPECT_EQ(d.witness_a.x, 1);
  EXPECT_EQ(d.witness_b.x, Rational(4, 3));
  EXPECT_FALSE(intersects(a, b));
  expect_distance(a, b, d);
  const PenetrationResult p = penetration(a, b);
  EXPECT_FALSE(p.intersect);
  EXPECT_EQ(p.squared_depth, 0);
  expect_penetration(a, b, p);
}

TEST(ProximityPenetration, CubesOverlappingByOneTenth) {
  const ConvexPolyhedron a = unit_cube();
  const ConvexPolyhedron b = cube_at(q3(Rational(9, 10), 0, 0));
  const PenetrationResult p = penetration(a, b);
  EXPECT_TRUE(p.intersect);
  EXPECT_EQ(p.squared_depth, Rational(1, 100));
  EXPECT_EQ(p.direction, v3(1, 0, 0));  // move B by +1/10 along x
  EXPECT_EQ(p.translation(), q3(Rational(1, 10), 0, 0));
  expect_penetration(a, b, p);
  const DistanceResult d = squared_distance(a, b);
  EXPECT_TRUE(d.intersect);
  EXPECT_EQ(d.squared_distance, 0);
  EXPECT_EQ(d.witness_a, d.witness_b);
  EXPECT_TRUE(intersects(a, b));
  // The mirror case: B on the other side, direction -x.
  const ConvexPolyhedron c = cube_at(q3(Rational(-9, 10), 0, 0));
  EXPECT_EQ(penetration(a, c).direction, v3(-1, 0, 0));
  EXPECT_EQ(penetration(a, c).squared_depth, Rational(1, 100));
}

TEST(Proximity, TouchingFaceEdgeAndVertexOnFace) {
  const ConvexPolyhedron a = unit_cube();
  const ConvexPolyhedron octa = ConvexPolyhedron::from_soup(test::octahedron());
  const ConvexPolyhedron cases[] = {
      cube_at(v3(1, 0, 0)),                                       // face to face
      cube_at(v3(1, 1, 0)),                                       // edge to edge
      cube_at(v3(1, 1, 1)),                                       // vertex to vertex
      octa.translated(q3(Rational(1, 2), Rational(1, 2), 2)),     // a vertex on the top face
      octa.translated(q3(Rational(1, 2), 1, 2)),                  // a vertex on the top edge
  };
  for (const ConvexPolyhedron& b : cases) {
    const DistanceResult d = squared_distance(a, b);
    const bool touching = d.squared_distance == 0;
    expect_distance(a, b, d);
    const PenetrationResult p = penetration(a, b);
    expect_penetration(a, b, p);
    if (touching) {
      EXPECT_TRUE(d.intersect);
      EXPECT_TRUE(intersects(a, b));
      EXPECT_TRUE(p.intersect);
      EXPECT_EQ(p.squared_depth, 0);
    }
  }
  EXPECT_TRUE(intersects(a, cases[0]));
  EXPECT_TRUE(intersects(a, cases[1]));
  EXPECT_TRUE(intersects(a, cases[2]));
  EXPECT_TRUE(intersects(a, cases[3]));
}

// fcl #545: box-box and box-mesh where the true normal is a face normal (EPA
// returned a normal towards a vertex and a depth sqrt(3) too large).
TEST(ProximityRegression, Fcl545BoxBoxAndBoxMeshFaceNormal) {
  const ConvexPolyhedron a = shapes::box(v3(-1, -1, -1), v3(1, 1, 1));
  const ConvexPolyhedron b = shapes::box(q3(Rational(-1, 2), Rational(-1, 2), Rational(9, 10)),
                                         q3(Rational(1, 2), Rational(1, 2), Rational(19, 10)));
  PenetrationResult p = penetration(a, b);
  EXPECT_EQ(p.direction, v3(0, 0, 1));
  EXPECT_EQ(p.squared_depth, Rational(1, 100));
  expect_penetration(a, b, p);
  // The same box as a triangle mesh (merged into facets on construction).
  const ConvexPolyhedron mesh = ConvexPolyhedron::from_soup(test::cube_triangles())
                                    .translated(q3(Rational(-1, 2), Rational(-1, 2), Rational(9, 10)));
  p = penetration(a, mesh);
  EXPECT_EQ(p.direction, v3(0, 0, 1));
  EXPECT_EQ(p.squared_depth, Rational(1, 100));
  expect_penetration(a, mesh, p);
}

// fcl #493 / #495: boxes kissing within 1e-9 (GJK and EPA disagreed or threw).
TEST(ProximityRegression, Fcl493And495BoxesWithinOneBillionth) {
  const ConvexPolyhedron a = unit_cube();
  const Rational e = parse_rational("1e-9");
  const ConvexPolyhedron apart = cube_at(q3(1 + e, 0, 0));
  DistanceResult d = squared_distance(a, apart);
  EXPECT_EQ(d.squared_distance, e * e);
  EXPECT_FALSE(d.intersect);
  expect_distance(a, apart, d);
  const ConvexPolyhedron over = cube_at(q3(1 - e, 0, 0));
  const PenetrationResult p = penetration(a, over);
  EXPECT_TRUE(p.intersect);
  EXPECT_EQ(p.squared_depth, e * e);
  EXPECT_EQ(p.direction, v3(1, 0, 0));
  expect_penetration(a, over, p);
  // The gap of the double nearest 1e-9, exactly.
  const Rational ed = rational_from_double(1e-9);
  d = squared_distance(a, cube_at(q3(1 + ed, 0, 0)));
  EXPECT_EQ(d.squared_distance, ed * ed);
  // Kissing exactly.
  EXPECT_EQ(squared_distance(a, cube_at(v3(1, 0, 0))).squared_distance, 0);
}

TEST(ProximityDegenerate, IdenticalOperandsTieBreak) {
  const ConvexPolyhedron a = unit_cube();
  const PenetrationResult p = penetration(a, a);
  EXPECT_TRUE(p.intersect);
  EXPECT_EQ(p.squared_depth, 1);
  EXPECT_EQ(p.direction, v3(-1, 0, 0));  // six facets tie: the smallest normal
  expect_penetration(a, a, p);
  expect_distance(a, a, squared_distance(a, a));
}

TEST(ProximityDegenerate, OneInsideTheOther) {
  const ConvexPolyhedron big = shapes::box(v3(-10, -10, -10), v3(10, 10, 10));
  const ConvexPolyhedron small = shapes::geodesic_sphere(2).translated(v3(3, 0, 0));
  const PenetrationResult p = penetration(big, small);
  EXPECT_TRUE(p.intersect);
  expect_penetration(big, small, p);
  expect_distance(big, small, squared_distance(big, small));
  expect_penetration(small, big, penetration(small, big));
}

TEST(ProximityDegenerate, FarApartAndTinyGaps) {
  const ConvexPolyhedron a = shapes::geodesic_sphere(2);
  const ConvexPolyhedron far = shapes::rotated_geodesic_sphere(2).translated(v3(1000000000, 3, -7));
  expect_distance(a, far, squared_distance(a, far));
  const Rational tiny = parse_rational("1e-12");
  const ConvexPolyhedron c = unit_cube();
  const ConvexPolyhedron gap = cube_at(q3(0, 1 + tiny, 0));
  const DistanceResult d = squared_distance(c, gap);
  EXPECT_EQ(d.squared_distance, tiny * tiny);
  const ConvexPolyhedron corner = cube_at(q3(1 + tiny, 1 + tiny, 1 + tiny));
  EXPECT_EQ(squared_distance(c, corner).squared_distance, 3 * tiny * tiny);
  const PenetrationResult p = penetration(c, cube_at(q3(0, 0, 1 - tiny)));
  EXPECT_EQ(p.squared_depth, tiny * tiny);
  EXPECT_EQ(p.direction, v3(0, 0, 1));
}

// --- transforms --------------------------------------------------------------

TEST(ProximityPlacement, DoubleRotationsAgreeWithTheMovedOperands) {
  const ConvexPolyhedron a = shapes::geodesic_sphere(1);
  const ConvexPolyhedron b = shapes::cube();
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> angle(-3.14, 3.14);
  std::uniform_real_distribution<double> shift(-2.5, 2.5);
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE("seed 4242, trial " + std::to_string(trial));
    const double t1 = angle(rng), t2 = angle(rng);
    // Rz(t1) Rx(t2), in doubles: not exactly orthogonal, applied exactly.
    const double c1 = std::cos(t1), s1 = std::sin(t1), c2 = std::cos(t2), s2 = std::sin(t2);
    Placement pb;
    pb.rotation = {{{c1, -s1 * c2, s1 * s2}, {s1, c1 * c2, -c1 * s2}, {0.0, s2, c2}}};
    pb.translation = {shift(rng), shift(rng), shift(rng)};
    Placement pa;
    pa.translation = {shift(rng) / 4, 0.0, 0.0};
    const PlacedPolyhedron placed_a(a, pa);
    const PlacedPolyhedron placed_b(b, pb);
    const ConvexPolyhedron ma = placed_a.materialized();
    const ConvexPolyhedron mb = placed_b.materialized();
    const test::OriginAndPolytope oracle = test::proximity_oracle(ma, mb);
    const DistanceResult d = squared_distance(placed_a, placed_b);
    EXPECT_EQ(test::check_distance(ma, mb, d, oracle), "");
    EXPECT_EQ(intersects(placed_a, placed_b), oracle.inside);
    EXPECT_EQ(test::check_penetration(ma, mb, penetration(placed_a, placed_b), oracle), "");
  }
}

// --- the rounded distance ------------------------------------------------------

TEST(ProximityNearestDoubleSqrt, CorrectlyRounded) {
  EXPECT_EQ(nearest_double_sqrt(Rational(0)), 0.0);
  EXPECT_EQ(nearest_double_sqrt(Rational(9, 4)), 1.5);
  EXPECT_EQ(nearest_double_sqrt(Rational(1, 9)), 1.0 / 3.0);
  EXPECT_EQ(nearest_double_sqrt(Rational(2)), std::sqrt(2.0));  // IEEE sqrt is correctly rounded
  EXPECT_EQ(nearest_double_sqrt(parse_rational("1e-18")), 1e-9);
  EXPECT_EQ(nearest_double_sqrt(parse_rational("1e600")), 1e300);  // beyond the double range squared
  EXPECT_EQ(nearest_double_sqrt(parse_rational("1e-600")), 1e-300);
  // Subnormal roots must be rounded once, not twice (at 53 bits, then by the
  // scaling back). u is the smallest subnormal; tiny nudges decide.
  const Rational u = Rational(std::ldexp(1.0, -1074));
  const Rational nudge(mpz_class(1), mpz_class(1) << 1200);  // 2^-1200: no double
  const auto square = [](const Rational& x) { return x * x; };
  EXPECT_EQ(nearest_double_sqrt(square(Rational(5, 2) * u + nudge)), std::ldexp(3.0, -1074));
  EXPECT_EQ(nearest_double_sqrt(square(Rational(3, 2) * u - nudge)), std::ldexp(1.0, -1074));
  EXPECT_EQ(nearest_double_sqrt(square(Rational(5, 2) * u)), std::ldexp(2.0, -1074));  // tie: even
  EXPECT_EQ(nearest_double_sqrt(square(Rational(7, 2) * u)), std::ldexp(4.0, -1074));
  EXPECT_EQ(nearest_double_sqrt(square(Rational(1, 4) * u)), 0.0);
  EXPECT_EQ(nearest_double_sqrt(square(Rational(std::ldexp(1.0, -1022)))), std::ldexp(1.0, -1022));
  EXPECT_EQ(nearest_double_sqrt(square(Rational(std::ldexp(1.0, -1022)) - nudge)), std::ldexp(1.0, -1022));
  std::mt19937_64 rng(99);
  for (int i = 0; i < 2000; ++i) {
    // For a double q, IEEE sqrt is the correctly rounded root: an independent oracle.
    const double q = std::ldexp(static_cast<double>(rng() >> 11), static_cast<int>(rng() % 200) - 150);
    EXPECT_EQ(nearest_double_sqrt(Rational(q)), std::sqrt(q)) << "q = " << q;
  }
  EXPECT_THROW((void)nearest_double_sqrt(Rational(-1)), Error);
}

// --- seeded random pairs ------------------------------------------------------

TEST(ProximityRandomPairs, TwoThousandSeededPairsAgreeWithTheOracle) {
  int kinds[3] = {0, 0, 0};
  constexpr int count = 2000;
  for (std::uint64_t seed = 1; seed <= count; ++seed) {
    const test::RandomPlacementCheck c = test::check_random_placement(seed);
    ASSERT_EQ(c.failure, "") << "seed " << seed << ": " << c.description;
    ++kinds[static_cast<int>(c.kind)];
  }
  EXPECT_GT(kinds[0], count / 5);
  EXPECT_GT(kinds[1], count / 5);
  EXPECT_GT(kinds[2], count / 5);
}

}  // namespace
}  // namespace cvms
