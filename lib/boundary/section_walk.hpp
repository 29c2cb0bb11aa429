// SPDX-License-Identifier: MIT
// The facets of a convex piece that a plane cuts through, found by walking
// the piece's surface instead of testing every vertex: climb from a vertex
// along edges towards the plane (each step strictly nearer in the normal's
// direction) until an edge crosses it, then go round the section from face
// to face, each face entered by one crossing edge and left by the other.
// The cost is the section's faces and the climb, not the piece's size.
//
// Why this finds exactly the facets the full test finds (covering_region.hpp:
// corners strictly on both sides): a vertex with no neighbour strictly
// nearer to the plane is extreme in that direction, so if it is still
// strictly on its side the whole piece is. Otherwise the section is a convex
// polygon whose edges lie on the faces crossing the plane, and consecutive
// faces round it share a crossing edge, unless the section passes through a
// vertex on the plane; such a vertex is a corner of a face the walk reaches
// before it, where its zero side is seen and the walk gives up (the caller
// then tests every vertex). The faces are returned sorted, so the result
// does not depend on where the walk started.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "piece_geometry.hpp"
#include "plane_clip.hpp"

namespace cvms::detail {

/// Scratch space of one thread for walk_section, reused from call to call.
struct SectionScratch {
  std::vector<std::int8_t> sides;      // per vertex, valid where stamps == stamp
  std::vector<std::uint32_t> stamps;
  std::uint32_t stamp = 0;
  std::vector<std::uint32_t> start;    // per piece: a vertex next to its last section
  std::vector<std::uint32_t> facets;   // the answer
  std::vector<std::uint32_t> face_stamps;  // per face, for section_through_vertex
  std::uint32_t face_stamp = 0;
  std::vector<HalfedgeId> queue;       // faces to classify, by one of their halfedges
  VertexId met;                        // a vertex on the plane that made the walk give up, if one did
};

/// For piece `piece_index` (q_geometry): false if every vertex is strictly
/// on one side of the plane; true if the plane cuts through it, with the
/// facets that have corners strictly on both sides in scratch.facets, in
/// increasing order; nothing if the walk met a vertex on the plane (then
/// in scratch.met) or gave up otherwise (scratch.met invalid).
std::optional<bool> walk_section(const PieceGeometry& q_geometry, std::uint32_t piece_index, const ClipPlane& plane,
                                 SectionScratch& scratch);

/// For a plane that cuts through the piece last walked (vertices strictly on
/// both sides) and passes through its vertex v: the facets that meet the
/// plane in a segment of positive length (corners strictly on both sides,
/// or two on the plane without the facet lying in it), in increasing order,
/// into scratch.facets; the same set as testing every vertex finds, found
/// from the facets round v outwards.
///
/// Why: the section S (piece ∩ plane) is a convex polygon of positive area
/// whose edges are exactly those segments (an edge of the piece lying in
/// the plane is the segment of both its facets). v, extreme in the piece,
/// is a corner of S, so some facet round v holds a segment. Going round S,
/// consecutive segments meet at a point inside an edge of the piece that
/// crosses the plane strictly (their facets share it) or at a vertex on the
/// plane (their facets lie round it). So from each facet found, crossing
/// the edges whose ends lie strictly on opposite sides and visiting the
/// facets round each corner on the plane reaches every one of them. The
/// cost is the facets along S and round its vertices on the plane.
void section_through_vertex(const PieceGeometry& q_geometry, VertexId v, const ClipPlane& plane,
                            SectionScratch& scratch);

/// The side of vertex v of the piece last walked, for the plane of that
/// walk: remembered if the walk evaluated it, else evaluated and
/// remembered now. For the caller that tests every vertex after the walk
/// gave up, so that no vertex is evaluated twice.
Sign walked_side(SectionScratch& scratch, const ConvexPolyhedron& q, VertexId v, const ClipPlane& plane);

}  // namespace cvms::detail
