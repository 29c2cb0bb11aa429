// SPDX-License-Identifier: MIT
// What the union's boundary reads of each piece, gathered once before the
// pieces are shared among threads: the facets' planes as cutting planes
// (exact integer normal and offset, with their approximations), the facets'
// corner cycles, and outward-rounded boxes of the piece and of each facet,
// read off the vertices' cached approximations,
// for the box hierarchy and for sides of planes proven on a whole box
// (covering_region.hpp: box_strictly_inside, box_strictly_outside).
#pragma once

#include <cstdint>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "outward_box.hpp"
#include "plane_clip.hpp"

namespace cvms::detail {

struct PieceGeometry {
  const ConvexPolyhedron* piece = nullptr;
  /// One per facet: dot(normal, x) <= offset holds on the piece.
  std::vector<ClipPlane> planes;
  /// Facet f's corners are corners[corner_start[f] .. corner_start[f + 1]),
  /// counterclockwise seen from outside.
  std::vector<std::uint32_t> corner_start;
  std::vector<VertexId> corners;
  std::vector<unions::OutwardBox> facet_boxes;
  unions::OutwardBox box;
};

/// The geometry of a non-empty piece, which must outlive it.
PieceGeometry piece_geometry(const ConvexPolyhedron& piece);

/// Corner v of the piece with its cached approximation.
Vec3Ref vertex_ref(const ConvexPolyhedron& piece, VertexId v);

/// Corner v of the piece as a clip point.
ClipPoint clip_point(const ConvexPolyhedron& piece, VertexId v);

}  // namespace cvms::detail
