// SPDX-License-Identifier: MIT
/// \file
/// The paper's benchmark shapes and other generators, all exact.
#pragma once

#include <cstdint>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/vec.hpp"

/// The paper's benchmark shapes and other generators, all exact.
namespace cvms::shapes {

/// Regular tetrahedron with vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1).
ConvexPolyhedron tetrahedron();
/// The cube [-1, 1]^3 (6 facets).
ConvexPolyhedron cube();
/// The octahedron |x|+|y|+|z| <= 1 (the paper's "Hedra", 8 facets).
ConvexPolyhedron octahedron();
/// The cube [-1,1]^3 with each corner cut at 1/3 of the edge length, i.e.
/// by the planes +-x +-y +-z = 7/3 (14 facets: 6 octagons, 8 triangles;
/// vertices the permutations of (+-1/3, +-1, +-1)). Exact rational
/// coordinates; the octagons are not regular (that needs sqrt(2)).
ConvexPolyhedron truncated_cube();
/// The paper's Sphere_k: an icosahedron subdivided k-1 times (k = 1..8 gives
/// 20 * 4^(k-1) triangles before rounding), vertices projected to the unit
/// sphere and rounded to double; the exact hull of those rounded points (so
/// facets may be merged and counts may differ slightly from 20 * 4^(k-1)).
/// \throw Error(invalid_argument) for k outside 1..9.
ConvexPolyhedron geodesic_sphere(int k);
/// As geodesic_sphere but built from an icosahedron rotated by a fixed
/// generic rotation before subdividing (rounded to double), so that its
/// Gaussian map is in general position with respect to geodesic_sphere's.
ConvexPolyhedron rotated_geodesic_sphere(int k);
/// The points of geodesic_sphere(k) before the hull (rounded to double).
std::vector<Vec3> geodesic_sphere_points(int k, bool rotated = false);
/// Axis-aligned box [lo, hi]. \throw Error(degenerate) unless lo < hi in every axis.
ConvexPolyhedron box(const Vec3& lo, const Vec3& hi);
/// A right prism over a regular-ish convex n-gon (exact rational vertices on
/// a circle from Pythagorean parametrisation) with the given height, n >= 3.
/// The base is circle_polygon(n) in the planes z = -height/2 and z = height/2.
/// \throw Error(invalid_argument) for n outside 3..1000000 or height <= 0.
ConvexPolyhedron prism(int n, const Rational& height);
/// n distinct points exactly on the unit circle, counterclockwise, at angles
/// close to -pi + 2 pi (i + 1/2) / n (so a strictly convex, nearly regular
/// n-gon): ((1-t^2)/(1+t^2), 2t/(1+t^2)) for rational t = p / (4n).
/// Platform-independent. \throw Error(invalid_argument) for n outside 3..1000000.
std::vector<Vec2> circle_polygon(int n);
/// The hull of n seeded random points (integer coordinates in [-range, range],
/// drawn from std::mt19937_64(seed) by a platform-independent rejection
/// sampling). If the n points do not span 3D, further points are drawn until
/// they do. \throw Error(invalid_argument) for n outside 4..10000000 or range
/// outside 1..2^62.
ConvexPolyhedron random_hull(std::uint64_t seed, int n, std::int64_t range = 1000);
/// The points random_hull(seed, n, range) takes the hull of.
std::vector<Vec3> random_points(std::uint64_t seed, int n, std::int64_t range = 1000);
/// The rotation matrix of the rational quaternion (a, b, c, d), exact:
/// entries have denominator a^2+b^2+c^2+d^2. \throw Error(invalid_argument) for 0.
Mat3 rational_rotation(std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d);
/// diag(sx, sy, sz), for ConvexPolyhedron::transformed.
/// \throw Error(invalid_argument) if a factor is 0.
Mat3 scaling(const Rational& sx, const Rational& sy, const Rational& sz);

}  // namespace cvms::shapes
