// SPDX-License-Identifier: MIT
/// \file
/// A validated convex polyhedron: what every Minkowski-sum algorithm takes and
/// returns. Its facets are maximal (no two adjacent facets are coplanar), every
/// vertex is extreme (no vertex inside a facet or on a straight boundary run),
/// faces are oriented counterclockwise seen from outside, and the volume is
/// positive. Each facet stores its exact outward normal, scaled to a primitive
/// integer vector (so equal directions have equal normals), and the plane offset
/// dot(normal, x) = offset. The library also keeps double approximations of
/// vertices and normals with proven error bounds for its predicate filters;
/// they are private to it (shared by copies, never visible here).
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
#include <memory>
#include <vector>

#include "cvms/mesh.hpp"
#include "cvms/polygon_soup.hpp"
#include "cvms/vec.hpp"

namespace cvms {

/// A convex polyhedron with maximal facets, extreme vertices and cached
/// exact facet planes (see the file comment).
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
  /// The empty polyhedron (no vertices; not a valid operand).
  ConvexPolyhedron();
  ~ConvexPolyhedron();
  /// Copies share the (immutable) connectivity, the internal approximations
  /// and a sum's packed vertices and normals (see Mesh::position); their
  /// other exact values are their own.
  ConvexPolyhedron(const ConvexPolyhedron&);
  /// Moves leave `other` empty.
  ConvexPolyhedron(ConvexPolyhedron&& other) noexcept;
  /// Copy assignment (shares the internal approximations).
  ConvexPolyhedron& operator=(const ConvexPolyhedron&);
  /// Move assignment.
  ConvexPolyhedron& operator=(ConvexPolyhedron&& other) noexcept;

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

  /// The half-edge structure: faces are the facets.
  [[nodiscard]] const Mesh& mesh() const noexcept { return mesh_; }
  /// Number of vertices (all extreme).
  [[nodiscard]] std::uint32_t num_vertices() const noexcept { return mesh_.num_vertices(); }
  /// Number of edges.
  [[nodiscard]] std::uint32_t num_edges() const noexcept { return mesh_.num_edges(); }
  /// Number of facets (maximal).
  [[nodiscard]] std::uint32_t num_facets() const noexcept { return mesh_.num_faces(); }

  /// The exact position of v.
  /// \throw std::bad_alloc only if the polyhedron is a sum's output whose
  ///   vertices are first asked for now (Mesh::position) and memory runs out.
  [[nodiscard]] const Vec3& vertex(VertexId v) const { return mesh_.position(v); }

  /// Exact outward normal of facet f: a primitive integer vector. A
  /// polyhedron made from a mesh or soup finds its planes when one is first
  /// asked for (once, for all facets; safe from concurrent readers), so
  /// that loading and checking alone never pay for them; a sum's output
  /// keeps its normals packed and makes them into Vec3s on the first call.
  /// \throw std::bad_alloc only then, if memory runs out.
  [[nodiscard]] const Vec3& normal(FaceId f) const;
  /// dot(normal(f), x) == plane_offset(f) for every point x of facet f.
  /// Made when one is first asked for (once, for all facets; safe from
  /// concurrent readers), after the normals: the sums and the validation
  /// never read them, so a sum or a load that never asks never pays for them.
  /// \throw std::bad_alloc only then, if memory runs out.
  [[nodiscard]] const Rational& plane_offset(FaceId f) const;

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
  // The library's own access: its constructor from parts whose geometry it
  // has checked or derived, and the approximations and planes its predicates
  // read. Declared here only as a friend, so no user can name it or build an
  // unchecked instance; defined inside the library
  // (lib/mesh/polyhedron_access.hpp).
  friend struct PolyhedronAccess;
  // The approximations, the planes and the arena of the exact values;
  // defined inside the library with PolyhedronAccess.
  struct Impl;

  // Null for an empty instance. Declared first so that the arena it holds
  // outlives every value of mesh_ that points into it.
  std::unique_ptr<Impl> impl_;
  Mesh mesh_;
};

/// Scales a nonzero rational vector by a positive factor to the primitive
/// integer vector of the same direction (gcd of components 1).
Vec3 primitive_direction(const Vec3& v);

}  // namespace cvms
