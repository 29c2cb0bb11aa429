// SPDX-License-Identifier: MIT
// minkowski_sum of convex sets of every dimension, sums of many and
// zonotopes, against the independent oracle (the hull of all pairwise vertex
// sums in the dimension they span, support/set_oracle.hpp) and hand-checked
// results: every pair of dimensions in both orders, the degenerate
// alignments (a polygon parallel to a facet, a segment parallel to an edge
// or a facet, coplanar and parallel polygons, collinear and skew segments),
// far from the origin and with rational coordinates; 2,000+ seeded random
// pairs on a small grid (so that alignments are frequent), every algorithm.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/set_sum.hpp"
#include "cvms/shapes.hpp"
#include "support/hand_solids.hpp"
#include "support/random_sets.hpp"
#include "support/set_oracle.hpp"

namespace cvms {
namespace {

using test::v3;
using Rng = std::mt19937_64;

ConvexSet square(long side, long z = 0) {
  return ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, z), v3(side, 0, z), v3(side, side, z), v3(0, side, z)});
}

ConvexSet box(long x, long y, long z) { return ConvexSet(shapes::box(v3(0, 0, 0), v3(x, y, z))); }

TEST(SetSum, KnownResults) {
  const ConvexSet x = ConvexSet::segment(v3(0, 0, 0), v3(1, 0, 0));
  const ConvexSet y = ConvexSet::segment(v3(0, 0, 0), v3(0, 2, 0));
  const ConvexSet z = ConvexSet::segment(v3(0, 0, 0), v3(0, 0, 3));
  const std::vector<ConvexSet> axes{x, y, z};
  EXPECT_EQ(test::describe_set(minkowski_sum(axes)), test::describe_set(box(1, 2, 3)));
  // Square + perpendicular segment: the box; square + itself: the doubled square.
  EXPECT_EQ(test::describe_set(minkowski_sum(square(2), z)), test::describe_set(box(2, 2, 3)));
  EXPECT_EQ(test::describe_set(minkowski_sum(square(2, 1), square(2, 1))), test::describe_set(square(4, 2)));
  // Parallel segments: a segment; skew ones: a parallelogram.
  const ConvexSet xx = minkowski_sum(x, ConvexSet::segment(v3(5, 5, 5), v3(3, 5, 5)));
  EXPECT_EQ(xx.vertices(), (std::vector<Vec3>{v3(3, 5, 5), v3(6, 5, 5)}));
  EXPECT_EQ(minkowski_sum(x, y).dimension(), 2);
  EXPECT_EQ(minkowski_sum(x, y).num_vertices(), 4u);
  // A point translates, the empty set absorbs.
  EXPECT_EQ(test::describe_set(minkowski_sum(ConvexSet::point(v3(1, 1, 1)), box(1, 1, 1))),
            test::describe_set(ConvexSet(shapes::box(v3(1, 1, 1), v3(2, 2, 2)))));
  EXPECT_TRUE(minkowski_sum(ConvexSet(), box(1, 1, 1)).empty());
  EXPECT_TRUE(minkowski_sum(square(1), ConvexSet()).empty());
  // A sum of nothing is the origin.
  EXPECT_EQ(minkowski_sum(std::vector<ConvexSet>{}).vertices(), std::vector<Vec3>{v3(0, 0, 0)});
}

// Every pair of dimensions, aligned with the cube's facets and edges and not.
TEST(SetSum, EveryPairOfDimensionsWithAlignments) {
  const Vec3 far{Rational(1000000000), Rational(-2000000000), Rational(1, 3)};
  const std::vector<ConvexSet> sets{
      ConvexSet::point(v3(1, -2, 3)),
      ConvexSet::segment(v3(0, 0, 0), v3(1, 0, 0)),                             // parallel to cube edges
      ConvexSet::segment(v3(0, 0, 0), v3(1, 1, 0)),                             // parallel to cube facets
      ConvexSet::segment(v3(0, 0, 0), v3(1, 2, 3)),                             // general
      ConvexSet::segment(far, far + Vec3{Rational(1, 7), 0, Rational(2, 9)}),  // far, rational
      square(1),                                                               // parallel to a cube facet
      square(3, 5).translated(far),
      ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, 0), v3(2, 0, 1), v3(0, 1, 0)}),  // tilted
      ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, 0), v3(1, 1, 0), v3(1, 1, 1), v3(0, 0, 1)}),  // diagonal
      ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, 0), v3(3, 0, 0), v3(3, 1, 0), v3(1, 2, 0)}),
      ConvexSet::polygon(std::vector<Vec3>{{parse_rational("0.1"), 0, parse_rational("-2.5")},  // decimals
                                           {parse_rational("1.7"), parse_rational("0.3"), parse_rational("-2.5")},
                                           {0, parse_rational("1e-3"), parse_rational("-2.5")}}),
      ConvexSet(shapes::cube()),
      ConvexSet(shapes::octahedron()),
      ConvexSet(shapes::prism(5, 2)),
      ConvexSet(shapes::truncated_cube()).translated(far),
  };
  for (std::size_t i = 0; i < sets.size(); ++i)
    for (std::size_t j = i; j < sets.size(); ++j)
      for (Algorithm algorithm : {Algorithm::cvms, Algorithm::essdms, Algorithm::chms}) {
        Options options;
        options.algorithm = algorithm;
        EXPECT_EQ(test::check_set_sum(sets[i], sets[j], options), "") << "sets " << i << " and " << j << ", "
                                                             << to_string(algorithm);
      }
}

