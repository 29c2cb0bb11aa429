// SPDX-License-Identifier: MIT
// See piece_geometry.hpp.
#include "piece_geometry.hpp"

#include "polyhedron_access.hpp"

namespace cvms::detail {

PieceGeometry piece_geometry(const ConvexPolyhedron& piece) {
  PieceGeometry g;
  g.piece = &piece;
  const FacetPlanes& planes = PolyhedronAccess::planes(piece);
  const std::span<const Vec3> normals = planes.exact_normals();
  std::vector<unions::OutwardBox> vertex_boxes;
  vertex_boxes.reserve(piece.num_vertices());
  for (VertexId v : piece.mesh().vertices()) vertex_boxes.push_back(unions::point_box(piece.vertex(v)));
  g.box = vertex_boxes.front();
  for (const unions::OutwardBox& b : vertex_boxes) g.box = unions::merged(g.box, b);
  const Mesh& mesh = piece.mesh();
  g.planes.reserve(piece.num_facets());
  g.corner_start.reserve(piece.num_facets() + 1);
  g.corner_start.push_back(0);
  for (FaceId f : mesh.faces()) {
    const Rational& offset = piece.plane_offset(f);
    g.planes.push_back({&normals[f.index()], &planes.normal_approx[f.index()], &offset, Approx::of(offset)});
    const HalfedgeId first = mesh.halfedge(f);
    unions::OutwardBox box = vertex_boxes[mesh.to(first).index()];
    for (HalfedgeId h : mesh.face_halfedges(f)) {
      g.corners.push_back(mesh.to(h));
      box = unions::merged(box, vertex_boxes[mesh.to(h).index()]);
    }
    g.facet_boxes.push_back(box);
    g.corner_start.push_back(static_cast<std::uint32_t>(g.corners.size()));
  }
  return g;
}

Vec3Ref vertex_ref(const ConvexPolyhedron& piece, VertexId v) {
  return {piece.vertex(v), PolyhedronAccess::vertex_approx(piece, v)};
}

ClipPoint clip_point(const ConvexPolyhedron& piece, VertexId v) {
  return {piece.vertex(v), PolyhedronAccess::vertex_approx(piece, v)};
}

}  // namespace cvms::detail
