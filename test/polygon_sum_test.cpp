// SPDX-License-Identifier: MIT
// A convex polygon + a convex polyhedron (the sets layer's construction from
// the two Gaussian maps, lib/sets/polygon_sum.cpp), against the independent
// oracle: the exact hull of the pairwise vertex sums (support/set_oracle.hpp),
// with every cached facet normal and offset checked against the facet's own
// corners (check_set_invariants). Seeded random triangles and convex n-gons
// with random polyhedra, and the alignments where the placement of P's
// facets on Q's map meets its degenerate cases: Q's plane parallel to a
// facet of P (a pole facet) or to an edge of P (an arc through a pole), an
// edge of Q parallel to an edge of P (an arc along a meridian) or to a facet
// of P (a facet on a meridian, stretched); decimal coordinates (the word-sized
// paths of the vertex sums and edge directions) and huge ones (the rational
// path); collinear corners dropped or rejected as ConvexSet::polygon does.
#include <gtest/gtest.h>

#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/predicates.hpp"
#include "cvms/rational.hpp"
#include "cvms/set_sum.hpp"
#include "cvms/shapes.hpp"
#include "support/hand_solids.hpp"
#include "support/set_oracle.hpp"

namespace cvms {
namespace {

using test::v3;
using Rng = std::mt19937_64;

// A random convex polygon of up to `corners` corners in the plane through
// `origin` spanned by u and w (not parallel), on a small grid of that plane:
// the hull of random grid points, none if they fall on a line.
std::optional<ConvexSet> random_polygon(Rng& rng, const Vec3& origin, const Vec3& u, const Vec3& w,
                                        int corners) {
  std::uniform_int_distribution<int> coordinate(-4, 4);
  std::vector<Vec3> points;
  for (int i = 0; i < corners; ++i)
    points.push_back(origin + Rational(coordinate(rng)) * u + Rational(coordinate(rng)) * w);
  ConvexSet s = convex_hull_set(points);
  if (s.dimension() != 2) return std::nullopt;
  return s;
}

// Some convex polyhedra: random hulls (general position, small and large
// coordinates), and shapes with parallel facets and edges.
ConvexPolyhedron polyhedron_for(std::uint64_t seed) {
  switch (seed % 5) {
    case 0:
      return shapes::random_hull(seed, 6 + static_cast<int>(seed % 20), 20);
    case 1:
      return shapes::random_hull(seed, 30, 1000);
    case 2:
      return shapes::cube();
    case 3:
      return shapes::prism(3 + static_cast<int>(seed % 6), 2);
    default:
      return shapes::truncated_cube();
  }
}

Vec3 random_vector(Rng& rng) {
  std::uniform_int_distribution<int> small(-3, 3);
  return v3(small(rng), small(rng), small(rng));
}

// The spanning directions of the polygon's plane for a seed: random, or
// aligned with P (a facet normal's plane, an edge direction, both).
std::pair<Vec3, Vec3> plane_directions(Rng& rng, const ConvexPolyhedron& p, std::uint64_t seed) {
  const Mesh& m = p.mesh();
  const FaceId f(static_cast<std::uint32_t>(rng() % m.num_faces()));
  const HalfedgeId h = m.halfedge(f);
  const Vec3 edge = p.vertex(m.to(h)) - p.vertex(m.from(h));
  const Vec3 next = p.vertex(m.to(m.next(h))) - p.vertex(m.to(h));
  switch (seed % 4) {
    case 0:  // parallel to facet f: poles on f, edges of Q parallel to f's
      return {edge, next};
    case 1:  // containing an edge direction of P: Q's edges parallel to it
      return {edge, random_vector(rng)};
    default:
      return {random_vector(rng), random_vector(rng)};
  }
}

TEST(PolygonPlusPolyhedron, RandomPolygonsAgainstTheHullOfPairwiseSums) {
  int checked = 0;
  for (std::uint64_t seed = 0; seed < 400; ++seed) {
    Rng rng(seed);
    const ConvexPolyhedron p = polyhedron_for(seed);
    const auto [u, w] = plane_directions(rng, p, seed);
    if (is_parallel(u, w)) continue;
    const int corners = seed % 3 == 0 ? 3 : 3 + static_cast<int>(rng() % 12);
    const auto q = random_polygon(rng, random_vector(rng), u, w, corners);
    if (!q) continue;
    ASSERT_EQ(test::check_set_sum(*q, ConvexSet(p)), "")
        << "seed " << seed << ", " << q->num_vertices() << " corners";
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

// Decimal coordinates: the corners scaled by 1/1000 and moved by a decimal
// offset, P moved by another (the word-sized sums of one-limb fractions);
// and coordinates beyond 2^64 (the rational fallbacks).
TEST(PolygonPlusPolyhedron, DecimalAndHugeCoordinates) {
  const Vec3 decimal_offset{parse_rational("0.125"), parse_rational("-3.7"), parse_rational("12.34567")};
  const Vec3 huge_offset{Rational("123456789012345678901234567890"), Rational(-7), Rational(1, 3)};
  for (std::uint64_t seed = 0; seed < 120; ++seed) {
    Rng rng(seed);
    const ConvexPolyhedron p = polyhedron_for(seed);
    const auto [u, w] = plane_directions(rng, p, seed);
    if (is_parallel(u, w)) continue;
    const Rational scale = seed % 2 == 0 ? parse_rational("0.001") : Rational(1);
    const auto q =
        random_polygon(rng, random_vector(rng), scale * u, scale * w, 3 + static_cast<int>(seed % 6));
    if (!q) continue;
    const Vec3& offset = seed % 3 == 2 ? huge_offset : decimal_offset;
    ASSERT_EQ(test::check_set_sum(q->translated(offset), ConvexSet(p).translated(-decimal_offset)), "")
        << "seed " << seed;
  }
}

// Hand-checked alignments with the cube [0, 1]^3: the square in a facet's
// plane (poles on two facets), a triangle with an edge along x (arcs along a
// meridian) and one with its plane containing the z axis (arcs through the
// poles), each summed with both orientations of the polygon's corners.
TEST(PolygonPlusPolyhedron, AlignedWithTheCube) {
  const ConvexSet cube(shapes::cube());
  const std::vector<std::vector<Vec3>> polygons{
      {v3(0, 0, 5), v3(2, 0, 5), v3(2, 2, 5), v3(0, 2, 5)},
      {v3(0, 0, 0), v3(3, 0, 0), v3(1, 2, 1)},
      {v3(0, 0, 0), v3(1, 1, 0), v3(0, 0, 1)},
      {v3(0, 0, 0), v3(2, 0, 1), v3(2, 2, 2), v3(0, 2, 1)},
  };
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    std::vector<Vec3> reversed(polygons[i].rbegin(), polygons[i].rend());
    EXPECT_EQ(test::check_set_sum(ConvexSet::polygon(polygons[i]), cube), "") << "polygon " << i;
    EXPECT_EQ(test::check_set_sum(ConvexSet::polygon(reversed), cube), "") << "polygon " << i << " reversed";
  }
  // The square + the unit cube is the box [0, 3] x [0, 3] x [5, 6].
  const ConvexSet box = minkowski_sum(ConvexSet::polygon(polygons[0]), cube);
  EXPECT_EQ(box.num_vertices(), 8u);
  EXPECT_EQ(box.polyhedron().num_facets(), 6u);
}

// Collinear corners: a corner in the middle of an edge is dropped (the sum
// is that of the triangle), corners all on one line are refused.
TEST(PolygonPlusPolyhedron, CollinearCornersAsConvexSetPolygon) {
  const ConvexSet cube(shapes::cube());
  const ConvexSet with_middle =
      ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, 0), v3(1, 1, 1), v3(2, 2, 2), v3(0, 3, 1)});
  const ConvexSet triangle = ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, 0), v3(2, 2, 2), v3(0, 3, 1)});
  EXPECT_EQ(test::describe_set(minkowski_sum(with_middle, cube)),
            test::describe_set(minkowski_sum(triangle, cube)));
  EXPECT_EQ(test::check_set_sum(with_middle, cube), "");
  try {
    (void)ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, 0), v3(1, 1, 1), v3(2, 2, 2)});
    ADD_FAILURE() << "collinear corners accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::degenerate);
  }
}

}  // namespace
}  // namespace cvms
