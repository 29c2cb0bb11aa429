// SPDX-License-Identifier: MIT
// See piece_geometry.hpp.
#include "piece_geometry.hpp"

#include "polyhedron_access.hpp"

#include <cmath>

namespace cvms::detail {
namespace {

std::vector<ClipPoint> box_corners(const unions::OutwardBox& box) {
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(box.lo[k]) || !std::isfinite(box.hi[k])) return {};
  }
  std::vector<ClipPoint> corners;
  corners.reserve(8);
  for (unsigned i = 0; i < 8; ++i) {
    Vec3 p;
    for (unsigned k = 0; k < 3; ++k) p[static_cast<int>(k)] = Rational(((i >> k) & 1U) != 0 ? box.hi[k] : box.lo[k]);
    const ApproxVec3 approx = ApproxVec3::of(p);  // exact: the coordinates are doubles
    corners.push_back({std::move(p), approx});
  }
  return corners;
}

}  // namespace

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
  g.box_corners = box_corners(g.box);
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
