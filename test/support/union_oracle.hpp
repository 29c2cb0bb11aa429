// SPDX-License-Identifier: MIT
// Brute-force answers for unions of convex pieces, independent of the box
// hierarchy and of side_of_plane: containment by plain Rational arithmetic
// on the facet planes, and intersection and distance as the exact convex
// query on every pair of pieces, in order. Also seeded random unions and
// exact points.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/convex_union.hpp"
#include "cvms/vec.hpp"

namespace cvms::test {

/// Whether some piece has dot(normal, p) <= offset on every facet.
bool union_contains_brute_force(const ConvexUnion& u, const Vec3& p);

/// The first pair (i, j) in order at the minimum exact squared distance
/// over all pairs of pieces (j = 0 for a convex other); the distance is
/// the library's convex one.
struct BruteNearest {
  Rational squared_distance;
  std::size_t piece = 0;
  std::size_t other_piece = 0;
};
BruteNearest nearest_brute_force(const ConvexUnion& u, const ConvexUnion& other);

/// Whether some pair of pieces intersects (the library's convex test).
bool intersects_brute_force(const ConvexUnion& u, const ConvexUnion& other);

/// `count` random hulls of 4..12 integer points, each in a cube of side
/// `size` at a random place in [-spread, spread]^3.
ConvexUnion random_union(std::uint64_t seed, int count, std::int64_t spread = 20, std::int64_t size = 6);

/// A random exact point of [-range, range]^3 with denominators up to 4.
Vec3 random_exact_point(std::mt19937_64& rng, std::int64_t range);

/// Points on the boundary of each piece: its vertices, the midpoints of its
/// edges and the centroids of its facets' vertices.
std::vector<Vec3> boundary_points(const ConvexUnion& u);

/// The vertex set of p, sorted.
std::vector<Vec3> vertex_set(const ConvexPolyhedron& p);

/// The volume of p by the divergence theorem: the signed volumes of the
/// tetrahedra (0, a, b, c) over a fan of each facet, counterclockwise from
/// outside (independent of the library's volumes).
Rational volume_by_tetrahedra(const ConvexPolyhedron& p);

}  // namespace cvms::test
