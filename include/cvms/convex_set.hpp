// SPDX-License-Identifier: MIT
/// \file
/// A convex polytope in 3D of any dimension: the empty set, a point, a
/// segment, a convex polygon in its exact plane, or a convex polyhedron with
/// positive volume (a ConvexPolyhedron, unchanged, with all its speed).
///
/// Canonical forms, so that equal sets have equal representations:
///  - a segment keeps its endpoints in lexicographic (x, y, z) order;
///  - a polygon's plane is dot(normal(), x) == plane_offset() with normal()
///    the primitive integer vector whose first nonzero coordinate is
///    positive; its vertices are strictly convex (no collinear ones), listed
///    counterclockwise seen from normal() (from the tip of the normal looking
///    back), starting at the lexicographically smallest.
/// Make them with convex_hull_set (any points) and convex_set_from_soup
/// (cvms/convex_hull.hpp), the factories here, or from a ConvexPolyhedron;
/// sum them with cvms/set_sum.hpp.
#pragma once

#include <span>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/polygon_soup.hpp"
#include "cvms/vec.hpp"

namespace cvms {

/// A convex polytope of dimension -1 (empty) to 3 (see the file comment).
/// Immutable value type; const member functions may run concurrently.
///
/// \code
/// cvms::ConvexSet square = cvms::ConvexSet::polygon(std::vector<cvms::Vec3>{
///     {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
/// square.dimension();  // 2, normal() == (0, 0, 1), plane_offset() == 0
/// \endcode
class ConvexSet {
 public:
  /// The empty set (dimension -1).
  ConvexSet() = default;
  /// The polyhedron as a set of dimension 3; a default-constructed (empty)
  /// polyhedron gives the empty set. Implicit: a polyhedron is a convex set.
  ConvexSet(ConvexPolyhedron polyhedron);  // NOLINT(google-explicit-constructor)

  /// The single point p.
  static ConvexSet point(const Vec3& p);
  /// The segment between a and b (endpoints stored in lexicographic order).
  /// \throw Error(degenerate) if a == b (convex_hull_set takes any points).
  static ConvexSet segment(const Vec3& a, const Vec3& b);
  /// The convex polygon with these vertices in cyclic order, either
  /// orientation. Repeated consecutive vertices and vertices on a straight
  /// run of the boundary are dropped.
  /// \throw Error(degenerate) for fewer than 3 distinct vertices or all of
  ///   them collinear (zero area);
  /// \throw Error(not_convex) naming the input vertex for a vertex off the
  ///   plane of the others, a reflex corner, a backtrack (a spike) or a
  ///   cycle that winds around more than once.
  /// Complexity: O(n) predicates.
  static ConvexSet polygon(std::span<const Vec3> cycle);

  /// -1 for the empty set, 0 point, 1 segment, 2 polygon, 3 polyhedron.
  [[nodiscard]] int dimension() const noexcept { return dimension_; }
  /// True iff this is the empty set.
  [[nodiscard]] bool empty() const noexcept { return dimension_ < 0; }

  /// Number of vertices (0 for the empty set).
  [[nodiscard]] std::size_t num_vertices() const noexcept;
  /// The exact vertices: the point; the two endpoints; the polygon's cycle
  /// (see the file comment); the polyhedron's vertices in its own order.
  [[nodiscard]] std::vector<Vec3> vertices() const;

  /// The polyhedron of a set of dimension 3.
  /// \throw Error(invalid_argument) if dimension() != 3.
  [[nodiscard]] const ConvexPolyhedron& polyhedron() const;
  /// The polygon's primitive integer plane normal (see the file comment).
  /// \throw Error(invalid_argument) if dimension() != 2.
  [[nodiscard]] const Vec3& normal() const;
  /// dot(normal(), x) for every point x of the polygon.
  /// \throw Error(invalid_argument) if dimension() != 2.
  [[nodiscard]] const Rational& plane_offset() const;
  /// The polygon's edges' outward normals within its plane: entry i is
  /// cross(v[i+1] - v[i], normal()) for the edge from vertex i to vertex
  /// i + 1 (cyclically); not normalised.
  /// \throw Error(invalid_argument) if dimension() != 2.
  [[nodiscard]] std::vector<Vec3> edge_normals() const;

  /// The image under x -> x + offset.
  [[nodiscard]] ConvexSet translated(const Vec3& offset) const;
  /// -S = {-x : x in S}.
  [[nodiscard]] ConvexSet reflected() const;

  /// The set as a soup: a polyhedron's facets; a polygon as one face
  /// (counterclockwise seen from normal()); a segment or a point as its
  /// points with no face; nothing for the empty set.
  [[nodiscard]] PolygonSoup to_soup() const;

 private:
  int dimension_ = -1;
  ConvexPolyhedron polyhedron_;  // dimension 3
  std::vector<Vec3> vertices_;   // dimensions 0 to 2
  Vec3 normal_;                  // dimension 2
  Rational offset_;              // dimension 2
};

}  // namespace cvms
