// SPDX-License-Identifier: MIT
// The side of A + b that translate_side.hpp gives each fragment of the
// boundary of dA + B (one locate per group of fragments sharing corners),
// against brute force: every corner of every fragment and its centroid,
// translated by -b, located exactly in the polycube A by its cubes
// (voxel_contains, which never runs the solid's ray test). No fragment
// meets the boundary of A + b, so a point of A's closed cubes is inside.
// Operands: polycubes with holes and a cavity, random height fields (fixed
// seeds) mapped by a rational rotation for decimal coordinates, each with
// a cube, an octahedron and a random convex polyhedron; one and two
// threads agree.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "boundary_fragments.hpp"
#include "cvms/convex_hull.hpp"
#include "face_sums.hpp"
#include "facet_polygons.hpp"
#include "solid_sum_fixtures.hpp"
#include "translate_side.hpp"

namespace cvms::test {
namespace {

ConvexPolyhedron hull_of(std::vector<Vec3> points) { return convex_hull(points); }

// The hull of random points with coordinates k / 8 in [-1/2, 1/2].
ConvexPolyhedron random_convex(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto coordinate = [&] { return Rational(static_cast<long>(rng() % 9) - 4, 8); };
  std::vector<Vec3> points;
  for (int k = 0; k < 14; ++k) points.push_back({coordinate(), coordinate(), coordinate()});
  return hull_of(points);
}

std::vector<ConvexPolyhedron> convex_operands(std::uint64_t seed) {
  const Rational h(1, 4);
  const Rational r(1, 3);
  return {hull_of({{-h, -h, -h},
                   {h, -h, -h},
                   {-h, h, -h},
                   {h, h, -h},
                   {-h, -h, h},
                   {h, -h, h},
                   {-h, h, h},
                   {h, h, h}}),
          hull_of({{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}}),
          random_convex(seed)};
}

// A point of B's interior: the centroid of its vertices.
Vec3 centroid(const ConvexPolyhedron& b) {
  Vec3 sum;
  for (VertexId v : b.mesh().vertices()) sum = sum + b.vertex(v);
  return Rational(Rational(1) / b.num_vertices()) * sum;
}

// The fragments of the boundary of dA + B for A = m(cubes), each checked
// at its corners and centroid against the cubes; returns how many were
// found inside A + b.
std::size_t expect_sides(const Cubes& cubes, const Mapping& m, const ConvexPolyhedron& b,
                         std::uint64_t seed) {
  SCOPED_TRACE("seed " + std::to_string(seed));
  const Solid a = polycube(cubes, m);
  const std::vector<ConvexPolyhedron> pieces = detail::face_sums(detail::facet_polygons(a), b, {});
  const detail::BoundaryFragments fragments = detail::union_boundary_fragments(pieces, {});
  const Vec3 inside_b = centroid(b);
  const std::vector<char> inside = detail::inside_translate(fragments, a, inside_b, {});
  Options two;
  two.threads = 2;
  EXPECT_EQ(detail::inside_translate(fragments, a, inside_b, two), inside);
  EXPECT_EQ(inside.size(), fragments.fragments.size());
  std::size_t found_inside = 0;
  for (std::size_t f = 0; f < fragments.fragments.size() && f < inside.size(); ++f) {
    const std::vector<Vec3>& corners = fragments.fragments[f].corners;
    std::vector<Vec3> points = corners;
    points.push_back(Rational(Rational(1) / 3) * (corners[0] + corners[1] + corners[2]));
    for (const Vec3& p : points) {
      const bool in_a = voxel_contains(cubes, unmapped(p - inside_b, m));
      EXPECT_EQ(in_a, inside[f] != 0) << "fragment " << f << " at " << text(p);
      if (in_a != (inside[f] != 0)) return found_inside;
    }
    found_inside += inside[f] != 0 ? 1 : 0;
  }
  return found_inside;
}

void expect_all_operands(const Cubes& cubes, const Mapping& m, std::uint64_t seed, bool some_inside) {
  std::size_t found_inside = 0;
  for (const ConvexPolyhedron& b : convex_operands(seed)) found_inside += expect_sides(cubes, m, b, seed);
  if (some_inside) {
    EXPECT_GT(found_inside, 0U);
  }
}

TEST(TranslateSide, PolycubesWithHolesAndCavities) {
  expect_all_operands(l_shape(), {}, 1, true);
  expect_all_operands(frame(4), {}, 2, true);
  expect_all_operands(hollow_cube(4), {}, 3, true);
}

TEST(TranslateSide, RandomPolycubesWithDecimalCoordinates) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed)
    expect_all_operands(random_height_field(seed), decimal_rotation(), seed, false);
}

// Fragments that share a corner share a group; a group's members are joined
// through shared corners only (two squares meeting at one corner: one
// group; a third square apart: its own).
TEST(TranslateSide, CornerGroups) {
  const auto p = [](int x, int y, int z) { return Vec3{Rational(x), Rational(y), Rational(z)}; };
  detail::BoundaryFragments fragments;
  fragments.planes.push_back({p(0, 0, 1), Rational(0)});
  fragments.fragments.push_back({0, {p(0, 0, 0), p(1, 0, 0), p(1, 1, 0), p(0, 1, 0)}});
  fragments.fragments.push_back({0, {p(5, 5, 0), p(6, 5, 0), p(6, 6, 0), p(5, 6, 0)}});
  fragments.fragments.push_back({0, {p(1, 1, 0), p(2, 1, 0), p(2, 2, 0), p(1, 2, 0)}});
  std::uint32_t count = 0;
  EXPECT_EQ(detail::corner_groups(fragments, count), (std::vector<std::uint32_t>{0, 1, 0}));
  EXPECT_EQ(count, 2U);
}

}  // namespace
}  // namespace cvms::test
