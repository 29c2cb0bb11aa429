// SPDX-License-Identifier: MIT
// The solids layer's exact triangle tests on hand-made configurations, and
// the hierarchy's pair count on growing meshes (linear, not quadratic).
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "cvms/solid.hpp"
#include "self_intersection.hpp"
#include "solid_access.hpp"
#include "solid_impl.hpp"
#include "triangle_intersection.hpp"

namespace {

using cvms::Vec3;
using cvms::detail::triangles_overlap;

TEST(TriangleOverlap, SharedEdge) {
  // 0, 1: the edge; 2 and 3 beside it.
  std::vector<Vec3> p = {{0, 0, 0}, {2, 0, 0}, {1, 2, 0}, {1, 1, 0}};
  EXPECT_TRUE(triangles_overlap(p, {0, 1, 2}, {1, 0, 3}));  // coplanar, same side: a fold
  p[3] = {1, -1, 0};
  EXPECT_FALSE(triangles_overlap(p, {0, 1, 2}, {1, 0, 3}));  // coplanar, either side
  p[3] = {1, 1, 1};
  EXPECT_FALSE(triangles_overlap(p, {0, 1, 2}, {1, 0, 3}));  // a dihedral angle
}

TEST(TriangleOverlap, SharedVertex) {
  std::vector<Vec3> p = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, {1, 2}, -1}, {1, {1, 2}, 1}};
  EXPECT_TRUE(triangles_overlap(p, {0, 1, 2}, {0, 3, 4}));  // the second pierces the first
  p[3] = {-1, 0, 1};
  p[4] = {0, -1, 1};
  EXPECT_FALSE(triangles_overlap(p, {0, 1, 2}, {0, 3, 4}));  // touching at the vertex only
  p[3] = {1, 1, 0};
  p[4] = {3, 1, 0};
  EXPECT_TRUE(triangles_overlap(p, {0, 1, 2}, {0, 3, 4}));  // coplanar, angles overlapping
  p[3] = {-1, 0, 0};
  p[4] = {0, -1, 0};
  EXPECT_FALSE(triangles_overlap(p, {0, 1, 2}, {0, 3, 4}));  // coplanar, angles apart
  p[3] = {1, 0, 0};
  p[4] = {1, 0, 1};
  EXPECT_TRUE(triangles_overlap(p, {0, 1, 2}, {0, 3, 4}));  // an edge along the other's edge
  p[3] = {1, 1, 1};
  p[4] = {-1, 1, 1};
  EXPECT_FALSE(triangles_overlap(p, {0, 1, 2}, {0, 3, 4}));  // crosses the plane only at the vertex
}

TEST(TriangleOverlap, NoSharedVertex) {
  std::vector<Vec3> p = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, -1}, {1, 1, 1}, {2, 3, 1}};
  EXPECT_TRUE(triangles_overlap(p, {0, 1, 2}, {3, 4, 5}));  // crossing
  p[3] = {1, 1, 0};
  p[4] = {1, 1, 2};
  EXPECT_TRUE(triangles_overlap(p, {0, 1, 2}, {3, 4, 5}));  // a corner on the face
  p[3] = {5, 5, 0};
  EXPECT_FALSE(triangles_overlap(p, {0, 1, 2}, {3, 4, 5}));  // a corner in the plane, outside
  p = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}, {2, 1, 0}, {1, 2, 0}};
  EXPECT_TRUE(triangles_overlap(p, {0, 1, 2}, {3, 4, 5}));  // coplanar, one inside the other
  p[3] = {5, 5, 0};
  p[4] = {6, 5, 0};
  p[5] = {5, 6, 0};
  EXPECT_FALSE(triangles_overlap(p, {0, 1, 2}, {3, 4, 5}));  // coplanar, apart
  p[3] = {2, 2, 0};                                          // on the hypotenuse x + y = 4
  EXPECT_TRUE(triangles_overlap(p, {0, 1, 2}, {3, 4, 5}));
}

// The surface of the cube [0, k]^3, each side cut into k x k unit squares.
cvms::PolygonSoup grid_cube(int k) {
  cvms::PolygonSoup soup;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      // u x w points out of the cube: e_{axis+1} x e_{axis+2} = e_axis.
      int u = (axis + 1) % 3;
      int w = (axis + 2) % 3;
      if (side == 0) std::swap(u, w);
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
          const auto base = static_cast<std::uint32_t>(soup.points.size());
          for (auto [di, dj] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
            Vec3 p{0, 0, 0};
            p[axis] = side * k;
            p[u] = i + di;
            p[w] = j + dj;
            soup.points.push_back(p);
          }
          soup.add_face({base, base + 1, base + 2, base + 3});
        }
    }
  return soup;
}

std::uint64_t candidate_pairs(int k) {
  const cvms::Solid solid = cvms::Solid::from_soup(grid_cube(k));
  EXPECT_EQ(solid.volume(), k * k * k);
  const auto& impl = cvms::SolidAccess::impl(solid);
  std::vector<std::uint32_t> own_face(impl.triangles.size());
  for (std::uint32_t t = 0; t < own_face.size(); ++t) own_face[t] = t;  // compare every pair
  const auto found =
      cvms::detail::find_self_intersection(impl.tree(), impl.vertices, impl.triangles, own_face);
  EXPECT_FALSE(found.faces.has_value());
  return found.candidate_pairs;
}

TEST(SelfIntersection, CandidatePairsGrowLinearly) {
  const std::uint64_t small = candidate_pairs(8);   // 768 triangles
  const std::uint64_t large = candidate_pairs(24);  // 6912 triangles, 9 times as many
  std::printf("candidate pairs: %llu for 768 triangles, %llu for 6912\n",
              static_cast<unsigned long long>(small), static_cast<unsigned long long>(large));
  EXPECT_LT(large, 12 * small);    // linear: about 9 times; quadratic would be 81
  EXPECT_LT(large, 20ull * 6912);  // a few neighbours per triangle
}

TEST(SolidAccess, AssumeValidDerivesTheProperties) {
  // The L-block's triangles: same derived data as through the validation.
  const cvms::Solid checked =
      cvms::read_solid(std::filesystem::path(CVMS_TEST_DATA_DIR) / "solids" / "l_block.off");
  const cvms::Solid trusted =
      cvms::SolidAccess::assume_valid({checked.vertices().begin(), checked.vertices().end()},
                                      {checked.triangles().begin(), checked.triangles().end()});
  EXPECT_EQ(trusted.volume(), 3);
  EXPECT_EQ(trusted.num_facets(), 8u);
  EXPECT_EQ(trusted.num_reflex_edges(), 1u);
  EXPECT_EQ(trusted.num_shells(), 1u);
  EXPECT_EQ(trusted.genus(), 0u);
  EXPECT_EQ(trusted.locate({cvms::Rational(1, 2), cvms::Rational(3, 2), cvms::Rational(1, 2)}),
            cvms::Location::inside);
  EXPECT_EQ(trusted.locate({cvms::Rational(3, 2), cvms::Rational(3, 2), cvms::Rational(1, 2)}),
            cvms::Location::outside);
}

}  // namespace
