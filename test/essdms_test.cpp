// SPDX-License-Identifier: MIT
// Tests specific to ESSDMS (paper Section 5.2, lib/minkowski/essdms.cpp): which of the
// four slope-diagram cases each facet falls in, counted by hand, and the
// contributing-vertex pre-check of the arc crossings. The exact sums
// themselves are checked for every algorithm by the differential suite in
// cvms_test.cpp.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cvms/minkowski.hpp"
#include "cvms/convex_hull.hpp"
#include "cvms/shapes.hpp"
#include "support/hand_solids.hpp"
#include "support/minkowski_check.hpp"
#include "support/random_clouds.hpp"

namespace cvms {
namespace {


// A sum with its diagnostic counters (Options::diagnostics).
struct CountedSum : MinkowskiResult {
  SumDiagnostics diagnostics;
};

CountedSum counted(const ConvexPolyhedron& a, const ConvexPolyhedron& b, Options o) {
  CountedSum r;
  o.diagnostics = &r.diagnostics;
  static_cast<MinkowskiResult&>(r) = minkowski_sum(a, b, o);
  return r;
}

CountedSum essdms(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  Options o;
  o.algorithm = Algorithm::essdms;
  return counted(a, b, o);
}

TEST(Essdms, CoincidentFacetPointsOnly) {
  // Cube + cube: six coincident facet points (case 1). Adjacent facets share
  // two contributing vertices (the common edge of their partners), so the
  // pre-check drops every arc and no crossing is tested.
  const auto c = shapes::cube();
  const CountedSum r = essdms(c, c);
  const Stats& s = r.stats;
  EXPECT_EQ(s.translated_facets, 6u);
  EXPECT_EQ(s.corner_facets, 0u);
  EXPECT_EQ(s.edge_facets, 0u);
  EXPECT_EQ(r.diagnostics.contributing_ties, 12u);
  EXPECT_EQ(r.diagnostics.edge_candidates, 0u);
}

TEST(Essdms, VertexRegionsAndCrossingArcs) {
  // Cube + octahedron |x| + |y| + |z| <= 1: no facet point of one lies on a
  // facet point or an arc of the other (case 4 for all 6 + 8 facets, one
  // contributing vertex each). Every arc passes the pre-check (the facets of
  // each edge have distinct single contributing vertices), so 12 x 12 pairs
  // are tested, and each cube arc, e.g. (1,0,0)-(0,1,0), properly crosses
  // exactly one octahedron arc, (1,1,1)-(1,1,-1), at (1,1,0): 12 edge facets.
  const auto c = shapes::cube();
  const auto o = shapes::octahedron();
  const CountedSum r = essdms(c, o);
  EXPECT_EQ(r.polyhedron.num_facets(), 26u);
  EXPECT_EQ(r.stats.translated_facets, 6u);
  EXPECT_EQ(r.stats.corner_facets, 8u);
  EXPECT_EQ(r.stats.edge_facets, 12u);
  EXPECT_EQ(r.diagnostics.contributing_ties, 0u);
  EXPECT_EQ(r.diagnostics.edge_candidates, 144u);
}

TEST(Essdms, FacetPointsOnArcs) {
  // Cube + rhombic dodecahedron (normals (+-1, +-1, 0) and permutations):
  // each of the 12 rhombi has its facet point strictly inside one cube arc
  // (case 2, f_B + e_A, two contributing vertices); the cube's facet points
  // lie in vertex regions of the dodecahedron (its 4-valent vertices such as
  // (2, 0, 0)). The arcs of the dodecahedron end on cube arcs and never cross
  // one: no edge facet.
  const auto c = shapes::cube();
  const auto r = convex_hull(test::rhombic_dodecahedron_points());
  const CountedSum sum = essdms(c, r);
  const Stats& s = sum.stats;
  EXPECT_EQ(s.translated_facets, 6u);
  EXPECT_EQ(s.corner_facets, 12u);
  EXPECT_EQ(s.edge_facets, 0u);
  EXPECT_EQ(sum.diagnostics.contributing_ties, 12u);
}

TEST(Essdms, PrecheckDropsArcsInsideOneNormalCone) {
  // Cube + geodesic sphere: the arcs of the sphere whose two facets have the
  // same contributing cube vertex lie in one octant and cannot cross a cube
  // arc; only the arcs that straddle an octant boundary are tested.
  const auto c = shapes::cube();
  const auto s = shapes::geodesic_sphere(3);
  const CountedSum sum = essdms(c, s);
  const Stats& st = sum.stats;
  EXPECT_GT(sum.diagnostics.edge_candidates, 0u);
  EXPECT_LT(sum.diagnostics.edge_candidates, std::uint64_t{c.num_edges()} * s.num_edges() / 10);
  EXPECT_GT(st.edge_facets, 0u);
  EXPECT_LE(st.edge_facets, sum.diagnostics.edge_candidates);
}

TEST(Essdms, ClassifiesFacetsLikeCvmsOnRandomPairs) {
  // The facets of A + B are the same whatever the algorithm, and CVMS and
  // ESSDMS name them the same way (translated, corner, edge; ties = facets
  // with two or more contributing vertices), so their stats agree.
  for (std::uint64_t seed = 500; seed < 800; ++seed) {
    const test::RandomPair p = test::random_pair(seed, 60);
    SCOPED_TRACE("seed " + std::to_string(seed) + " (" + p.description + ")");
    Options o;
    o.algorithm = Algorithm::cvms;
    const CountedSum cv_sum = counted(p.a, p.b, o), es_sum = essdms(p.a, p.b);
    const Stats &cv = cv_sum.stats, &es = es_sum.stats;
    ASSERT_EQ(es.translated_facets, cv.translated_facets);
    ASSERT_EQ(es.corner_facets, cv.corner_facets);
    ASSERT_EQ(es.edge_facets, cv.edge_facets);
    ASSERT_EQ(es_sum.diagnostics.contributing_ties, cv_sum.diagnostics.contributing_ties);
  }
}

}  // namespace
}  // namespace cvms
