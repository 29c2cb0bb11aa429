// SPDX-License-Identifier: MIT
// See covering_region.hpp.
#include "covering_region.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

#include "cvms/rational.hpp"
#include "filtered_predicates.hpp"

namespace cvms::detail {
namespace {

// A facet of Q around vertex v (on the plane) with every corner on the
// plane, if there is one: then the plane is that facet's.
std::optional<FaceId> facet_in_plane(SectionScratch& section, const ConvexPolyhedron& q, VertexId v,
                                     const ClipPlane& plane) {
  const Mesh& mesh = q.mesh();
  for (HalfedgeId out : mesh.outgoing_halfedges(v)) {
    const FaceId g = mesh.face(out);
    bool all_on = true;
    for (HalfedgeId h : mesh.face_halfedges(g)) {
      if (walked_side(section, q, mesh.to(h), plane) != Sign::zero) {
        all_on = false;
        break;
      }
    }
    if (all_on) return g;
  }
  return std::nullopt;
}

// covering_region when the plane h is that of a facet g of Q, found with no
// test of Q's other vertices. Q lies on one side of h, the side of any vertex
// off h; the vertices on h are exactly g's corners (each is a point of
// Q ∩ h = g and extreme in Q, so extreme in g); a facet other than g with
// two corners on h holds the segment between them, a common edge with g,
// and none has three (it would lie in h). So the facets with corners
// strictly on both sides or two or more on h, short of all, are those
// across g's edges: the region the full test finds.
bool region_of_facet_in_plane(const PieceGeometry& q_geometry, FaceId g, bool q_before_p, const ClipPlane& plane,
                              SectionScratch& section, std::vector<ClipPlane>& region) {
  const ConvexPolyhedron& q = *q_geometry.piece;
  const Mesh& mesh = q.mesh();
  // The corner of g's first halfedge has an edge leaving g (every vertex
  // has three or more), which ends off h.
  const VertexId corner = mesh.to(mesh.halfedge(g));
  Sign q_side = Sign::zero;
  for (HalfedgeId out : mesh.outgoing_halfedges(corner)) {
    q_side = walked_side(section, q, mesh.to(out), plane);
    if (q_side != Sign::zero) break;
  }
  // On the inner side, g faces the same way as the facet on h: the piece
  // of smaller index keeps that stretch of boundary.
  if (q_side != Sign::positive && !q_before_p) return false;
  std::vector<std::uint32_t>& across = section.facets;
  across.clear();
  for (HalfedgeId h : mesh.face_halfedges(g)) across.push_back(mesh.face(Mesh::twin(h)).index());
  std::sort(across.begin(), across.end());
  for (const std::uint32_t f : across) region.push_back(q_geometry.planes[f]);
  return true;
}

// Whether Q has vertices strictly on both sides of the plane, decided at
// its vertex v on the plane: Q lies in v + the cone of the edges leaving v
// (the tangent cone of a convex polytope at a vertex is spanned by its
// edges), so a vertex of Q strictly on one side makes some edge leaving v
// go strictly to that side, and v has a neighbour there.
bool crosses_at(SectionScratch& section, const ConvexPolyhedron& q, VertexId v, const ClipPlane& plane) {
  bool outer = false;
  bool inner = false;
  for (HalfedgeId out : q.mesh().outgoing_halfedges(v)) {
    const Sign s = walked_side(section, q, q.mesh().to(out), plane);
    outer = outer || s == Sign::positive;
    inner = inner || s == Sign::negative;
  }
  return outer && inner;
}

}  // namespace

bool covering_region(const PieceGeometry& q_geometry, std::uint32_t q_index, bool q_before_p, const ClipPlane& plane,
                     std::vector<Sign>& sides, SectionScratch& section, std::vector<ClipPlane>& region) {
  region.clear();
  // Q strictly on one side, proven on its box: no vertex of Q is read.
  if (box_strictly_inside(q_geometry.box, plane) || box_strictly_outside(q_geometry.box, plane)) return false;
  if (const std::optional<bool> cuts = walk_section(q_geometry, q_index, plane, section)) {
    if (!*cuts) return false;
    for (const std::uint32_t g : section.facets) region.push_back(q_geometry.planes[g]);
    return true;
  }
  const ConvexPolyhedron& q = *q_geometry.piece;
  if (section.met.is_valid()) {
    if (const std::optional<FaceId> g = facet_in_plane(section, q, section.met, plane))
      return region_of_facet_in_plane(q_geometry, *g, q_before_p, plane, section, region);
    // Q on one side, touching the plane in no facet: in an edge or a
    // vertex, which covers nothing.
    if (!crosses_at(section, q, section.met, plane)) return false;
    section_through_vertex(q_geometry, section.met, plane, section);
    for (const std::uint32_t g : section.facets) region.push_back(q_geometry.planes[g]);
    return true;
  }
  sides.resize(q.num_vertices());
  bool any_outer = false;
  bool any_inner = false;
  std::size_t on_plane = 0;
  for (VertexId v : q.mesh().vertices()) {
    const Sign s = walked_side(section, q, v, plane);
    sides[v.index()] = s;
    any_outer = any_outer || s == Sign::positive;
    any_inner = any_inner || s == Sign::negative;
    on_plane += s == Sign::zero ? 1 : 0;
  }
  const bool crosses = any_outer && any_inner;
  const bool facet_on_plane = !crosses && on_plane >= 3;
  // Q on the outer side (no inner corner) with a facet on h faces the other
  // way; on the inner side it faces the same way.
  if (!crosses && !(facet_on_plane && (any_outer || q_before_p))) return false;
  const std::size_t facets = q_geometry.planes.size();
  for (std::size_t g = 0; g < facets; ++g) {
    bool outer = false;
    bool inner = false;
    std::uint32_t zeros = 0;
    const std::uint32_t begin = q_geometry.corner_start[g];
    const std::uint32_t end = q_geometry.corner_start[g + 1];
    for (std::uint32_t k = begin; k < end; ++k) {
      const Sign s = sides[q_geometry.corners[k].index()];
      outer = outer || s == Sign::positive;
      inner = inner || s == Sign::negative;
      zeros += s == Sign::zero ? 1 : 0;
    }
    if ((outer && inner) || (zeros >= 2 && zeros < end - begin)) region.push_back(q_geometry.planes[g]);
  }
  return true;
}

namespace {

// The box's corner with the greatest dot(normal, x) of its points when
// `sense` is Sign::positive, with the least when it is Sign::negative: per
// coordinate, hi or lo as the normal's coordinate has the sense's sign or
// the other. The signs are read off the normal's approximation, never its
// exact coordinates (one more cache line per plane): a coordinate whose
// approximation does not prove its sign gives nothing, unless it is exactly
// zero (value and error 0), when either end will do.
std::optional<ApproxVec3> extreme_corner(const unions::OutwardBox& box, const ApproxVec3& normal, Sign sense) {
  const Approx* n[3] = {&normal.x, &normal.y, &normal.z};
  ApproxVec3 corner;
  Approx* c[3] = {&corner.x, &corner.y, &corner.z};
  for (std::size_t k = 0; k < 3; ++k) {
    const Approx& nk = *n[k];
    if (!(std::fabs(nk.value) > nk.error) && !(nk.value == 0 && nk.error == 0)) return std::nullopt;
    const bool high = sense == Sign::positive ? nk.value > 0 : nk.value < 0;
    *c[k] = Approx{high ? box.hi[k] : box.lo[k], 0.0};
  }
  return corner;
}

}  // namespace

bool box_strictly_inside(const unions::OutwardBox& box, const ClipPlane& plane) {
  const std::optional<ApproxVec3> corner = extreme_corner(box, *plane.normal_approx, Sign::positive);
  return corner && side_of_plane_if_certain(*corner, *plane.normal_approx, plane.offset_approx) == Sign::negative;
}

bool box_strictly_outside(const unions::OutwardBox& box, const ClipPlane& plane) {
  const std::optional<ApproxVec3> corner = extreme_corner(box, *plane.normal_approx, Sign::negative);
  return corner && side_of_plane_if_certain(*corner, *plane.normal_approx, plane.offset_approx) == Sign::positive;
}

FacetOverlap facet_overlap(const std::vector<ClipPlane>& region, const PieceGeometry& p_geometry,
                           std::uint32_t facet) {
  const ConvexPolyhedron& piece = *p_geometry.piece;
  bool all = true;
  for (const ClipPlane& plane : region) {
    bool outside = false;
    bool inside = false;
    for (std::uint32_t k = p_geometry.corner_start[facet]; k < p_geometry.corner_start[facet + 1]; ++k) {
      const Sign s = side(vertex_ref(piece, p_geometry.corners[k]), plane);
      outside = outside || s == Sign::positive;
      inside = inside || s == Sign::negative;
    }
    if (outside && !inside) return FacetOverlap::none;
    all = all && !outside;
  }
  return all ? FacetOverlap::all : FacetOverlap::part;
}

}  // namespace cvms::detail
