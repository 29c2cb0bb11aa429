// SPDX-License-Identifier: MIT
// ConvexSet and its construction: the factories' canonical forms and errors,
// convex_hull_set in every dimension against the independent set oracle
// (exact rank, gift wrapping), and convex_set_from_soup on flat soups.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/shapes.hpp"
#include "support/cpu_time.hpp"
#include "support/hand_solids.hpp"
#include "support/io_expect.hpp"
#include "support/random_numbers.hpp"
#include "support/set_oracle.hpp"

namespace cvms {
namespace {

using test::fraction;
using test::v3;

template <class F>
void expect_error(F&& f, ErrorCategory category, const std::string& word) {
  try {
    f();
    ADD_FAILURE() << "no error, expected " << to_string(category) << " mentioning " << word;
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), category) << e.what();
    EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
  }
}

TEST(ConvexSet, EmptyAndPoint) {
  const ConvexSet empty;
  EXPECT_EQ(empty.dimension(), -1);
  EXPECT_TRUE(empty.empty());
  EXPECT_EQ(empty.num_vertices(), 0u);
  EXPECT_EQ(ConvexSet(ConvexPolyhedron()).dimension(), -1);
  const ConvexSet p = ConvexSet::point(v3(1, 2, 3));
  EXPECT_EQ(p.dimension(), 0);
  EXPECT_EQ(p.vertices(), std::vector<Vec3>{v3(1, 2, 3)});
  EXPECT_EQ(p.translated(v3(1, 1, 1)).vertices(), std::vector<Vec3>{v3(2, 3, 4)});
  EXPECT_EQ(p.reflected().vertices(), std::vector<Vec3>{v3(-1, -2, -3)});
  expect_error([&] { (void)p.polyhedron(); }, ErrorCategory::invalid_argument, "dimension 0");
  expect_error([&] { (void)p.normal(); }, ErrorCategory::invalid_argument, "normal");
}

TEST(ConvexSet, SegmentIsOrdered) {
  const ConvexSet s = ConvexSet::segment(v3(1, 0, 0), v3(0, 5, 0));
  EXPECT_EQ(s.dimension(), 1);
  EXPECT_EQ(s.vertices(), (std::vector<Vec3>{v3(0, 5, 0), v3(1, 0, 0)}));
  EXPECT_EQ(test::check_set_invariants(s), "");
  expect_error([] { (void)ConvexSet::segment(v3(1, 1, 1), v3(1, 1, 1)); }, ErrorCategory::degenerate,
               "both endpoints");
  EXPECT_EQ(s.to_soup().points.size(), 2u);
  EXPECT_EQ(s.to_soup().num_faces(), 0u);
}

TEST(ConvexSet, PolygonIsCanonical) {
  // Clockwise from +z, with a repeated and a collinear vertex: normal +z,
  // counterclockwise, from the smallest vertex, 4 vertices.
  const std::vector<Vec3> cycle{v3(2, 2, 7), v3(2, 0, 7), v3(2, 0, 7), v3(1, 0, 7), v3(0, 0, 7), v3(0, 2, 7)};
  const ConvexSet q = ConvexSet::polygon(cycle);
  EXPECT_EQ(q.dimension(), 2);
  EXPECT_EQ(q.normal(), v3(0, 0, 1));
  EXPECT_EQ(q.plane_offset(), 7);
  EXPECT_EQ(q.vertices(), (std::vector<Vec3>{v3(0, 0, 7), v3(2, 0, 7), v3(2, 2, 7), v3(0, 2, 7)}));
  EXPECT_EQ(test::check_set_invariants(q), "");
  EXPECT_EQ(q.edge_normals()[0], v3(0, -2, 0));
  // A downward-facing normal is made canonical: (0, 0, -3) -> (0, 0, 1); a
  // tilted plane keeps its exact integer normal.
  const ConvexSet t = ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, 0), v3(0, 1, 1), v3(1, 0, 0)});
  EXPECT_EQ(t.normal(), v3(0, 1, -1));
  EXPECT_EQ(test::check_set_invariants(t), "");
  EXPECT_EQ(test::check_set_invariants(t.reflected()), "");
  EXPECT_EQ(test::check_set_invariants(q.translated({Rational(1, 3), 0, Rational(-5, 7)})), "");
  const PolygonSoup soup = q.to_soup();
  ASSERT_EQ(soup.num_faces(), 1u);
  EXPECT_EQ(soup.face(0).size(), 4u);
}

