// SPDX-License-Identifier: MIT
/// \file
/// A validated convex polyhedron: what every Minkowski-sum algorithm takes and
/// returns. Its facets are maximal (no two adjacent facets are coplanar), every
/// vertex is extreme (no vertex inside a facet or on a straight boundary run),
/// faces are oriented counterclockwise seen from outside, and the volume is
/// positive. Each facet stores its exact outward normal, scaled to a primitive
/// integer vector (so equal directions have equal normals), and the plane offset
/// dot(normal, x) = offset; double approximations of vertices and normals with
/// proven error bounds sit next to them for the predicate filters.
///
/// What construction from a mesh repairs silently: a consistently inward
/// orientation (flipped), coplanar adjacent faces (merged into one facet),
/// vertices inside a facet or on a straight run of its boundary (dropped).
/// What it rejects: mixed orientation, holes, non-manifold parts (topology,
/// from Mesh::from_soup), reflex edges, folds, non-planar or non-convex faces
/// and surfaces that wind around more than once (not_convex), zero-area faces
/// and flat input (degenerate).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cvms/approx.hpp"
#include "cvms/mesh.hpp"
#include "cvms/polygon_soup.hpp"
#include "cvms/vec.hpp"

namespace cvms {

namespace detail {
struct ConvexPolyhedronAccess;  // lib/mesh/trusted_polyhedron.hpp: the algorithms' output path
}  // namespace detail

/// A convex polyhedron with maximal facets, extreme vertices and cached
/// exact and approximate facet planes (see the file comment).
///
/// \pre Accessors taking a handle require a valid handle of mesh() (index
///   below the matching num_*()); this is not checked.
/// A default-constructed instance is empty (no vertices) and is not a valid
/// operand of minkowski_sum. Immutable after construction: const member
/// functions may run concurrently.
///
/// \code
/// cvms::ConvexPolyhedron p = cvms::ConvexPolyhedron::from_soup(cvms::read_file("cube.off"));
/// for (cvms::FaceId f : p.mesh().faces()) {
///   const cvms::Vec3& n = p.normal(f);  // exact, primitive integer
///   // x is inside p  <=>  dot(n, x) <= p.plane_offset(f) for every facet f
/// }
/// \endcode
class ConvexPolyhedron {
 public:
  ConvexPolyhedron() = default;

  /// Checks and normalises a closed mesh: merges coplanar adjacent faces into
  /// maximal facets, drops vertices that are not extreme, flips a globally
  /// inward orientation. Convexity is verified exactly (local convexity at
  /// every edge plus a global winding check; the argument is in
  /// lib/mesh/convex_polyhedron.cpp). Input faces may be any planar convex
  /// polygons, with collinear vertices allowed.
  /// Result numbering: vertices are the extreme input vertices in input
  /// order; facets are ordered by the smallest input face they contain; each
  /// facet's cycle starts at its smallest vertex index.
  /// \throw Error(not_convex) naming the first reflex edge (its two vertex
  ///   indices of the input and its two faces), a fold (zero dihedral angle),
  ///   a non-planar or non-convex face, or a non-convex merged facet;
  /// \throw Error(degenerate) for a flat (zero-volume) input or a zero-area face;
  /// \throw Error(topology) for an empty mesh, several connected components
  ///   or a surface that is not a sphere (Euler characteristic != 2).
  /// Complexity: O(V + E + F) predicates (plus O(n log n) to rebuild the mesh).
  static ConvexPolyhedron from_mesh(const Mesh& mesh);

  /// Mesh::from_soup followed by from_mesh; errors of both.
  static ConvexPolyhedron from_soup(PolygonSoup soup);

  /// Trusted construction from facets that the caller guarantees are maximal,
  /// convex, counterclockwise from outside, with only extreme vertices (used
  /// by the algorithms for their output). Topology is still checked by
  /// Mesh::from_soup; geometry is not rechecked. \pre the guarantee holds.
  /// Normals come from each facet's first corner. Numbering is the soup's.
  static ConvexPolyhedron from_trusted_soup(PolygonSoup soup);

  /// The half-edge structure: faces are the facets.
  [[nodiscard]] const Mesh& mesh() const noexcept { return mesh_; }
  /// Number of vertices (all extreme).
  [[nodiscard]] std::uint32_t num_vertices() const noexcept { return mesh_.num_vertices(); }
  /// Number of edges.
  [[nodiscard]] std::uint32_t num_edges() const noexcept { return mesh_.num_edges(); }
  /// Number of facets (maximal).
  [[nodiscard]] std::uint32_t num_facets() const noexcept { return mesh_.num_faces(); }

  /// The exact position of v.
  [[nodiscard]] const Vec3& vertex(VertexId v) const noexcept { return mesh_.position(v); }
  /// The cached double approximation of vertex(v).
  [[nodiscard]] const ApproxVec3& vertex_approx(VertexId v) const noexcept { return vertex_approx_[v.index()]; }
  /// vertex(v) with its approximation, for the predicates.
  [[nodiscard]] Vec3Ref vertex_ref(VertexId v) const noexcept { return {vertex(v), vertex_approx(v)}; }

  /// Exact outward normal of facet f: a primitive integer vector.
  [[nodiscard]] const Vec3& normal(FaceId f) const noexcept { return normals_[f.index()]; }
  /// The cached double approximation of normal(f).
  [[nodiscard]] const ApproxVec3& normal_approx(FaceId f) const noexcept { return normal_approx_[f.index()]; }
  /// normal(f) with its approximation, for the predicates.
  [[nodiscard]] Vec3Ref normal_ref(FaceId f) const noexcept { return {normal(f), normal_approx(f)}; }
  /// dot(normal(f), x) == plane_offset(f) for every point x of facet f.
  [[nodiscard]] const Rational& plane_offset(FaceId f) const noexcept { return offsets_[f.index()]; }

  /// The direction of the edge of h: vertex(to(h)) - vertex(from(h)).
  [[nodiscard]] Vec3 edge_vector(HalfedgeId h) const;

  /// Re-verifies exactly that the stored data describe a convex polyhedron
  /// with maximal facets and extreme vertices (for tests; O(V F) in the worst case is fine).
  [[nodiscard]] bool is_convex() const;
  /// V - E + F (2 for every valid instance).
  [[nodiscard]] int euler_characteristic() const noexcept;

  /// Vertices and facet cycles as a soup (see Mesh::to_soup).
  [[nodiscard]] PolygonSoup to_soup() const { return mesh_.to_soup(); }

  /// The image under x -> linear * x + offset, vertex and facet numbering
  /// kept. A negative determinant is handled (facet cycles are reversed).
  /// \throw Error(invalid_argument) if det(linear) == 0.
  [[nodiscard]] ConvexPolyhedron transformed(const Mat3& linear, const Vec3& offset) const;
  /// The image under x -> x + offset (same numbering, normals unchanged).
  [[nodiscard]] ConvexPolyhedron translated(const Vec3& offset) const;
  /// -P = {-x : x in P}, for configuration-space obstacles A + (-B).
  [[nodiscard]] ConvexPolyhedron reflected() const;

 private:
  friend struct detail::ConvexPolyhedronAccess;
  void compute_caches();  // normals, offsets, approximations

  Mesh mesh_;
  std::vector<ApproxVec3> vertex_approx_;
  std::vector<Vec3> normals_;
  std::vector<ApproxVec3> normal_approx_;
  std::vector<Rational> offsets_;
};

/// Scales a nonzero rational vector by a positive factor to the primitive
/// integer vector of the same direction (gcd of components 1).
Vec3 primitive_direction(const Vec3& v);

}  // namespace cvms
