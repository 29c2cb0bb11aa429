// SPDX-License-Identifier: MIT
// Tests of CHMS (the hull of all pairwise vertex sums) against known sums and
// the brute-force hull of the pairwise sums; also the full convex_hull path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/convex_hull.hpp"
#include "cvms/rational.hpp"
#include "support/oracle.hpp"

namespace cvms {
namespace {

using test::brute_force_hull;
using test::check_invariants;
using test::describe;
using test::difference;
using test::pairwise_sums;
using test::Shape;

Vec3 v(long x, long y, long z) { return {Rational(x), Rational(y), Rational(z)}; }

std::vector<Vec3> signed_permutations(long a, long b, long c) {
  std::set<Vec3> out;
  long base[3] = {a, b, c};
  std::sort(base, base + 3);
  do {
    for (int s = 0; s < 8; ++s)
      out.insert(v(s & 1 ? -base[0] : base[0], s & 2 ? -base[1] : base[1], s & 4 ? -base[2] : base[2]));
  } while (std::next_permutation(base, base + 3));
  return {out.begin(), out.end()};
}

std::vector<Vec3> vertices(const ConvexPolyhedron& p) {
  std::vector<Vec3> out;
  for (VertexId i : p.mesh().vertices()) out.push_back(p.vertex(i));
  return out;
}

const std::vector<Vec3> tetra{v(1, 1, 1), v(1, -1, -1), v(-1, 1, -1), v(-1, -1, 1)};

TEST(ConvexHull, KnownSolidsAreValidPolyhedra) {
  struct Case {
    std::vector<Vec3> pts;
    std::uint32_t v, e, f;
  };
  const Case cases[] = {{tetra, 4, 6, 4},
                        {signed_permutations(1, 1, 1), 8, 12, 6},
                        {signed_permutations(0, 0, 1), 6, 12, 8},
                        {signed_permutations(0, 1, 1), 12, 24, 14},
                        {signed_permutations(0, 1, 2), 24, 36, 14}};
  for (const Case& c : cases) {
    ConvexPolyhedron p = convex_hull(c.pts);
    ASSERT_EQ(check_invariants(p), "");
    EXPECT_EQ(p.num_vertices(), c.v);
    EXPECT_EQ(p.num_edges(), c.e);
    EXPECT_EQ(p.num_facets(), c.f);
    EXPECT_TRUE(p.is_convex());
    Shape expected = brute_force_hull(c.pts);
    EXPECT_TRUE(describe(p) == expected) << difference(expected, describe(p));
  }
}

TEST(ConvexHull, RandomCloudsAreValidPolyhedra) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    std::vector<Vec3> pts;
    const long range = seed % 2 ? 3 : 1000;  // small ranges: many coplanar points
    for (int i = 0; i < 30; ++i)
      pts.push_back(v(static_cast<long>(rng() % (2 * range + 1)) - range,
                      static_cast<long>(rng() % (2 * range + 1)) - range,
                      static_cast<long>(rng() % (2 * range + 1)) - range));
    ConvexPolyhedron p = convex_hull(pts);
    ASSERT_EQ(check_invariants(p), "");
    Shape expected = brute_force_hull(pts);
    EXPECT_TRUE(describe(p) == expected) << difference(expected, describe(p));
  }
}

TEST(ConvexHull, DegenerateInputThrows) {
  std::vector<Vec3> flat;
  for (long i = 0; i < 10; ++i) flat.push_back(v(i, i * i, 0));
  try {
    (void)convex_hull(flat);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::degenerate);
  }
}

// chms(a, b) is a valid polyhedron equal to the brute-force hull of the
// pairwise sums of the vertices.
void expect_chms_matches_brute_force(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  ConvexPolyhedron sum = chms(a, b);
  ASSERT_EQ(check_invariants(sum), "");
  EXPECT_TRUE(sum.is_convex());
  Shape expected = brute_force_hull(pairwise_sums(vertices(a), vertices(b)));
  EXPECT_TRUE(describe(sum) == expected) << difference(expected, describe(sum));
}

TEST(Chms, CubePlusCubeIsTheDoubleCube) {
  ConvexPolyhedron cube = convex_hull(signed_permutations(1, 1, 1));
  ConvexPolyhedron sum = chms(cube, cube);
  ASSERT_EQ(check_invariants(sum), "");
  Shape expected = brute_force_hull(signed_permutations(2, 2, 2));
  EXPECT_TRUE(describe(sum) == expected) << difference(expected, describe(sum));
  EXPECT_EQ(sum.num_vertices(), 8u);
  EXPECT_EQ(sum.num_edges(), 12u);
  EXPECT_EQ(sum.num_facets(), 6u);
}

TEST(Chms, TetrahedronPlusItsReflectionIsACuboctahedron) {
  std::vector<Vec3> minus;
  for (const Vec3& p : tetra) minus.push_back(-p);
  ConvexPolyhedron sum = chms(convex_hull(tetra), convex_hull(minus));
  ASSERT_EQ(check_invariants(sum), "");
  EXPECT_EQ(sum.num_vertices(), 12u);
  EXPECT_EQ(sum.num_edges(), 24u);
  EXPECT_EQ(sum.num_facets(), 14u);
  // The vertices are the differences of distinct tetrahedron vertices:
  // the permutations of (+-2, +-2, 0).
  Shape expected = brute_force_hull(signed_permutations(0, 2, 2));
  EXPECT_TRUE(describe(sum) == expected) << difference(expected, describe(sum));
}