TEST(ConvexSet, PolygonErrors) {
  expect_error([] { (void)ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, 0), v3(1, 0, 0), v3(0, 0, 0)}); },
               ErrorCategory::degenerate, "distinct vertices");
  expect_error([] { (void)ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, 0), v3(1, 0, 0), v3(2, 0, 0)}); },
               ErrorCategory::degenerate, "no area");
  expect_error(
      [] { (void)ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, 0), v3(1, 0, 0), v3(1, 1, 0), v3(0, 1, 1)}); },
      ErrorCategory::not_convex, "not in the plane");
  expect_error(
      [] {
        (void)ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, 0), v3(4, 0, 0), v3(1, 1, 0), v3(0, 4, 0)});
      },
      ErrorCategory::not_convex, "vertex 2 is a reflex corner");
  expect_error(
      [] {
        (void)ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, 0), v3(2, 0, 0), v3(4, 0, 0), v3(3, 0, 0), v3(2, 2, 0)});
      },
      ErrorCategory::not_convex, "spike");
  // A pentagram: every corner turns left, but it winds twice.
  expect_error(
      [] {
        (void)ConvexSet::polygon(std::vector<Vec3>{v3(0, 10, 0), v3(6, -8, 0), v3(-10, 3, 0), v3(10, 3, 0),
                                                   v3(-6, -8, 0)});
      },
      ErrorCategory::not_convex, "winds around 2 times");
  // A bow tie (zero signed area, not collinear) is not
  // convex, as from_mesh says, not degenerate.
  expect_error(
      [] { (void)ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, 0), v3(1, 1, 0), v3(1, 0, 0), v3(0, 1, 0)}); },
      ErrorCategory::not_convex, "zero signed area");
}

// The area of a polygon whose vertices have different denominators, summed in
// one running rational, would be quadratic in the degree (seconds for
// 40,000 vertices). A 20,000-gon on a parabola with a denominator per vertex
// must take well under a second.
TEST(ConvexSet, BigPolygonWithManyDenominatorsIsNotQuadratic) {
  std::vector<Vec3> cycle;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const Rational t = Rational(i) + Rational(1, 1000003 + 2 * i);
    cycle.push_back(Vec3{t, t * t, Rational(0)});
  }
  const auto start = test::cpu_seconds();
  const ConvexSet polygon = ConvexSet::polygon(cycle);
  const double seconds = test::cpu_seconds() - start;
  EXPECT_EQ(polygon.dimension(), 2);
  EXPECT_EQ(polygon.num_vertices(), static_cast<std::size_t>(n));  // the arc closed by its chord
  EXPECT_LT(seconds, 3.0 * test::slow_factor);
}

TEST(ConvexHullSet, EveryDimension) {
  EXPECT_EQ(convex_hull_set(std::vector<Vec3>{}).dimension(), -1);
  const std::vector<Vec3> one{v3(1, 2, 3), v3(1, 2, 3)};
  EXPECT_EQ(convex_hull_set(one).dimension(), 0);
  const std::vector<Vec3> line{v3(1, 1, 1), v3(3, 3, 3), v3(-1, -1, -1), v3(2, 2, 2)};
  const ConvexSet s = convex_hull_set(line);
  EXPECT_EQ(s.vertices(), (std::vector<Vec3>{v3(-1, -1, -1), v3(3, 3, 3)}));
  const std::vector<Vec3> square{v3(0, 0, 0), v3(1, 0, 0), v3(1, 1, 0), v3(0, 1, 0), v3(1, 1, 0),
                                 Vec3{Rational(1, 2), 0, 0}, Vec3{Rational(1, 3), Rational(1, 3), 0}};
  const ConvexSet q = convex_hull_set(square);
  EXPECT_EQ(q.dimension(), 2);
  EXPECT_EQ(q.num_vertices(), 4u);
  // Doubles are taken exactly; a NaN is named.
  const std::vector<std::array<double, 3>> doubles{{0.1, 0, 0}, {0.3, 0, 0}, {0.2, 0, 0}};
  EXPECT_EQ(convex_hull_set(doubles).vertices(), (std::vector<Vec3>{{Rational(0.1), 0, 0}, {Rational(0.3), 0, 0}}));
  const std::vector<std::array<double, 3>> nan{{0, 0, 0}, {0, std::nan(""), 0}};
  expect_error([&] { (void)convex_hull_set(nan); }, ErrorCategory::invalid_argument, "point 1 has a NaN coordinate y");
  const ConvexSet cube = convex_hull_set(shapes::cube().mesh().positions());
  EXPECT_EQ(cube.dimension(), 3);
  EXPECT_EQ(cube.polyhedron().num_facets(), 6u);
}

// Random point sets of every dimension, in random planes and lines (small
// integer bases, so that collinear boundary points are common), with the
// origin near and far (1e9), against the oracle.
TEST(ConvexHullSet, RandomAgainstOracle) {
  for (std::uint64_t seed = 0; seed < 400; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> small(-3, 3);
    const int dimension = static_cast<int>(seed % 4);
    const Vec3 origin = seed % 5 == 0 ? Vec3{Rational(1000000000), Rational(-1000000000, 3), Rational(7)}
                                      : v3(small(rng), small(rng), small(rng));
    Vec3 basis[3];
    for (Vec3& b : basis) b = v3(small(rng), small(rng), small(rng));
    std::vector<Vec3> points;
    const int n = 1 + static_cast<int>(rng() % 12);
    for (int i = 0; i < n; ++i) {
      Vec3 p = origin;
      for (int k = 0; k < dimension; ++k) p += fraction(small(rng), 1 + static_cast<long>(rng() % 2)) * basis[k];
      points.push_back(p);
    }
    const ConvexSet hull = convex_hull_set(points);
    SCOPED_TRACE("seed " + std::to_string(seed));
    EXPECT_EQ(test::check_set_invariants(hull), "");
    const test::SetShape expected = test::hull_oracle(points);
    EXPECT_EQ(test::describe_set(hull), expected) << test::difference(expected, test::describe_set(hull));
  }
}

