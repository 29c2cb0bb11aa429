// SPDX-License-Identifier: MIT
/// \file
/// A closed polyhedral solid that need not be convex: the bounded region
/// enclosed by one or more closed, oriented, non-self-intersecting surfaces.
/// This is what a user's mesh file usually describes (a part, a scan, a
/// robot link), and the operand of the non-convex sums (cvms/decomposition.hpp).
///
/// What the validation accepts: faces that are planar simple polygons, convex
/// or not, with collinear vertices allowed; coplanar neighbouring faces
/// (together they form one facet); several shells, each a closed 2-manifold
/// surface of any genus, where an outer shell faces outward and a cavity (a
/// shell inside another) faces inward, so that the inside is always on the
/// back of every face. Parts of the solid may touch along edges or at points
/// (two cubes sharing an edge or a corner), given with shared indices (an
/// edge on four faces, a vertex whose faces form several fans) or with a
/// point repeated per part, as cvms writes them: the solid is then the
/// regular closed set those faces bound, its boundary split into closed
/// 2-manifold shells by pairing the faces around such an edge in their
/// angular order and giving each fan around a vertex its own vertex (the
/// same point), so vertices() may hold a point more than once.
/// What it rejects, each with a located error (0-based face and vertex
/// indices of the input): an open surface, an edge with an odd number of
/// faces or not as many each way, faces around an edge whose directions do
/// not alternate (topology); inconsistent or inverted orientation
/// (topology); a face that is not planar, not simple or has zero area
/// (degenerate); two faces that intersect other than in a shared edge or
/// vertex (at equal points; topology, naming both faces); zero volume
/// (degenerate).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/io.hpp"
#include "cvms/polygon_soup.hpp"
#include "cvms/vec.hpp"

namespace cvms {

/// Where a point lies with respect to a closed set.
enum class Location {
  outside,   ///< in the complement of the set
  boundary,  ///< on the set's boundary
  inside,    ///< in the set's interior
};

/// A validated closed polyhedral solid (see the file comment). Immutable
/// value type; copies share their data; const member functions may run
/// concurrently. A default-constructed instance is empty (no shells).
///
/// \code
/// cvms::Solid s = cvms::read_solid("bracket.obj");
/// s.volume();                      // exact
/// s.locate(cvms::Vec3{0, 0, 0});   // outside, boundary or inside, exactly
/// \endcode
class Solid {
 public:
  /// The empty solid.
  Solid();
  ~Solid();
  /// Copies share the immutable validated solid (cheap).
  Solid(const Solid&);
  /// Moves leave the source empty.
  Solid(Solid&&) noexcept;
  /// Copies share the immutable validated solid (cheap).
  Solid& operator=(const Solid&);
  /// Moves leave the source empty.
  Solid& operator=(Solid&&) noexcept;

  /// Validates a soup exactly (see the file comment). Points that no face
  /// uses are ignored; equal points with different indices are one vertex,
  /// except where parts touch: one vertex per fan there.
  /// \throw Error(topology), Error(degenerate) naming the faces, edges or
  ///   vertices at fault (0-based, input numbering); Error(limit) if the
  ///   validation would need more memory than the soup's size allows.
  /// Complexity: O(n log n) expected on real meshes (the self-intersection
  ///   test prunes face pairs with a bounding-volume hierarchy).
  static Solid from_soup(PolygonSoup soup);

  /// The polyhedron as a solid (one convex shell; no validation needed).
  static Solid from_polyhedron(const ConvexPolyhedron& polyhedron);

  /// The vertices of the boundary (exact).
  [[nodiscard]] std::span<const Vec3> vertices() const noexcept;
  /// The boundary as triangles of vertex indices, counterclockwise seen from
  /// outside the solid (the inside is on the back). Each facet is
  /// triangulated without new vertices.
  [[nodiscard]] std::span<const std::array<std::uint32_t, 3>> triangles() const noexcept;
  /// The facet of each triangle (same index as triangles()). A facet is a
  /// maximal connected planar region of the boundary; it may be non-convex
  /// and have holes.
  [[nodiscard]] std::span<const std::uint32_t> triangle_facets() const noexcept;
  /// Number of facets.
  [[nodiscard]] std::uint32_t num_facets() const noexcept;
  /// The outward normal of facet f as a primitive integer vector.
  [[nodiscard]] const Vec3& facet_normal(std::uint32_t f) const;
  /// dot(facet_normal(f), x) == facet_offset(f) on facet f.
  [[nodiscard]] const Rational& facet_offset(std::uint32_t f) const;

  /// Number of shells (closed connected boundary surfaces).
  [[nodiscard]] std::uint32_t num_shells() const noexcept;
  /// Number of shells that bound a cavity (facing inward).
  [[nodiscard]] std::uint32_t num_cavities() const noexcept;
  /// Sum of the genera of the shells (0 for a ball, 1 for a torus).
  [[nodiscard]] std::uint32_t genus() const noexcept;
  /// Number of reflex edges: edges where the solid is locally non-convex
  /// (edges inside a facet do not count). Zero exactly for a convex solid.
  [[nodiscard]] std::uint32_t num_reflex_edges() const noexcept;
  /// True when the solid is one convex shell.
  [[nodiscard]] bool is_convex() const noexcept;
  /// The exact volume (positive).
  [[nodiscard]] const Rational& volume() const noexcept;

  /// Where p lies, exactly. O(log n) typical per query after the first,
  /// which builds a bounding-volume hierarchy of the faces (once; safe from
  /// concurrent readers).
  [[nodiscard]] Location locate(const Vec3& p) const;
  /// locate(p) != Location::outside.
  [[nodiscard]] bool contains(const Vec3& p) const { return locate(p) != Location::outside; }

  /// The boundary as a soup of its facets' triangles (vertices() and
  /// triangles()).
  [[nodiscard]] PolygonSoup to_soup() const;

 private:
  // The library's own access to the validated data; defined inside the
  // library, so no user can build an unchecked instance.
  friend struct SolidAccess;
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

/// Reads a mesh file (OFF, OBJ, STL, PLY) and validates it as a solid; every
/// error is prefixed by "<path>: ".
/// \throw Error as read_file and Solid::from_soup.
Solid read_solid(const std::filesystem::path& path, const ReadLimits& limits = {});

}  // namespace cvms
