// SPDX-License-Identifier: MIT
// The parts of the sum of a solid with a convex polyhedron that do not need
// the union's boundary: the solid's boundary cut into convex polygons
// (facet_polygons.hpp), checked by planes, convexity and areas against the
// solid's own triangles; the sums of those polygons with the polyhedron
// (face_sums.hpp), checked against the exact hull of the pairwise vertex
// sums, for thread counts, limits and cancellation.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <string>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/convex_set.hpp"
#include "cvms/convex_union.hpp"
#include "cvms/decomposition.hpp"
#include "cvms/error.hpp"
#include "decomposition_fixtures.hpp"
#include "face_sums.hpp"
#include "facet_polygons.hpp"
#include "support/union_oracle.hpp"

namespace cvms::test {
namespace {

Solid grid_solid(int nx, int ny, int nz, const std::function<bool(int, int, int)>& fill) {
  return unit_grid(nx, ny, nz, fill).solid();
}

Solid l_block() {
  return grid_solid(2, 2, 1, [](int i, int j, int) { return i + j < 2; });
}

Solid hollow_cube() {
  return grid_solid(
      4, 4, 4, [](int i, int j, int k) { return i == 0 || j == 0 || k == 0 || i == 3 || j == 3 || k == 3; });
}

Solid star_prism() { return read_solid(std::string(CVMS_TEST_DATA_DIR) + "/solids/star_prism.off"); }

// Twice the area of a planar polygon along n: dot(n, sum of cross(p_i, p_i+1)).
Rational twice_area(const std::vector<Vec3>& polygon, const Vec3& n) {
  Vec3 sum;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    sum = sum + cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return dot(n, sum);
}

// The facet whose plane holds every corner and whose normal the polygon's
// orientation agrees with; -1 if none.
long facet_of(const Solid& s, const std::vector<Vec3>& polygon) {
  for (std::uint32_t f = 0; f < s.num_facets(); ++f) {
    bool on = true;
    for (const Vec3& p : polygon) on = on && dot(s.facet_normal(f), p) == s.facet_offset(f);
    if (on && twice_area(polygon, s.facet_normal(f)) > 0) return f;
  }
  return -1;
}

TEST(FacetPolygons, AUnitCubeGivesItsSixSquares) {
  const std::vector<std::vector<Vec3>> polygons =
      detail::facet_polygons(grid_solid(1, 1, 1, [](int, int, int) { return true; }));
  ASSERT_EQ(polygons.size(), 6u);
  for (const auto& p : polygons) EXPECT_EQ(p.size(), 4u);
}

TEST(FacetPolygons, ConvexOnOneFacetEachAndCoveringEveryFacet) {
  for (const Solid& s : {l_block(), hollow_cube(), star_prism()}) {
    const std::vector<std::vector<Vec3>> polygons = detail::facet_polygons(s);
    EXPECT_LT(polygons.size(), s.triangles().size());
    std::map<long, Rational> polygon_area, triangle_area;
    for (const auto& polygon : polygons) {
      const long f = facet_of(s, polygon);
      ASSERT_GE(f, 0);
      const ConvexSet convex = ConvexSet::polygon(polygon);  // throws unless convex
      EXPECT_EQ(convex.dimension(), 2);
      polygon_area[f] += twice_area(polygon, s.facet_normal(static_cast<std::uint32_t>(f)));
    }
    for (std::size_t t = 0; t < s.triangles().size(); ++t) {
      const auto& tri = s.triangles()[t];
      const std::uint32_t f = s.triangle_facets()[t];
      triangle_area[f] +=
          twice_area({s.vertices()[tri[0]], s.vertices()[tri[1]], s.vertices()[tri[2]]}, s.facet_normal(f));
    }
    EXPECT_EQ(polygon_area, triangle_area);
  }
}

ConvexPolyhedron tilted_box() {
  return convex_hull(std::vector<Vec3>{
      {0, 0, 0}, {2, 1, 0}, {0, 1, 0}, {2, 2, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, Rational(3, 2)}, {1, 1, 1}});
}

TEST(FaceSums, EachIsTheHullOfThePairwiseVertexSums) {
  const std::vector<std::vector<Vec3>> polygons = detail::facet_polygons(star_prism());
  const ConvexPolyhedron b = tilted_box();
  const std::vector<ConvexPolyhedron> sums = detail::face_sums(polygons, b, Options{});
  ASSERT_EQ(sums.size(), polygons.size());
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    std::vector<Vec3> pairwise;
    for (const Vec3& p : polygons[i])
      for (VertexId v : b.mesh().vertices()) pairwise.push_back(p + b.vertex(v));
    EXPECT_EQ(vertex_set(sums[i]), vertex_set(convex_hull(pairwise))) << "polygon " << i;
  }
}

// A + B = (A + b) u (the face sums) for b inside B: random exact points
// and the face sums' vertices against brute force over the pairwise sums of
// both decompositions' pieces.
TEST(FaceSums, WithTheSolidMovedIntoBTheyMakeTheWholeSum) {
  const ConvexPolyhedron b = tilted_box();
  const Vec3 inside_b{Rational(1, 2), Rational(1, 2), Rational(1, 2)};
  for (const Solid& a : {l_block(), hollow_cube(), star_prism()}) {
    const std::vector<ConvexPolyhedron> sums = detail::face_sums(detail::facet_polygons(a), b, Options{});
    const ConvexUnion faces(sums);
    const ConvexUnion pieces = minkowski_sum_pieces(a, Solid::from_polyhedron(b));
    std::mt19937_64 rng(50);
    for (int k = 0; k < 500; ++k) {
      const Vec3 p = random_exact_point(rng, 7);
      EXPECT_EQ(a.contains(p - inside_b) || faces.contains(p), union_contains_brute_force(pieces, p))
          << "seed 50, point " << k;
    }
    for (const ConvexPolyhedron& sum : sums)
      for (VertexId v : sum.mesh().vertices()) EXPECT_TRUE(union_contains_brute_force(pieces, sum.vertex(v)));
  }
}

TEST(FaceSums, ThreadCountDoesNotChangeTheSums) {
  const std::vector<std::vector<Vec3>> polygons = detail::facet_polygons(hollow_cube());
  Options two;
  two.threads = 2;
  const std::vector<ConvexPolyhedron> one = detail::face_sums(polygons, tilted_box(), Options{});
  const std::vector<ConvexPolyhedron> other = detail::face_sums(polygons, tilted_box(), two);
  ASSERT_EQ(one.size(), other.size());
  for (std::size_t i = 0; i < one.size(); ++i) EXPECT_EQ(vertex_set(one[i]), vertex_set(other[i]));
}

TEST(FaceSums, TheTotalOfFacetsRespectsTheLimitsForEveryThreadCount) {
  const std::vector<std::vector<Vec3>> polygons = detail::facet_polygons(star_prism());
  std::string first;
  for (unsigned threads : {1u, 2u}) {
    Options options;
    options.threads = threads;
    options.limits.max_output_facets = 40;  // a few sums fit, not all
    try {
      (void)detail::face_sums(polygons, tilted_box(), options);
      ADD_FAILURE() << "no limit error";
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::limit);
      EXPECT_NE(std::string(e.message()).find("SumLimits::max_output_facets"), std::string::npos) << e.what();
      if (first.empty()) first = e.message();
      EXPECT_EQ(std::string(e.message()), first);  // the same face named whatever the threads
    }
  }
  Options tiny;
  tiny.limits.max_output_facets = 4 * polygons.size() - 1;
  try {
    (void)detail::face_sums(polygons, tilted_box(), tiny);
    ADD_FAILURE() << "no limit error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.message()).find("would have at least 4 facets each"), std::string::npos)
        << e.what();
  }
}

TEST(FaceSums, ProgressCountsTheFacesAndCanStopThem) {
  const std::vector<std::vector<Vec3>> polygons = detail::facet_polygons(hollow_cube());
  std::uint64_t last = 0, total = 0;
  Options options;
  options.progress = [&](const Progress& p) {
    EXPECT_STREQ(p.stage, "solid sum: faces");
    last = p.done;
    total = p.total;
    return true;
  };
  (void)detail::face_sums(polygons, tilted_box(), options);
  EXPECT_EQ(total, polygons.size());
  EXPECT_EQ(last, total);
  for (unsigned threads : {1u, 2u}) {
    int calls = 0;
    options.threads = threads;
    options.progress = [&](const Progress&) { return ++calls < 3; };
    try {
      (void)detail::face_sums(polygons, tilted_box(), options);
      ADD_FAILURE() << "not cancelled";
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::cancelled) << e.what();
    }
  }
}

}  // namespace
}  // namespace cvms::test