TEST(ConvexSetFromSoup, FlatSoups) {
  // One face, in any orientation.
  PolygonSoup one = test::make_soup({v3(0, 0, 5), v3(0, 3, 5), v3(3, 3, 5), v3(3, 0, 5)}, {{0, 1, 2, 3}});
  const ConvexSet q = convex_set_from_soup(one);
  EXPECT_EQ(q.dimension(), 2);
  EXPECT_EQ(q.num_vertices(), 4u);
  // The same square as four triangles around its centre (an exporter's
  // triangulation, with one extra point used by no face).
  PolygonSoup fan = test::make_soup(
      {v3(0, 0, 5), v3(3, 0, 5), v3(3, 3, 5), v3(0, 3, 5), {Rational(3, 2), Rational(3, 2), 5}, v3(9, 9, 9)},
      {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
  const ConvexSet tiled = convex_set_from_soup(fan);
  EXPECT_EQ(test::describe_set(tiled), test::describe_set(q));
  // Points only: the hull.
  PolygonSoup points;
  points.points = {v3(0, 0, 0), v3(1, 1, 1), v3(2, 2, 2)};
  EXPECT_EQ(convex_set_from_soup(points).dimension(), 1);
  // A solid: the polyhedron.
  EXPECT_EQ(convex_set_from_soup(test::cube_quads()).dimension(), 3);
}

TEST(ConvexSetFromSoup, FlatErrors) {
  expect_error(
      [] {
        (void)convex_set_from_soup(
            test::make_soup({v3(0, 0, 0), v3(4, 0, 0), v3(1, 1, 0), v3(0, 4, 0)}, {{0, 1, 2, 3}}));
      },
      ErrorCategory::not_convex, "face 0: polygon: vertex 2 is a reflex corner");
  // Three unit squares of an L-shaped (non-convex) region.
  expect_error(
      [] {
        (void)convex_set_from_soup(test::make_soup({v3(0, 0, 0), v3(1, 0, 0), v3(2, 0, 0), v3(2, 1, 0), v3(1, 1, 0),
                                                    v3(0, 1, 0), v3(0, 2, 0), v3(1, 2, 0)},
                                                   {{0, 1, 4, 5}, {1, 2, 3, 4}, {5, 4, 7, 6}}));
      },
      ErrorCategory::not_convex, "the boundary of the faces: polygon: vertex");
  // Two triangles facing opposite ways.
  expect_error(
      [] {
        (void)convex_set_from_soup(
            test::make_soup({v3(0, 0, 0), v3(1, 0, 0), v3(1, 1, 0), v3(0, 1, 0)}, {{0, 1, 2}, {0, 2, 3}, {0, 3, 2}}));
      },
      ErrorCategory::not_convex, "oriented against");
  // Two separate squares: two boundary cycles.
  expect_error(
      [] {
        (void)convex_set_from_soup(test::make_soup(
            {v3(0, 0, 0), v3(1, 0, 0), v3(1, 1, 0), v3(0, 1, 0), v3(5, 0, 0), v3(6, 0, 0), v3(6, 1, 0), v3(5, 1, 0)},
            {{0, 1, 2, 3}, {4, 5, 6, 7}}));
      },
      ErrorCategory::topology, "one cycle");
  expect_error([] { (void)convex_set_from_soup(test::make_soup({v3(0, 0, 0), v3(1, 1, 1), v3(2, 2, 2)}, {{0, 1, 2}})); },
               ErrorCategory::degenerate, "no area");
  // One face that is not planar is named as such, with a vertex off its plane.
  expect_error(
      [] {
        (void)convex_set_from_soup(
            test::make_soup({v3(0, 0, 0), v3(0, 0, 0), v3(1, 0, 0), v3(2, 0, 0), v3(1, 1, 0), v3(1, 1, 1), v3(0, 1, 0)},
                            {{0, 1, 2, 3, 4, 5, 6}}));
      },
      ErrorCategory::not_convex, "face 0 is not planar (vertex 5 is off the plane of vertices 0, 2 and 4)");
  // An open non-flat surface keeps the polyhedron's errors.
  PolygonSoup open = test::cube_quads();
  open.face_offsets.pop_back();
  open.face_indices.resize(open.face_offsets.back());
  EXPECT_THROW((void)convex_set_from_soup(open), Error);
}

}  // namespace
}  // namespace cvms
