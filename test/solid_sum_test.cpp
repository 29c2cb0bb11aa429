// SPDX-License-Identifier: MIT
// minkowski_sum of solids (cvms/solid_sum.hpp) end to end, against oracles
// that never run the boundary code:
//  - polycubes summed with integer boxes or with polycubes, placed by one
//    map x -> M x + t (decimals, rotations): the voxel oracle
//    (support/voxel_oracle.hpp) gives the volume, the vertex set, the facet
//    count and containment;
//  - exact points (random with fixed seeds, and on and next to the output's
//    vertices, edges and facets) located against brute force over the
//    pairwise sums of the decompositions' pieces (minkowski_sum_pieces);
//  - every output vertex on three independent facet planes of those pieces;
//  - the one-convex road against the road through both decompositions.
// The fixtures and checks are in solid_sum_fixtures.hpp; many random
// polycubes are in the soak run (solid_sum_soak_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <string>
#include <tuple>
#include <utility>

#include "cvms/error.hpp"
#include "diamond_ring.hpp"
#include "solid_sum_fixtures.hpp"

namespace cvms::test {
namespace {

// The oracle itself against counts found by hand.
TEST(VoxelOracle, AgreesWithHandCounts) {
  // L + unit cube: the 3 x 3 L without its corner, 2 high.
  const Cubes l = polycube_sum(l_shape(), box_cubes(1, 1, 1));
  EXPECT_EQ(l, dilated(l_shape(), 1, 1, 1));
  EXPECT_EQ(l.size(), 16u);
  EXPECT_EQ(voxel_vertices(l).size(), 12u);
  EXPECT_EQ(voxel_facets(l), 8u);
  // Frame 5 + unit cube: a 6 x 6 ring around a 2 x 2 hole, 2 high.
  const Cubes ring = dilated(frame(5), 1, 1, 1);
  EXPECT_EQ(ring.size(), 2u * (36 - 4));
  EXPECT_EQ(voxel_vertices(ring).size(), 16u);
  EXPECT_EQ(voxel_facets(ring), 10u);
  // Two blocks meeting along an edge: the edge's ends once in the grid.
  const Cubes edge = dilated({{0, 0, 0}, {2, 2, 0}}, 1, 1, 1);
  EXPECT_EQ(voxel_vertices(edge).size(), 14u);
  EXPECT_EQ(voxel_facets(edge), 12u);
  EXPECT_TRUE(voxel_contains(edge, Vec3{Rational(2), Rational(2), Rational(1, 2)}));
  EXPECT_FALSE(voxel_contains(edge, Vec3{Rational(5, 2), Rational(3, 2), Rational(1, 2)}));
  EXPECT_TRUE(voxel_contains(edge, Vec3{Rational(-0), Rational(3, 2), Rational(2)}));
  EXPECT_FALSE(voxel_contains(edge, Vec3{Rational(-1, 3), Rational(3, 2), Rational(1)}));
}

TEST(SolidSum, LShapePlusCubeIsTheLOfSideThreeByHand) {
  const Solid result = minkowski_sum(polycube(l_shape()), polycube(box_cubes(1, 1, 1)));
  // By hand: the 3 x 3 square without its 1 x 1 corner, 2 high: 8 x 2.
  EXPECT_EQ(result.volume(), 16);
  EXPECT_EQ(result.num_facets(), 8u);
  EXPECT_EQ(vertex_coordinates(result).size(), 12u);
  EXPECT_EQ(result.num_shells(), 1u);
  expect_polycube_sum(l_shape(), box_cubes(1, 1, 1), {}, 1);
}

TEST(SolidSum, LShapePlusFlatBoxAndTallBox) {
  expect_polycube_sum(l_shape(), box_cubes(2, 1, 3), {}, 2);
  expect_polycube_sum(cubes_where(3, 3, 2, [](int i, int j, int k) { return i + j + k < 3; }),
                      box_cubes(1, 2, 1), {}, 3);
}

TEST(SolidSum, FrameKeepsItsHoleWithASmallCubeAndLosesItWithABigOne) {
  const Solid small = minkowski_sum(polycube(frame(5)), polycube(box_cubes(1, 1, 1)));
  EXPECT_EQ(small.genus(), 1u);
  expect_polycube_sum(frame(5), box_cubes(1, 1, 1), {}, 4);
  const Solid big = minkowski_sum(polycube(frame(5)), polycube(box_cubes(3, 3, 1)));
  EXPECT_EQ(big.genus(), 0u);
  EXPECT_TRUE(big.is_convex());
  expect_polycube_sum(frame(5), box_cubes(3, 3, 1), {}, 5);
}

TEST(SolidSum, RotatedCoarseTorusKeepsItsGenus) {
  // A ring 4 x 4 x 2 around a 2 x 2 hole, turned off every axis, plus a
  // turned unit cube: the voxel oracle through the same rotation.
  const Cubes torus =
      cubes_where(4, 4, 2, [](int i, int j, int) { return i == 0 || j == 0 || i == 3 || j == 3; });
  const Mapping turn{rational_rotation(), Vec3{Rational(1, 3), 0, Rational(-2)}};
  const Solid result = minkowski_sum(polycube(torus, turn), polycube(box_cubes(1, 1, 1), turn));
  EXPECT_EQ(result.genus(), 1u);
  expect_polycube_sum(torus, box_cubes(1, 1, 1), turn, 6);
}

TEST(SolidSum, CavityShrinksWithASmallCubeAndFillsWithABigOne) {
  const Solid small = minkowski_sum(polycube(hollow_cube(5)), polycube(box_cubes(1, 1, 1)));
  EXPECT_EQ(small.num_cavities(), 1u);
  EXPECT_EQ(small.num_shells(), 2u);
  expect_polycube_sum(hollow_cube(5), box_cubes(1, 1, 1), {}, 7);
  const Solid big = minkowski_sum(polycube(hollow_cube(5)), polycube(box_cubes(3, 3, 3)));
  EXPECT_EQ(big.num_cavities(), 0u);
  expect_voxels(big, dilated(hollow_cube(5), 3, 3, 3));
}

TEST(SolidSum, DecimalCoordinates) {
  // Cubes of side 0.1 at an offset of 0.25: every coordinate a decimal.
  const Rational tenth_part(1, 10);
  const Mat3 scale = matrix({tenth_part, 0, 0, 0, tenth_part, 0, 0, 0, tenth_part});
  const Mapping tenth{scale, Vec3{Rational(1, 4), Rational(-7, 20), Rational(3, 100)}};
  expect_polycube_sum(l_shape(), box_cubes(2, 1, 1), tenth, 8);
  expect_polycube_sum(frame(4), box_cubes(1, 1, 1), tenth, 9);
}

TEST(SolidSum, TwoNonConvexSolidsGoThroughBothDecompositions) {
  expect_polycube_sum(l_shape(), frame(3), {}, 10);
  const Cubes step = cubes_where(2, 2, 2, [](int i, int j, int k) { return i + j + k <= 1; });
  expect_polycube_sum(step, l_shape(), {}, 11);
}

TEST(SolidSum, RingCutAtItsJointsPlusLBlock) {
  // Both non-convex: the ring's decomposition cuts it at its joints (planes
  // that hold no facet). The oracle's pieces are the ring's segments built
  // by hand, each + each unit cube of the L: no decomposition in them.
  const DiamondRing ring{{{2, 1}, {1, 2}, {-1, 2}, {-2, 1}, {-2, -1}, {-1, -2}, {1, -2}, {2, -1}}};
  const Solid result = minkowski_sum(ring.solid(), polycube(l_shape()));
  std::vector<ConvexPolyhedron> cubes;
  for (const auto& c : l_shape()) {
    std::vector<Vec3> corners;
    for (int k = 0; k < 8; ++k)
      corners.push_back(Vec3{Rational(c[0] + (k & 1)), Rational(c[1] + ((k >> 1) & 1)), Rational(c[2] + (k >> 2))});
    cubes.push_back(convex_hull(corners));
  }
  const ConvexUnion by_hand = minkowski_sum(ConvexUnion(ring.segment_hulls()), ConvexUnion(std::move(cubes)));
  expect_points(result, by_hand, 15);
  expect_vertices_on_piece_planes(result, by_hand);
  EXPECT_EQ(result.num_shells(), 1u);
  EXPECT_EQ(result.genus(), 1u);
}

TEST(SolidSum, LobesTouchingAlongAnEdgeHoldItsVerticesOncePerLobe) {
  // Two unit cubes apart, plus a unit cube: two 2 x 2 x 2 blocks meeting
  // along the edge x = y = 2, 0 <= z <= 2. The output keeps both blocks
  // closed: its ends (2, 2, 0) and (2, 2, 2) appear twice, once per shell.
  const Cubes apart{{0, 0, 0}, {2, 2, 0}};
  const Solid result = minkowski_sum(polycube(apart), polycube(box_cubes(1, 1, 1)));
  EXPECT_EQ(result.num_shells(), 2u);
  EXPECT_EQ(result.vertices().size(), 16u);
  const Vec3 end{Rational(2), Rational(2), Rational(0)};
  EXPECT_EQ(std::count(result.vertices().begin(), result.vertices().end(), end), 2);
  EXPECT_EQ(result.locate(Vec3{Rational(2), Rational(2), Rational(1)}), Location::boundary);
  expect_polycube_sum(apart, box_cubes(1, 1, 1), {}, 12);
}

TEST(SolidSum, LobesTouchingAtAPointHoldItOncePerLobe) {
  const Cubes apart{{0, 0, 0}, {2, 2, 2}};
  const Solid result = minkowski_sum(polycube(apart), polycube(box_cubes(1, 1, 1)));
  EXPECT_EQ(result.num_shells(), 2u);
  const Vec3 touch{Rational(2), Rational(2), Rational(2)};
  EXPECT_EQ(std::count(result.vertices().begin(), result.vertices().end(), touch), 2);
  expect_polycube_sum(apart, box_cubes(1, 1, 1), {}, 13);
}

Solid data_solid(const std::string& name) {
  return read_solid(std::string(CVMS_TEST_DATA_DIR) + "/solids/" + name);
}

TEST(SolidSum, StarPrismPlusCube) {
  const Solid star = data_solid("star_prism.off");
  const Solid cube = polycube(box_cubes(1, 1, 1));
  const Solid result = minkowski_sum(star, cube);
  const ConvexUnion pieces = minkowski_sum_pieces(star, cube);
  expect_points(result, pieces, 14);
  expect_vertices_on_piece_planes(result, pieces);
  EXPECT_EQ(result.num_shells(), 1u);
}

TEST(SolidSum, OneConvexRoadAndBothDecomposedRoadGiveTheSameSolid) {
  for (const Solid& a : {data_solid("star_prism.off"), polycube(hollow_cube(4)), polycube(frame(4))}) {
    const Solid b =
        polycube(box_cubes(1, 2, 1), {Mat3::identity(), Vec3{Rational(1, 2), 0, Rational(-1, 3)}});
    const Solid one_convex = minkowski_sum(a, b);
    const Solid decomposed = union_solid(minkowski_sum_pieces(a, b));
    EXPECT_EQ(vertex_coordinates(one_convex), vertex_coordinates(decomposed));
    EXPECT_EQ(one_convex.volume(), decomposed.volume());
    EXPECT_EQ(one_convex.num_facets(), decomposed.num_facets());
    // The sum commutes: B + A takes the same road.
    const Solid swapped = minkowski_sum(b, a);
    EXPECT_EQ(vertex_coordinates(swapped), vertex_coordinates(one_convex));
    EXPECT_EQ(swapped.volume(), one_convex.volume());
  }
}

TEST(SolidSum, TwoConvexSolidsGiveTheirConvexSum) {
  const Solid a = polycube(box_cubes(1, 2, 3));
  const Solid b = polycube(box_cubes(2, 1, 1), {Mat3::identity(), Vec3{Rational(1, 2), 0, 0}});
  const Solid result = minkowski_sum(a, b);
  EXPECT_TRUE(result.is_convex());
  EXPECT_EQ(result.volume(), 3 * 3 * 4);
  EXPECT_EQ(vertex_coordinates(result).size(), 8u);
}

TEST(SolidSum, ThreadCountDoesNotChangeTheResult) {
  for (const Solid& a : {polycube(hollow_cube(4)), data_solid("star_prism.off")}) {
    const Solid b = polycube(box_cubes(1, 1, 1));
    Options one, two;
    two.threads = 2;
    const Solid r1 = minkowski_sum(a, b, one), r2 = minkowski_sum(a, b, two);
    EXPECT_TRUE(std::ranges::equal(r1.vertices(), r2.vertices()));
    EXPECT_TRUE(std::ranges::equal(r1.triangles(), r2.triangles()));
  }
  const Solid r1 = minkowski_sum(polycube(l_shape()), polycube(frame(3)));
  Options two;
  two.threads = 2;
  const Solid r2 = minkowski_sum(polycube(l_shape()), polycube(frame(3)), two);
  EXPECT_TRUE(std::ranges::equal(r1.vertices(), r2.vertices()));
  EXPECT_TRUE(std::ranges::equal(r1.triangles(), r2.triangles()));
}

TEST(SolidSum, ProgressCanCancelEachRoad) {
  const Solid l = polycube(l_shape()), cube = polycube(box_cubes(1, 1, 1)), ring = polycube(frame(3));
  for (unsigned threads : {1u, 2u})
    for (int allowed : {0, 1, 3}) {
      SCOPED_TRACE("threads " + std::to_string(threads) + ", calls allowed " + std::to_string(allowed));
      int calls = 0;
      Options options;
      options.threads = threads;
      options.progress = [&](const Progress&) { return calls++ < allowed; };
      for (const auto& [a, b] : {std::pair{l, cube}, std::pair{l, ring}, std::pair{cube, cube}}) {
        // A sum of two unit cubes reports at least its stages' starts and ends.
        if (a.is_convex() && b.is_convex() && allowed > 1) continue;
        calls = 0;
        try {
          (void)minkowski_sum(a, b, options);
          ADD_FAILURE() << "not cancelled";
        } catch (const Error& e) {
          EXPECT_EQ(e.category(), ErrorCategory::cancelled) << e.what();
        }
      }
    }
}

TEST(SolidSum, ProgressHearsTheFaceSums) {
  std::set<std::string> stages;
  Options options;
  options.progress = [&](const Progress& p) {
    stages.insert(p.stage);
    return true;
  };
  (void)minkowski_sum(polycube(l_shape()), polycube(box_cubes(1, 1, 1)), options);
  EXPECT_EQ(stages.count("solid sum: faces"), 1u);
}

TEST(SolidSum, LimitErrorNamesTheLimit) {
  Options options;
  options.limits.max_output_facets = 12;
  const Solid l = polycube(l_shape()), cube = polycube(box_cubes(1, 1, 1)), ring = polycube(frame(3));
  for (const auto& [a, b] : {std::pair{l, cube}, std::pair{cube, l}, std::pair{l, ring}}) {
    try {
      (void)minkowski_sum(a, b, options);
      ADD_FAILURE() << "no limit error";
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::limit);
      EXPECT_NE(std::string(e.message()).find("max_output_facets"), std::string::npos) << e.what();
    }
  }
  options.limits.max_output_facets = std::uint64_t{1} << 26;
  options.limits.max_memory_bytes = 16 * SumLimits::bytes_per_output_facet;
  try {
    (void)minkowski_sum(l, cube, options);
    ADD_FAILURE() << "no limit error";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::limit);
    EXPECT_NE(std::string(e.message()).find("max_memory_bytes"), std::string::npos) << e.what();
  }
}

TEST(SolidSum, EmptyOperandIsRefused) {
  const Solid cube = polycube(box_cubes(1, 1, 1));
  for (const auto& [a, b, name] : {std::tuple{Solid(), cube, "A"}, std::tuple{cube, Solid(), "B"}}) {
    try {
      (void)minkowski_sum(a, b);
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
      EXPECT_NE(std::string(e.message()).find(std::string(name) + " is empty"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace cvms::test
