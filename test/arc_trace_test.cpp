// SPDX-License-Identifier: MIT
// Tests of the Gaussian-arc walk (lib/minkowski/arc_trace.cpp) against a brute-force
// crossing test over all edges of B in plain rational arithmetic, on
// tie-heavy pairs (parallel facets, parallel edges, arcs through facet
// normals) and random pairs.
#include "arc_trace.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "contributing_vertices.hpp"
#include "cvms/convex_hull.hpp"
#include "cvms/shapes.hpp"
#include "support/hand_solids.hpp"
#include "support/random_clouds.hpp"
#include "polyhedron_builder.hpp"

namespace cvms::detail {
namespace {

Rational det(const Vec3& u, const Vec3& v, const Vec3& w) { return dot(u, cross(v, w)); }

// x (perpendicular to the edge of h) strictly inside the Gaussian arc of h,
// which runs from n(face(h)) to n(face(twin(h))) counterclockwise about d_h.
bool strictly_inside_arc(const ConvexPolyhedron& p, HalfedgeId h, const Vec3& x) {
  const Mesh& m = p.mesh();
  const Vec3 d = p.edge_vector(h);
  const Vec3& n1 = p.normal(m.face(h));
  const Vec3& n2 = p.normal(m.face(Mesh::twin(h)));
  return sgn(det(n1, x, d)) > 0 && sgn(det(x, n2, d)) > 0;
}

// The halfedges g of b whose arcs the arc of ha properly crosses, oriented so
// that cross(d_A, d_g) is the crossing point; sorted.
std::vector<HalfedgeId> brute_force_crossings(const ConvexPolyhedron& a, HalfedgeId ha,
                                              const ConvexPolyhedron& b) {
  std::vector<HalfedgeId> out;
  const Vec3 da = a.edge_vector(ha);
  for (HalfedgeId g : b.mesh().halfedges()) {
    const Vec3 x = cross(da, b.edge_vector(g));
    if (is_zero(x)) continue;
    if (strictly_inside_arc(a, ha, x) && strictly_inside_arc(b, g, x)) out.push_back(g);
  }
  return out;
}

// Every edge of a that passes Property 1: the walk finds exactly the brute
// force crossings. Returns the number of crossings found (to check the cases
// exercise the walk).
std::size_t expect_walk_matches_brute_force(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  std::vector<VertexId> list;
  ContributingVertices cv(a.num_facets());
  for (FaceId f : a.mesh().faces()) {
    maximising_vertices(b, detail::normal_ref(a, f), list);
    cv.append(list);
  }
  std::size_t found = 0;
  std::uint64_t steps = 0;
  // One scratch for all edges, as the algorithm reuses it: d_A of each
  // edge overwrites the previous one's.
  ArcTraceScratch scratch;
  std::vector<HalfedgeId>& got = scratch.crossed;
  for (HalfedgeId ha : a.mesh().halfedges()) {
    const auto c1 = cv.of(a.mesh().face(ha));
    const auto c2 = cv.of(a.mesh().face(Mesh::twin(ha)));
    if (!disjoint_sorted(c1, c2)) {
      // Property 1: no crossing at all.
      EXPECT_TRUE(brute_force_crossings(a, ha, b).empty()) << "halfedge " << ha.index();
      continue;
    }
    got.clear();
    trace_edge_facets(a, ha, b, c1, c2, scratch, steps);
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, brute_force_crossings(a, ha, b)) << "halfedge " << ha.index();
    found += got.size();
  }
  return found;
}

ConvexPolyhedron rhombic_dodecahedron() {
  return convex_hull(test::rhombic_dodecahedron_points());
}

TEST(ArcTrace, CubePlusCubeAndAPlusAHaveNoCrossings) {
  const auto c = shapes::cube();
  EXPECT_EQ(expect_walk_matches_brute_force(c, c), 0u);
  const auto s = shapes::geodesic_sphere(2);
  EXPECT_EQ(expect_walk_matches_brute_force(s, s), 0u);
}

TEST(ArcTrace, ArcsThroughFacetNormalsOfB) {
  // Every arc of the cube passes through a facet normal of the rhombic
  // dodecahedron: the walk jumps across those facets and reports nothing.
  const auto c = shapes::cube();
  const auto r = rhombic_dodecahedron();
  EXPECT_EQ(expect_walk_matches_brute_force(c, r), 0u);
  expect_walk_matches_brute_force(r, c);
  const auto t = shapes::truncated_cube();
  expect_walk_matches_brute_force(t, r);
  expect_walk_matches_brute_force(r, t);
}

TEST(ArcTrace, PrismsWithParallelEdgesAndFacets) {
  const auto p6 = shapes::prism(6, 1);
  const auto p8 = shapes::prism(8, Rational(5, 2));
  Mat3 quarter_turn_x;  // (x, y, z) -> (x, -z, y)
  quarter_turn_x.m[0][0] = 1;
  quarter_turn_x.m[1][2] = -1;
  quarter_turn_x.m[2][1] = 1;
  const auto side = shapes::prism(5, 3).transformed(quarter_turn_x, {});
  // Coaxial prisms: the side arcs share the equator (parallel edges) and the
  // meridians meet it at their end points only: no proper crossing.
  EXPECT_EQ(expect_walk_matches_brute_force(p6, p8), 0u);
  expect_walk_matches_brute_force(p8, p6);
  EXPECT_GT(expect_walk_matches_brute_force(p6, side), 0u);
  expect_walk_matches_brute_force(side, p8);
  expect_walk_matches_brute_force(side, side);
}

TEST(ArcTrace, RotatedSpheresInGeneralPosition) {
  const auto a = shapes::geodesic_sphere(2);
  const auto b = shapes::rotated_geodesic_sphere(2);
  EXPECT_GT(expect_walk_matches_brute_force(a, b), 50u);
  expect_walk_matches_brute_force(b, a);
  const auto c = shapes::cube();
  expect_walk_matches_brute_force(c, b);
  expect_walk_matches_brute_force(b, c);
}

TEST(ArcTrace, RandomPairsMatchBruteForce) {
  for (std::uint64_t seed = 1; seed <= 120; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const test::RandomPair p = test::random_pair(seed, 40);
    expect_walk_matches_brute_force(p.a, p.b);
    expect_walk_matches_brute_force(p.b, p.a);
  }
}

}  // namespace
}  // namespace cvms::detail