TEST(SetSum, RandomPairsAgainstOracle) {
  constexpr std::uint64_t pairs = 2400;
  for (std::uint64_t seed = 0; seed < pairs; ++seed) {
    Rng rng(seed);
    const Vec3 origin_a = seed % 7 == 0 ? Vec3{Rational(1000000000), 0, Rational(-1, 3)} : Vec3{0, 0, 0};
    const ConvexSet a = test::random_set(rng, static_cast<int>(seed % 4), origin_a);
    const ConvexSet b = test::random_set(rng, static_cast<int>((seed / 4) % 4), v3(1, 0, -1));
    Options options;
    options.algorithm = seed % 3 == 0 ? Algorithm::essdms : (seed % 3 == 1 ? Algorithm::cvms : Algorithm::chms);
    ASSERT_EQ(test::check_set_sum(a, b, options), "") << "seed " << seed << " (dimensions " << a.dimension() << " and "
                                             << b.dimension() << ", " << to_string(options.algorithm) << ")";
  }
}

// Bigger polygons (many meridians per arc) in random and axis planes plus
// random hulls, prisms and boxes (facets parallel to the polygon's plane).
TEST(SetSum, BigPolygonsPlusPolyhedra) {
  for (std::uint64_t seed = 0; seed < 60; ++seed) {
    Rng rng(seed);
    std::uniform_int_distribution<int> coordinate(-40, 40), small(-3, 3);
    const Vec3 u = seed % 2 == 0 ? v3(1, 0, 0) : v3(small(rng), small(rng), 1);
    const Vec3 w = seed % 2 == 0 ? v3(0, 1, 0) : v3(1, small(rng), small(rng));
    std::vector<Vec3> points;
    for (int i = 0; i < 60; ++i) points.push_back(Rational(coordinate(rng)) * u + Rational(coordinate(rng)) * w);
    const ConvexSet polygon = convex_hull_set(points);
    if (polygon.dimension() != 2) continue;  // u and w happened to be parallel
    const ConvexSet p = seed % 3 == 0   ? ConvexSet(shapes::prism(7 + static_cast<int>(seed % 5), 3))
                        : seed % 3 == 1 ? ConvexSet(shapes::random_hull(seed, 40, 20))
                                        : box(3, 5, 7);
    ASSERT_EQ(test::check_set_sum(polygon, p), "") << "seed " << seed;
  }
}

TEST(SetSum, ManyOperandsIndependentOfOrder) {
  for (std::uint64_t seed = 0; seed < 60; ++seed) {
    Rng rng(seed);
    std::vector<ConvexSet> operands;
    const int n = 2 + static_cast<int>(seed % 4);
    for (int i = 0; i < n; ++i) operands.push_back(test::random_set(rng, static_cast<int>(rng() % 4), v3(0, 0, 0)));
    ConvexSet oracle = operands[0];
    for (int i = 1; i < n; ++i) {
      const test::SetShape step = test::sum_oracle(oracle, operands[i]);
      oracle = convex_hull_set(std::vector<Vec3>(step.vertices.begin(), step.vertices.end()));
    }
    const test::SetShape expected = test::describe_set(oracle);
    for (int shuffle = 0; shuffle < 3; ++shuffle) {
      std::shuffle(operands.begin(), operands.end(), rng);
      const ConvexSet sum = minkowski_sum(operands);
      ASSERT_EQ(test::check_set_invariants(sum), "") << "seed " << seed;
      ASSERT_EQ(test::describe_set(sum), expected)
          << "seed " << seed << ", shuffle " << shuffle << ": " << test::difference(expected, test::describe_set(sum));
    }
  }
}

std::vector<Vec3> random_generators(Rng& rng, int n) {
  std::uniform_int_distribution<int> coordinate(-1000, 1000);
  std::vector<Vec3> g;
  for (int i = 0; i < n; ++i) g.push_back(v3(coordinate(rng), coordinate(rng), coordinate(rng)));
  return g;
}

