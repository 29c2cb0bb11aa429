// SPDX-License-Identifier: MIT
// See piece_geometry.hpp.
#include "piece_geometry.hpp"

#include "polyhedron_access.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace cvms::detail {
namespace {

// The box of vertex v from its cached approximation, with no exact
// arithmetic: each coordinate lies within `error` of `value`, and value -
// error and value + error, each rounded to nearest and then stepped one
// double outward, bound that interval (a correctly rounded result r of x
// has x between r's neighbours). Exact coordinates (error 0) give the same
// box as point_box; the others a box a few units in the last place wider,
// which only prunes a little less. An approximation that is not finite
// falls back to point_box.
unions::OutwardBox vertex_box(const ConvexPolyhedron& piece, VertexId v) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  const ApproxVec3& approx = PolyhedronAccess::vertex_approx(piece, v);
  unions::OutwardBox box;
  const std::array<const Approx*, 3> coordinates = {&approx.x, &approx.y, &approx.z};
  for (std::size_t k = 0; k < 3; ++k) {
    const Approx& c = *coordinates[k];
    if (!std::isfinite(c.value) || !std::isfinite(c.error)) return unions::point_box(piece.vertex(v));
    box.lo[k] = c.error == 0 ? c.value : std::nextafter(c.value - c.error, -infinity);
    box.hi[k] = c.error == 0 ? c.value : std::nextafter(c.value + c.error, infinity);
  }
  return box;
}

}  // namespace

PieceGeometry piece_geometry(const ConvexPolyhedron& piece) {
  PieceGeometry g;
  g.piece = &piece;
  const FacetPlanes& planes = PolyhedronAccess::planes(piece);
  const std::span<const Vec3> normals = planes.exact_normals();
  std::vector<unions::OutwardBox> vertex_boxes;
  vertex_boxes.reserve(piece.num_vertices());
  for (VertexId v : piece.mesh().vertices()) vertex_boxes.push_back(vertex_box(piece, v));
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
