// SPDX-License-Identifier: MIT
// SumLimits for the sums of convex sets (output size quadratic in the input,
// for the constructions of lib/sets/): a 100,000-gon plus a 10,000-gon prism (about 5 x 10^8
// facets) or a zonotope of 100,000 generators (about 10^10) must be refused
// with Error(limit) from counts made before the output is built, quickly;
// a sum within the limits is unaffected. The counts are exact where the
// construction is (polygon + polyhedron, segment + polyhedron without
// coplanar parallelograms, zonotopes in general position): a limit of
// exactly the result's facets admits it, one less refuses it. Small limits
// in Options keep the tests fast; the attack inputs are made here.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/set_sum.hpp"
#include "cvms/shapes.hpp"
#include "support/cpu_time.hpp"
#include "support/hand_solids.hpp"
#include "support/set_oracle.hpp"

namespace cvms {
namespace {

using test::v3;

Options facet_limit(std::uint64_t facets) {
  Options options;
  options.limits.max_output_facets = facets;
  return options;
}

// The message of the Error(limit) that `sum` throws, or a failure.
template <class Sum>
std::string limit_message(Sum sum) {
  try {
    (void)sum();
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::limit) << e.what();
    return e.message();
  }
  ADD_FAILURE() << "no limit error";
  return {};
}

// The polygon circle_polygon(n) in the plane y = y0 (normal along y).
ConvexSet upright_polygon(int n, long y0 = 0) {
  std::vector<Vec3> cycle;
  for (const Vec2& p : shapes::circle_polygon(n)) cycle.push_back(Vec3{p.x, Rational(y0), p.y});
  return ConvexSet::polygon(cycle);
}

// The n-gon (k, 0, k^2), k = 0..n-1, in the plane y = 0: integer vertices
// (circle_polygon's rationals with n different denominators make
// ConvexSet::polygon's area vector quadratic in n: a minute for 100,000).
ConvexSet parabola_polygon(long n) {
  std::vector<Vec3> cycle;
  for (long k = 0; k < n; ++k) cycle.push_back(v3(k, 0, k * k));
  return ConvexSet::polygon(cycle);
}

// circle_polygon(n) in the plane z = 0.
ConvexSet flat_polygon(int n) {
  std::vector<Vec3> cycle;
  for (const Vec2& p : shapes::circle_polygon(n)) cycle.push_back(Vec3{p.x, p.y, Rational(0)});
  return ConvexSet::polygon(cycle);
}

// circle_polygon(n) mapped into a generic plane by an injective linear map.
ConvexSet tilted_polygon(int n) {
  std::vector<Vec3> cycle;
  for (const Vec2& p : shapes::circle_polygon(n)) cycle.push_back(Vec3{p.x * 3, p.y * 2 + p.x, p.x - p.y});
  return ConvexSet::polygon(cycle);
}

// The limit at exactly the result's facet count admits the sum (and it is
// the oracle's); one less refuses it.
void expect_exact_count(const ConvexSet& a, const ConvexSet& b, const std::string& context) {
  SCOPED_TRACE(context);
  const ConvexSet sum = minkowski_sum(a, b);
  ASSERT_EQ(sum.dimension(), 3);
  const std::uint64_t facets = sum.polyhedron().num_facets();
  EXPECT_EQ(test::check_set_sum(a, b, facet_limit(facets)), "");
  const std::string message = limit_message([&] { return minkowski_sum(a, b, facet_limit(facets - 1)); });
  EXPECT_NE(message.find("has " + std::to_string(facets) + " facets"), std::string::npos) << message;
  EXPECT_NE(message.find("SumLimits::max_output_facets"), std::string::npos) << message;
}

TEST(SetSumLimits, PolygonPlusPolyhedronIsCountedExactly) {
  for (int seed = 1; seed <= 12; ++seed) {
    const ConvexPolyhedron p = shapes::random_hull(static_cast<std::uint64_t>(seed), 20 + 5 * seed, 50);
    expect_exact_count(upright_polygon(7 + seed), ConvexSet(p), "upright, seed " + std::to_string(seed));
    expect_exact_count(tilted_polygon(5 + 3 * seed), ConvexSet(p), "tilted, seed " + std::to_string(seed));
  }
  // Facets on meridians and arcs ending at them: a prism and a box.
  expect_exact_count(upright_polygon(12), ConvexSet(shapes::prism(12, 2)), "prism");
  expect_exact_count(upright_polygon(8), ConvexSet(shapes::box(v3(0, 0, 0), v3(1, 2, 3))), "box");
}

TEST(SetSumLimits, SegmentPlusPolyhedronIsCountedExactly) {
  for (int seed = 1; seed <= 12; ++seed) {
    const ConvexPolyhedron p = shapes::random_hull(static_cast<std::uint64_t>(seed), 30, 50);
    const ConvexSet s = ConvexSet::segment(v3(0, 0, 0), v3(7, 3 + seed, 101));
    SCOPED_TRACE(seed);
    const std::uint64_t facets = minkowski_sum(s, ConvexSet(p)).polyhedron().num_facets();
    EXPECT_EQ(test::check_set_sum(s, ConvexSet(p), facet_limit(facets)), "");
    const std::string message = limit_message([&] { return minkowski_sum(s, ConvexSet(p), facet_limit(facets - 1)); });
    EXPECT_NE(message.find("segment + polyhedron"), std::string::npos) << message;
  }
}

TEST(SetSumLimits, SegmentPlusPolygonAndPolygonPlusPolygon) {
  const ConvexSet q = upright_polygon(40);
  const ConvexSet s = ConvexSet::segment(v3(0, 0, 0), v3(0, 1, 0));
  EXPECT_EQ(test::check_set_sum(s, q, facet_limit(42)), "");
  EXPECT_NE(limit_message([&] { return minkowski_sum(s, q, facet_limit(41)); }).find("segment + polygon"),
            std::string::npos);
  // Polygons in non-parallel planes: the count is that of the polygon plus
  // the other's prism, at least the sum's facets.
  const ConvexSet flat = flat_polygon(30);
  const std::uint64_t facets = minkowski_sum(q, flat).polyhedron().num_facets();
  EXPECT_EQ(test::check_set_sum(q, flat, facet_limit(facets + 40 + 30)), "");
  const std::string message = limit_message([&] { return minkowski_sum(q, flat, facet_limit(facets - 1)); });
  EXPECT_NE(message.find("polygon + polygon"), std::string::npos) << message;
}

// The finding itself: a 100,000-gon plus a 10,000-gon prism whose axis is
// in the polygon's plane, about 5 x 10^8 facets (500 GB at 1 KB a facet),
// refused under the default limits after two binary searches per edge.
TEST(SetSumLimits, HugePolygonPlusPrismIsRefusedAtOnce) {
  const ConvexSet polygon = parabola_polygon(100000);
  const ConvexSet prism(shapes::prism(10000, 2));
  const auto start = test::cpu_seconds();
  const std::string message = limit_message([&] { return minkowski_sum(polygon, prism); });
  const double seconds = test::cpu_seconds() - start;
  EXPECT_NE(message.find("SumLimits::max_memory_bytes"), std::string::npos) << message;
  EXPECT_LT(seconds, 5.0) << message;
  // Through a sum of many, and with the prism flattened to its base polygon.
  const std::vector<ConvexSet> three{polygon, prism, ConvexSet::point(v3(1, 2, 3))};
  EXPECT_NE(limit_message([&] { return minkowski_sum(three); }).find("polygon + polyhedron"), std::string::npos);
  const ConvexSet base = flat_polygon(10000);
  EXPECT_NE(limit_message([&] { return minkowski_sum(polygon, base); }).find("polygon + polygon"), std::string::npos);

}

TEST(SetSumLimits, ZonotopeIsBoundedBeforeAnySum) {
  // General position: exactly n (n - 1) facets.
  const std::vector<Vec3> g = shapes::random_points(7, 12);
  ASSERT_EQ(zonotope(v3(0, 0, 0), g).polyhedron().num_facets(), 132u);
  SumLimits limits;
  limits.max_output_facets = 132;
  EXPECT_EQ(zonotope(v3(0, 0, 0), g, limits).polyhedron().num_facets(), 132u);
  limits.max_output_facets = 131;
  std::string message = limit_message([&] { return zonotope(v3(0, 0, 0), g, limits); });
  EXPECT_NE(message.find("zonotope of 12 segments in 12 directions): the sum has up to 132 facets"),
            std::string::npos)
      << message;
  // Parallel generators are one direction: 2,100 of them in 3 directions
  // are a box, not 4 x 10^6 facets.
  std::vector<Vec3> parallel;
  for (long k = 1; k <= 700; ++k)
    for (const Vec3& d : {v3(k, 0, 0), v3(0, -k, 0), v3(0, 0, 2 * k)}) parallel.push_back(d);
  limits.max_output_facets = 6;
  EXPECT_EQ(zonotope(v3(0, 0, 0), parallel, limits).polyhedron().num_facets(), 6u);
  // The CLI's largest: 100,000 generators, about 10^10 facets, refused at once.
  const std::vector<Vec3> many = shapes::random_points(1, 100000);
  const auto start = test::cpu_seconds();
  message = limit_message([&] { return zonotope(v3(0, 0, 0), many); });
  const double seconds = test::cpu_seconds() - start;
  EXPECT_NE(message.find("SumLimits::max_memory_bytes"), std::string::npos) << message;
  EXPECT_LT(seconds, 5.0) << message;
}

}  // namespace
}  // namespace cvms
