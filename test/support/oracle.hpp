// SPDX-License-Identifier: MIT
// Independent exact oracles for tests: brute-force hulls and canonical,
// order-free descriptions of polyhedra that compare as exact rationals.
#pragma once

#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/vec.hpp"

namespace cvms::test {

/// A facet plane dot(normal, x) = offset with normal primitive integer.
struct Plane {
  Vec3 normal;
  Rational offset;
  friend bool operator<(const Plane& a, const Plane& b) {
    if (a.normal != b.normal) return a.normal < b.normal;
    return a.offset < b.offset;
  }
  friend bool operator==(const Plane& a, const Plane& b) { return a.normal == b.normal && a.offset == b.offset; }
};

/// Order-free description: sorted vertex positions and facet planes.
struct Shape {
  std::set<Vec3> vertices;
  std::set<Plane> planes;
  friend bool operator==(const Shape& a, const Shape& b) {
    return a.vertices == b.vertices && a.planes == b.planes;
  }
};

/// The description of a polyhedron, from its stored facets. The planes are
/// recomputed from the facet vertices here (not read from the cache), so a
/// wrong cached normal shows up as a difference.
Shape describe(const ConvexPolyhedron& p);

/// The description of a polygon soup: its points, and for each face the
/// plane of its exact area vector sum(cross(p_i, p_i+1)) (so a clockwise face
/// gives the opposite plane). Faces of zero area are skipped.
Shape describe(const PolygonSoup& soup);

/// Checks a soup meant to be a convex polyhedron with maximal facets: every
/// point used and distinct, every face at least a triangle, planar, strictly
/// convex and counterclockwise from outside, every point on or below every
/// face plane, every directed edge used once and its reverse once, Euler
/// characteristic 2, faces sharing an edge not coplanar.
/// Returns "" when valid, else a message.
std::string check_soup_invariants(const PolygonSoup& soup);

/// The hull of points by brute force, O(n^4): every plane through three
/// points with all points on one side is a facet plane; the extreme points
/// are those that are not in the convex hull of the others. Only for small n.
/// Returns an empty Shape if the points do not span 3D.
Shape brute_force_hull(std::span<const Vec3> points);

/// The pairwise sums {a + b}.
std::vector<Vec3> pairwise_sums(std::span<const Vec3> a, std::span<const Vec3> b);

/// Human-readable difference between two shapes (for test failure messages).
std::string difference(const Shape& expected, const Shape& actual);

/// "(x, y, z)" with exact coordinates (for test failure messages).
std::string to_text(const Vec3& v);

/// Checks every invariant of a ConvexPolyhedron that can be checked
/// independently of the code that built it: mesh.validate(), Euler
/// characteristic 2, every facet planar and convex with all vertices on or
/// below every facet plane, adjacent facets not coplanar, every vertex strictly
/// below some facet plane through... Returns "" when valid, else a message.
std::string check_invariants(const ConvexPolyhedron& p);

}  // namespace cvms::test