TEST(Chms, CubePlusOctahedron) {
  ConvexPolyhedron cube = convex_hull(signed_permutations(1, 1, 1));
  ConvexPolyhedron octa = convex_hull(signed_permutations(0, 0, 1));
  expect_chms_matches_brute_force(cube, octa);
  ConvexPolyhedron sum = chms(cube, octa);
  // Each cube vertex grows into a triangle (3 octahedron directions), so
  // V = 8 * 3; facets: 6 squares, 8 triangles, and 12 edge facets.
  EXPECT_EQ(sum.num_vertices(), 24u);
  EXPECT_EQ(sum.num_facets(), 26u);
  EXPECT_EQ(sum.num_edges(), 48u);
}

TEST(Chms, RandomPairsMatchBruteForce) {
  int checked = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    auto cloud = [&](int n, long range) {
      std::vector<Vec3> pts;
      for (int i = 0; i < n; ++i)
        pts.push_back(v(static_cast<long>(rng() % (2 * range + 1)) - range,
                        static_cast<long>(rng() % (2 * range + 1)) - range,
                        static_cast<long>(rng() % (2 * range + 1)) - range));
      return pts;
    };
    const long range = seed % 2 ? 2 : 100;
    ConvexPolyhedron a = convex_hull(cloud(7, range));
    ConvexPolyhedron b = convex_hull(cloud(6, range));
    if (a.num_vertices() * b.num_vertices() > 60) continue;  // keep brute force fast
    expect_chms_matches_brute_force(a, b);
    ++checked;
  }
  EXPECT_GE(checked, 8);
}

TEST(Chms, CubePlusRoundedSphereCloud) {
  // Too big for brute force: the sum must be a valid polyhedron whose
  // vertices are pairwise sums and whose facet planes have every pairwise
  // sum on or below them.
  std::mt19937_64 rng(77);
  std::normal_distribution<double> g;
  std::vector<Vec3> pts;
  for (int i = 0; i < 300; ++i) {
    double x = g(rng), y = g(rng), z = g(rng), r = std::sqrt(x * x + y * y + z * z);
    pts.push_back({Rational(x / r), Rational(y / r), Rational(z / r)});
  }
  ConvexPolyhedron sphere = convex_hull(pts);
  ConvexPolyhedron cube = convex_hull(signed_permutations(1, 1, 1));
  ConvexPolyhedron sum = chms(cube, sphere);
  ASSERT_EQ(check_invariants(sum), "");
  auto sums = pairwise_sums(vertices(cube), vertices(sphere));
  std::set<Vec3> all(sums.begin(), sums.end());
  Shape s = describe(sum);
  for (const Vec3& q : s.vertices) EXPECT_TRUE(all.count(q));
  for (const auto& pl : s.planes)
    for (const Vec3& q : sums) ASSERT_LE(dot(pl.normal, q), pl.offset);
  // Each facet of the sum is parallel to a facet of an operand or spanned by
  // an edge of each; the 6 cube directions always appear.
  std::set<Vec3> normals;
  for (const auto& pl : s.planes) normals.insert(pl.normal);
  for (const Vec3& n : signed_permutations(0, 0, 1)) EXPECT_TRUE(normals.count(n));
}

// CHMS hands the hull approximations of the sums and makes exact sums only on
// demand: the result must be the very polyhedron (same vertex order) that
// the hull of the exact pairwise sums gives, also where the approximations
// are inexact (thirds), huge, tiny or infinite (the filters give up) or
// doubles.
TEST(Chms, SameAsHullOfThePairwiseSums) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    // 1e400 is beyond the double range: infinite approximations.
    const Rational scales[] = {Rational(1), Rational(1, 3), parse_rational("1e300"), parse_rational("1e-300"),
                               parse_rational("1e400")};
    const Rational& scale = scales[seed % 5];
    auto cloud = [&](int n) {
      std::vector<Vec3> pts;
      for (int i = 0; i < n; ++i) {
        Vec3 p;
        for (int k = 0; k < 3; ++k)
          p[k] = seed % 8 < 4 ? Rational(static_cast<long>(rng() % 7) - 3) * scale
                              : Rational(std::uniform_real_distribution<double>(-1.0, 1.0)(rng)) * scale;
        pts.push_back(p);
      }
      return pts;
    };
    ConvexPolyhedron a = convex_hull(cloud(40)), b = convex_hull(cloud(30));
    ConvexPolyhedron sum = chms(a, b), hull = convex_hull(pairwise_sums(vertices(a), vertices(b)));
    EXPECT_EQ(vertices(sum), vertices(hull));
    EXPECT_TRUE(describe(sum) == describe(hull)) << difference(describe(hull), describe(sum));
  }
}

}  // namespace
}  // namespace cvms
