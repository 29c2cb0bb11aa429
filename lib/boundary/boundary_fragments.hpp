// SPDX-License-Identifier: MIT
// The boundary of a union of convex polyhedra as convex polygons on oriented
// planes: each piece's facet minus the parts of it that lie inside the union
// (inside another piece, or against another piece's facet that faces it), a
// facet shared by pieces on the same side kept once (by the first piece).
// What is left is exactly the boundary of the regularised union, as
// interior-disjoint convex polygons; assembling them into one mesh is
// boundary_assembly.hpp's work.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/rational.hpp"
#include "cvms/vec.hpp"

namespace cvms::detail {

/// The plane dot(normal, x) == offset, with the union's inside on the side
/// dot(normal, x) < offset. The normal is a primitive integer vector, so
/// equal oriented planes have equal (normal, offset).
struct OrientedPlane {
  Vec3 normal;
  Rational offset;
};

/// A convex polygon of the boundary on planes[plane]: at least three
/// corners, counterclockwise seen from the side the normal points to, no two
/// corners equal and no three consecutive corners collinear.
struct BoundaryFragment {
  std::uint32_t plane = 0;
  std::vector<Vec3> corners;
};

/// The boundary of a regularised union: distinct oriented planes and the
/// fragments on them, with pairwise disjoint relative interiors; their union
/// is the union's boundary. Two fragments on one plane and facing opposite
/// ways never overlap.
struct BoundaryFragments {
  std::vector<OrientedPlane> planes;
  std::vector<BoundaryFragment> fragments;
};

/// Per piece, per facet in face order: nonzero to leave the facet out of the
/// candidates (see union_boundary_fragments).
using FacetMask = std::vector<std::vector<char>>;

/// The boundary of the union of `pieces` (full-dimensional; they may overlap,
/// touch or share facets). Deterministic: the same pieces in the same order
/// give the same fragments in the same order, whatever options.threads.
/// A facet f of piece p with skip[p][f] nonzero gives no fragments (it still
/// takes its part away from the other pieces' facets): the fragments are
/// those of the other facets. An empty `skip` skips nothing.
/// \throw Error(cancelled) if options.progress returns false.
/// \throw Error(limit) if the corners made would pass
///   options.limits.max_memory_bytes (an estimate per corner).
/// \throw Error(invalid_argument) for an empty piece, or a non-empty `skip`
///   without one entry per piece holding one per facet.
BoundaryFragments union_boundary_fragments(std::span<const ConvexPolyhedron> pieces, const Options& options,
                                           const FacetMask& skip = {});

}  // namespace cvms::detail
