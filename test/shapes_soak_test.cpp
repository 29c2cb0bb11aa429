// SPDX-License-Identifier: MIT
// Long runs of the shape generators: the paper's Sphere5 and Sphere6 (and
// their rotated twins) through the exact hull. Prints their V/E/F, which
// docs/testing.md lists.
#include <gtest/gtest.h>

#include <iostream>
#include <set>
#include <string>

#include "cvms/shapes.hpp"
#include "support/oracle.hpp"

namespace cvms {
namespace {

TEST(GeodesicSphereSoak, LevelsOneToSix) {
  for (bool rotated : {false, true})
    for (int k = 1; k <= 6; ++k) {
      SCOPED_TRACE("k " + std::to_string(k) + " rotated " + std::to_string(rotated));
      ConvexPolyhedron s = rotated ? shapes::rotated_geodesic_sphere(k) : shapes::geodesic_sphere(k);
      std::vector<Vec3> points = shapes::geodesic_sphere_points(k, rotated);
      std::set<Vec3> vertices;
      for (VertexId v : s.mesh().vertices()) vertices.insert(s.vertex(v));
      EXPECT_TRUE(vertices == std::set<Vec3>(points.begin(), points.end()));
      // Measured: no facet merges or flips, the subdivision's own counts.
      EXPECT_EQ(s.num_facets(), 20u << (2 * (k - 1)));
      EXPECT_EQ(s.num_edges(), 30u << (2 * (k - 1)));
      EXPECT_EQ(s.euler_characteristic(), 2);
      if (k <= 4) {  // check_invariants is O(V F)
        EXPECT_EQ(test::check_invariants(s), "");
      }
      std::cout << (rotated ? "rotated_geodesic_sphere(" : "geodesic_sphere(") << k
                << "): V/E/F = " << s.num_vertices() << "/" << s.num_edges() << "/" << s.num_facets() << "\n";
    }
}

}  // namespace
}  // namespace cvms
