// SPDX-License-Identifier: MIT
// Facets of the pieces f + B (face_sums.hpp) that provably lie inside
// A + B, so that the union's boundary need not clip them: a certificate from
// A's face polygons alone, one exact comparison of dot products per corner
// looked at. The proof is in interior_facets.cpp; skipping such a facet as
// a candidate of union_boundary_fragments never changes the sum, because
// every fragment it would give lies in the interior of A + b, which the sum
// of a solid with a convex set drops (solid_sum.cpp).
#pragma once

#include <span>
#include <vector>

#include "boundary_fragments.hpp"
#include "cvms/convex_polyhedron.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/vec.hpp"

namespace cvms::detail {

/// For each piece k = polygons[k] + B, for each of its facets in face order,
/// nonzero iff the facet's relative interior is proven to lie in the interior
/// of A + B, where the polygons are convex polygons inside A's boundary
/// (face polygons of A, facet_polygons.hpp; they need not meet edge to edge,
/// the certificate is then only found less often). Deterministic; the
/// pieces are shared over options.threads threads.
/// \pre pieces.size() == polygons.size(), pieces[k] == polygons[k] + B for
///   one full-dimensional convex B, every polygon convex with at least three
///   corners.
FacetMask interior_facets(std::span<const std::vector<Vec3>> polygons, std::span<const ConvexPolyhedron> pieces,
                          const Options& options);

}  // namespace cvms::detail
