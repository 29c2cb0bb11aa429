// SPDX-License-Identifier: MIT
// The exact EPA behind penetration() (lib/proximity/epa.cpp) against its
// reference, the whole-sum scan (detail::penetration_by_sum), field by field,
// and against the brute-force oracle (test/support/proximity_oracle.hpp): the
// 2,000 seeded placements of the proximity tests, then hand-made ties (the
// EPA must find every facet at the least distance, not one of them), placed
// operands, and convex sets whose A + (-B) is solid or flat.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "cvms/proximity.hpp"
#include "cvms/shapes.hpp"
#include "penetration_by_sum.hpp"
#include "support/hand_solids.hpp"
#include "support/oracle.hpp"
#include "support/proximity_oracle.hpp"
#include "support/random_sets.hpp"
#include "support/set_proximity_oracle.hpp"

namespace cvms {
namespace {

using test::v3;

// "" iff both answers are the same but for the witnesses (a contact is
// rarely unique; the oracle checks them).
std::string differences(const PenetrationResult& epa, const PenetrationResult& sum) {
  if (epa.intersect != sum.intersect) return "intersect differs";
  if (epa.squared_depth != sum.squared_depth)
    return "squared_depth " + to_string(epa.squared_depth) + ", the sum gives " +
           to_string(sum.squared_depth);
  if (epa.direction != sum.direction)
    return "direction " + test::to_text(epa.direction) + ", the sum gives " + test::to_text(sum.direction);
  if (epa.offset != sum.offset) return "offset differs";
  return "";
}

void expect_as_sum_and_oracle(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  const PenetrationResult p = penetration(a, b);
  EXPECT_EQ(differences(p, detail::penetration_by_sum(a, b)), "");
  EXPECT_EQ(test::check_penetration(a, b, p, test::proximity_oracle(a, b)), "");
}

TEST(Epa, TwoThousandSeededPairsAsTheSumAndTheOracle) {
  for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
    const test::RandomPlacement r = test::random_placement(seed);
    ASSERT_EQ(r.failure, "") << "seed " << seed << ": " << r.description;
    const PenetrationResult p = penetration(r.a, r.b);
    ASSERT_EQ(differences(p, detail::penetration_by_sum(r.a, r.b)), "")
        << "seed " << seed << ": " << r.description;
    ASSERT_EQ(test::check_penetration(r.a, r.b, p, r.oracle), "") << "seed " << seed << ": " << r.description;
  }
}

TEST(Epa, CentredCubesTieOnSixFacets) {
  const ConvexPolyhedron c = shapes::box(v3(-1, -1, -1), v3(1, 1, 1));
  const PenetrationResult p = penetration(c, c);
  EXPECT_EQ(p.squared_depth, 4);
  EXPECT_EQ(p.direction, v3(-1, 0, 0));  // the smallest of the six normals
  expect_as_sum_and_oracle(c, c);
}

TEST(Epa, CubeInsideABiggerCube) {
  const ConvexPolyhedron big = shapes::box(v3(-3, -3, -3), v3(3, 3, 3));
  const ConvexPolyhedron small = shapes::box(v3(-1, -1, -1), v3(1, 1, 1));
  expect_as_sum_and_oracle(big, small);  // six ties
  expect_as_sum_and_oracle(small, big);
  // Off centre: three ties (+x, +y, +z), then two, then one.
  for (const Vec3& t : {v3(1, 1, 1), v3(1, 1, 0), v3(1, 0, 0), v3(2, -1, 0)}) {
    SCOPED_TRACE(test::to_text(t));
    expect_as_sum_and_oracle(big, small.translated(t));
    expect_as_sum_and_oracle(small.translated(t), big);
  }
}

TEST(Epa, SymmetricSpheresTieOnManyFacets) {
  for (int k = 1; k <= 3; ++k) {
    SCOPED_TRACE("Sphere" + std::to_string(k));
    const ConvexPolyhedron s = shapes::geodesic_sphere(k);
    expect_as_sum_and_oracle(s, s);
    expect_as_sum_and_oracle(s, shapes::rotated_geodesic_sphere(k));
    expect_as_sum_and_oracle(s, shapes::cube());
  }
}

TEST(Epa, TouchingAtAVertexEdgeOrFaceReportsTheSmallestFacetThroughTheOrigin) {
  const ConvexPolyhedron a = shapes::box(v3(0, 0, 0), v3(1, 1, 1));
  for (const Vec3& t : {v3(1, 0, 0), v3(1, 1, 0), v3(1, 1, 1), v3(-1, -1, 1), v3(0, 0, -1)}) {
    SCOPED_TRACE(test::to_text(t));
    expect_as_sum_and_oracle(a, a.translated(t));
  }
}

TEST(Epa, PlacedOperandsAsTheSum) {
  const ConvexPolyhedron a = shapes::geodesic_sphere(1);
  const ConvexPolyhedron b = shapes::cube();
  std::mt19937_64 rng(1717);
  std::uniform_real_distribution<double> angle(-3.14, 3.14);
  std::uniform_real_distribution<double> shift(-1.5, 1.5);
  for (int trial = 0; trial < 20; ++trial) {
    SCOPED_TRACE("seed 1717, trial " + std::to_string(trial));
    const double c = std::cos(angle(rng)), s = std::sin(angle(rng));
    Placement pb;
    pb.rotation = {{{c, -s, 0.0}, {s, c, 0.0}, {0.0, 0.0, 1.0}}};
    pb.translation = {shift(rng), shift(rng), shift(rng)};
    const PlacedPolyhedron placed_b(b, pb);
    const PenetrationResult p = penetration(a, placed_b);
    EXPECT_EQ(differences(p, detail::penetration_by_sum(a, placed_b)), "");
    const ConvexPolyhedron mb = placed_b.materialized();
    EXPECT_EQ(test::check_penetration(a, mb, p, test::proximity_oracle(a, mb)), "");
  }
}

// Sets of every dimension on a small grid (many alignments), overlapping by
// construction: solid A + (-B) goes through the EPA, a flat one to the sum.
TEST(Epa, ConvexSetsAsTheSum) {
  std::mt19937_64 rng(2017);
  int deep = 0;  // overlapping with a solid M: answered by the EPA
  for (int trial = 0; trial < 300; ++trial) {
    const int da = trial % 4;
    const int db = (trial / 4) % 4;
    SCOPED_TRACE("seed 2017, trial " + std::to_string(trial));
    const ConvexSet a = test::random_set(rng, da, Vec3{0, 0, 0});
    const ConvexSet b = test::random_set(rng, db, v3(static_cast<long>(rng() % 3) - 1, 0, 0));
    const PenetrationResult p = penetration(a, b);
    EXPECT_EQ(differences(p, detail::penetration_by_sum(a, b)), "");
    EXPECT_TRUE(test::set_contains(a, p.witness_a));
    EXPECT_TRUE(test::set_contains(b, p.witness_b));
    if (p.intersect) {
      EXPECT_EQ(p.witness_a - p.witness_b, p.translation());
    }
    deep += sgn(p.squared_depth) > 0 ? 1 : 0;
  }
  EXPECT_GT(deep, 60);
}

}  // namespace
}  // namespace cvms
