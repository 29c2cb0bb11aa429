// SPDX-License-Identifier: MIT
// The penetration query's fast -P (lib/proximity/reflection.hpp) against
// ConvexPolyhedron::reflected(), which recomputes every plane: same vertices,
// normals and offsets index by index, and a valid convex polyhedron.
#include <gtest/gtest.h>

#include "cvms/shapes.hpp"
#include "reflection.hpp"

namespace cvms::detail {
namespace {

TEST(ProximityReflection, EqualsReflected) {
  for (const ConvexPolyhedron& p : {shapes::cube(), shapes::tetrahedron(), shapes::truncated_cube(),
                                    shapes::rotated_geodesic_sphere(2), shapes::random_hull(7, 60)}) {
    const ConvexPolyhedron fast = reflection(p);
    const ConvexPolyhedron slow = p.reflected();
    ASSERT_EQ(fast.num_vertices(), slow.num_vertices());
    ASSERT_EQ(fast.num_facets(), slow.num_facets());
    for (VertexId v : fast.mesh().vertices()) EXPECT_EQ(fast.vertex(v), slow.vertex(v));
    for (FaceId f : fast.mesh().faces()) {
      EXPECT_EQ(fast.normal(f), slow.normal(f));
      EXPECT_EQ(fast.plane_offset(f), slow.plane_offset(f));
    }
    EXPECT_TRUE(fast.is_convex());
    EXPECT_EQ(fast.euler_characteristic(), 2);
  }
}

}  // namespace
}  // namespace cvms::detail
