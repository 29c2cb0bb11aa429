// SPDX-License-Identifier: MIT
// Facets of the pieces of A + B that provably lie inside A + B, so that the
// union's boundary need not clip them: a certificate from the convex parts
// of A the pieces are made of (A's face polygons when B is convex, the
// pieces of A's decomposition otherwise, and then those of B's as well),
// one exact comparison of dot products per corner looked at. With face
// polygons, the inner translate of each polygon Q (the facet Q + G of
// Q + B facing into A, G the face of B least along A's outward normal at
// Q) is interior too, but for finitely many segments: A fills a half-ball
// below almost every point of Q and B rises from G. And when the polygons
// are unions of A's triangles, so is a facet e + B_n at a side e of Q
// where exactly Q and one more polygon meet and the facet's normal n
// points to the front of neither: A then holds every direction from e's
// points along e and n, and B every one along its own face B_n and some
// into B below it. The proofs are in interior_facets.cpp; skipping such a
// facet as a candidate of union_boundary_fragments never changes the sum.
#pragma once

#include <span>
#include <vector>

#include "boundary_fragments.hpp"
#include "cvms/convex_polyhedron.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/vec.hpp"

namespace cvms::detail {

/// How the polygons given to interior_facets cover A's boundary.
enum class PolygonTiling {
  /// Convex polygons with disjoint relative interiors, meeting anyhow.
  convex,
  /// As facet_polygons.hpp makes them: each a union of A's triangles with
  /// every corner of those triangles among its corners. Then a facet at an
  /// edge of A can be certified from the two polygons on that edge.
  of_triangles,
};

/// For each piece k = polygons[k] + B, for each of its facets in face order,
/// nonzero iff the facet's relative interior, but for at most finitely many
/// segments in it, is proven to lie in the interior of A + B (every
/// fragment the facet could give is then dropped), where the polygons are
/// convex polygons covering A's boundary as `tiling` says (they need not
/// meet edge to edge, the certificates are then only found less often).
/// Deterministic; the pieces are shared over options.threads threads.
/// \pre pieces.size() == polygons.size(), pieces[k] == polygons[k] + B for
///   one full-dimensional convex B, every polygon convex with at least three
///   corners, counterclockwise seen from outside A.
FacetMask interior_facets(std::span<const std::vector<Vec3>> polygons, std::span<const ConvexPolyhedron> pieces,
                          const Options& options, PolygonTiling tiling = PolygonTiling::convex);

/// The same for the pieces of A + B from convex decompositions of both:
/// piece k is the sum of the convex hulls of a_parts[k / m] and
/// b_parts[k % m], m = b_parts.size(), each part given by its vertices. A
/// facet is certified from either side, the parts of the other side playing
/// the face polygons' role (interior_facets.cpp); skipping it changes no
/// fragment of the union, since its relative interior lies inside the union.
/// \pre pieces.size() == a_parts.size() * b_parts.size(); the parts of each
///   side are full-dimensional convex sets inside that operand.
FacetMask interior_facets_of_pairs(std::span<const std::vector<Vec3>> a_parts,
                                   std::span<const std::vector<Vec3>> b_parts,
                                   std::span<const ConvexPolyhedron> pieces, const Options& options);

}  // namespace cvms::detail
