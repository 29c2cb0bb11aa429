// SPDX-License-Identifier: MIT
// A + B of solids as one solid (see cvms/solid_sum.hpp), by the road with the
// fewest pieces:
//  - both convex: their convex sum;
//  - one convex (say B; the sum commutes): no decomposition. For a point b
//    inside B, A + B = (A + b) u (dA + B) (proof below), and dA + B is the
//    union of f + B over A's boundary cut into convex polygons f
//    (facet_polygons.hpp, face_sums.hpp): convex pieces whose union's
//    boundary comes in fragments as for any union. dA + b lies in the
//    interior of dA + B (b is interior to B), so no point of the boundary of
//    dA + B lies on the boundary of A + b: each fragment (connected) lies
//    wholly in the interior of A + b, where it bounds nothing of the sum and
//    is dropped, or wholly outside A + b, where it is kept; so does a group
//    of fragments joined by shared corners, and one exact locate of a point
//    of the group in A tells which (translate_side.hpp). The pieces'
//    facets proven to lie inside A + B (interior_facets.hpp) give only such
//    dropped fragments, so they are not clipped at all.
//  - neither convex: the pairwise sums of both decompositions, united, the
//    pieces' facets proven inside A + B (interior_facets.hpp) skipped.
// Proof of A + B = (A + b) u (dA + B): let x = a + c with a in A, c in B.
// If x - b is in A, x is in A + b. Otherwise the segment from a (in A) to
// x - b = a + (c - b) (not in A) meets dA at some a' = a + t (c - b),
// t in [0, 1], and x - a' = (1 - t) c + t b lies in B (convex): x is in
// dA + B. Both sets lie in A + B, so the union is all of it.
#include "cvms/solid_sum.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "boundary_assembly.hpp"
#include "boundary_fragments.hpp"
#include "cvms/convex_hull.hpp"
#include "cvms/decomposition.hpp"
#include "cvms/error.hpp"
#include "face_sums.hpp"
#include "facet_polygons.hpp"
#include "interior_facets.hpp"
#include "translate_side.hpp"

namespace cvms {
namespace {

ConvexPolyhedron as_polyhedron(const Solid& convex) {
  const std::vector<Vec3> points(convex.vertices().begin(), convex.vertices().end());
  return convex_hull(points);
}

// A point in B's interior: the centroid of its vertices.
Vec3 interior_point(const ConvexPolyhedron& b) {
  Vec3 sum;
  for (VertexId v : b.mesh().vertices()) sum = sum + b.vertex(v);
  return Rational(Rational(1) / b.num_vertices()) * sum;
}

// The fragments that lie outside A + b, with the planes they use renumbered
// in order.
detail::BoundaryFragments outside(detail::BoundaryFragments all, const Solid& a, const Vec3& b,
                                  const Options& options) {
  const std::vector<char> inside = detail::inside_translate(all, a, b, options);
  detail::BoundaryFragments kept;
  std::vector<std::uint32_t> renumbered(all.planes.size(), UINT32_MAX);
  for (std::size_t i = 0; i < all.fragments.size(); ++i) {
    if (inside[i] != 0) continue;
    detail::BoundaryFragment& fragment = all.fragments[i];
    std::uint32_t& plane = renumbered[fragment.plane];
    if (plane == UINT32_MAX) {
      plane = static_cast<std::uint32_t>(kept.planes.size());
      kept.planes.push_back(all.planes[fragment.plane]);
    }
    fragment.plane = plane;
    kept.fragments.push_back(std::move(fragment));
  }
  return kept;
}

// A + B for A not convex and B convex.
Solid sum_with_convex(const Solid& a, const ConvexPolyhedron& b, const Options& options) {
  const std::vector<std::vector<Vec3>> polygons = detail::facet_polygons(a);
  const std::vector<ConvexPolyhedron> pieces = detail::face_sums(polygons, b, options);
  const Vec3 inside_b = interior_point(b);
  const detail::FacetMask interior =
      detail::interior_facets(polygons, pieces, options, detail::PolygonTiling::of_triangles);
  return detail::assemble_boundary(
      outside(detail::union_boundary_fragments(pieces, options, interior), a, inside_b, options), options);
}

// Each convex piece's vertices.
std::vector<std::vector<Vec3>> vertex_lists(const ConvexUnion& parts) {
  std::vector<std::vector<Vec3>> out;
  out.reserve(parts.size());
  for (const ConvexPolyhedron& part : parts.pieces()) {
    std::vector<Vec3>& vertices = out.emplace_back();
    for (VertexId v : part.mesh().vertices()) vertices.push_back(part.vertex(v));
  }
  return out;
}

// A + B for neither convex: minkowski_sum_pieces (the pairwise sums of the
// two decompositions, in pair order) united, the pieces' facets that the
// decompositions prove inside the sum left out of the candidates.
Solid sum_of_pieces(const Solid& a, const Solid& b, const Options& options,
                    const DecompositionOptions& decomposition) {
  DecompositionOptions heard = decomposition;
  if (!heard.progress) heard.progress = options.progress;  // a caller cancels the whole sum with one callback
  const ConvexUnion a_parts = convex_decomposition(a, heard);
  const ConvexUnion b_parts = convex_decomposition(b, heard);
  const ConvexUnion pieces = minkowski_sum(a_parts, b_parts, options);
  const detail::FacetMask interior =
      detail::interior_facets_of_pairs(vertex_lists(a_parts), vertex_lists(b_parts), pieces.pieces(), options);
  return detail::assemble_boundary(detail::union_boundary_fragments(pieces.pieces(), options, interior), options);
}

}  // namespace

Solid minkowski_sum(const Solid& a, const Solid& b, const Options& options,
                    const DecompositionOptions& decomposition) {
  if (a.triangles().empty())
    throw Error(ErrorCategory::invalid_argument, "minkowski_sum of solids: A is empty");
  if (b.triangles().empty())
    throw Error(ErrorCategory::invalid_argument, "minkowski_sum of solids: B is empty");
  switch (solid_sum_road(a, b)) {
    case SolidSumRoad::convex:
      return Solid::from_polyhedron(minkowski_sum(as_polyhedron(a), as_polyhedron(b), options).polyhedron);
    case SolidSumRoad::faces_with_convex:
      if (b.is_convex()) return sum_with_convex(a, as_polyhedron(b), options);
      return sum_with_convex(b, as_polyhedron(a), options);
    case SolidSumRoad::pieces:
      break;
  }
  return sum_of_pieces(a, b, options, decomposition);
}

}  // namespace cvms