TEST(Zonotope, CountsInGeneralPosition) {
  for (int n = 3; n <= 50; ++n) {
    Rng rng(static_cast<std::uint64_t>(n));
    const std::vector<Vec3> g = random_generators(rng, n);
    const ConvexSet z = zonotope(v3(1, 2, 3), g);
    ASSERT_EQ(z.dimension(), 3);
    // In general position the facets are the planes orthogonal to each
    // cross(g_i, g_j), both ways, at offset dot(n, center) + sum |dot(n, g_k)|.
    std::set<test::Plane> planes;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        for (int side : {1, -1}) {
          const Vec3 normal = Rational(side) * primitive_direction(cross(g[i], g[j]));
          Rational offset = dot(normal, v3(1, 2, 3));
          for (const Vec3& gk : g) offset += abs(dot(normal, gk));
          planes.insert({normal, offset});
        }
    EXPECT_EQ(test::describe_set(z).planes, planes) << "n = " << n;
    const ConvexPolyhedron& p = z.polyhedron();
    const auto un = static_cast<std::uint32_t>(n);
    EXPECT_EQ(p.num_vertices(), un * un - un + 2) << "n = " << n;
    EXPECT_EQ(p.num_edges(), 2 * un * (un - 1)) << "n = " << n;
    EXPECT_EQ(p.num_facets(), un * (un - 1)) << "n = " << n;
    if (n <= 12) {  // the invariants cost O(V F) exact checks
      EXPECT_EQ(test::check_set_invariants(z), "") << "n = " << n;
    }
  }
}

// The symmetric four-generator zonotope is the rhombic dodecahedron, checked
// by hand: the sums of +-(1,1,1), +-(1,1,-1), +-(1,-1,1), +-(-1,1,1) reach
// the 8 cube corners (+-2,+-2,+-2) (three generators agree with the corner's
// signs, the fourth cancels one) and the 6 points 4 e_i (two of each sign
// pattern add up along one axis); its 12 rhombi lie on |x_i| + |x_j| = 4.
TEST(Zonotope, SymmetricFourGeneratorsAreTheRhombicDodecahedron) {
  const std::vector<Vec3> g{v3(1, 1, 1), v3(1, 1, -1), v3(1, -1, 1), v3(-1, 1, 1)};
  test::SetShape expected;
  expected.dimension = 3;
  for (int sx : {-2, 2})
    for (int sy : {-2, 2})
      for (int sz : {-2, 2}) expected.vertices.insert(v3(sx, sy, sz));
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {-4, 4}) {
      Vec3 p{0, 0, 0};
      p[axis] = sign;
      expected.vertices.insert(p);
    }
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      for (int si : {-1, 1})
        for (int sj : {-1, 1}) {
          Vec3 n{0, 0, 0};
          n[i] = si;
          n[j] = sj;
          expected.planes.insert({n, Rational(4)});
        }
  const ConvexSet z = zonotope(v3(0, 0, 0), g);
  EXPECT_EQ(test::describe_set(z), expected);
  EXPECT_EQ(z.polyhedron().num_edges(), 24u);
}

// The vertices and facet planes of small zonotopes against the hull of all
// 2^n sign combinations; parallel generators merge; flat ones give zonogons.
TEST(Zonotope, AgainstAllSignCombinations) {
  auto oracle = [](const Vec3& center, const std::vector<Vec3>& g) {
    std::vector<Vec3> corners;
    for (std::uint32_t mask = 0; mask < (1u << g.size()); ++mask) {
      Vec3 p = center;
      for (std::size_t k = 0; k < g.size(); ++k) p += (mask >> k & 1) ? g[k] : -g[k];
      corners.push_back(p);
    }
    return test::hull_oracle(corners);
  };
  Rng rng(15);
  for (int n = 1; n <= 9; ++n) {
    const std::vector<Vec3> g = random_generators(rng, n);
    EXPECT_EQ(test::describe_set(zonotope(v3(0, 0, 0), g)), oracle(v3(0, 0, 0), g)) << "n = " << n;
  }
  const std::vector<Vec3> parallel{v3(1, 0, 0), v3(2, 0, 0), v3(0, 1, 0), v3(0, 0, 1), v3(0, -3, 0)};
  const ConvexSet merged = zonotope(v3(0, 0, 0), parallel);
  EXPECT_EQ(test::describe_set(merged), test::describe_set(ConvexSet(shapes::box(v3(-3, -4, -1), v3(3, 4, 1)))));
  const std::vector<Vec3> flat{v3(1, 0, 0), v3(0, 1, 0), v3(1, 1, 0), v3(1, -2, 0)};
  const ConvexSet zonogon = zonotope(v3(0, 0, 7), flat);
  EXPECT_EQ(zonogon.dimension(), 2);
  EXPECT_EQ(zonogon.num_vertices(), 8u);
  EXPECT_EQ(test::describe_set(zonogon), oracle(v3(0, 0, 7), flat));
  EXPECT_EQ(zonotope(v3(4, 4, 4), std::vector<Vec3>{}).vertices(), std::vector<Vec3>{v3(4, 4, 4)});
  EXPECT_EQ(zonotope(v3(0, 0, 0), std::vector<Vec3>{v3(1, 1, 1), v3(0, 0, 0), v3(-2, -2, -2)}).vertices(),
            (std::vector<Vec3>{v3(-3, -3, -3), v3(3, 3, 3)}));
}

}  // namespace
}  // namespace cvms
