// SPDX-License-Identifier: MIT
// See covering_region.hpp.
#include "covering_region.hpp"

#include <cstddef>
#include <optional>

#include "cvms/rational.hpp"

namespace cvms::detail {

bool covering_region(const PieceGeometry& q_geometry, std::uint32_t q_index, bool q_before_p, const ClipPlane& plane,
                     std::vector<Sign>& sides, SectionScratch& section, std::vector<ClipPlane>& region) {
  region.clear();
  if (!q_geometry.box_corners.empty()) {
    // The corners nearest and farthest in the normal's direction.
    unsigned nearest = 0;
    for (int k = 0; k < 3; ++k) {
      if (sgn((*plane.normal)[k]) < 0) nearest |= 1U << k;
    }
    if (side(q_geometry.box_corners[nearest], plane) == Sign::positive) return false;
    if (side(q_geometry.box_corners[nearest ^ 7U], plane) == Sign::negative) return false;
  }
  if (const std::optional<bool> cuts = walk_section(q_geometry, q_index, plane, section)) {
    if (!*cuts) return false;
    for (const std::uint32_t g : section.facets) region.push_back(q_geometry.planes[g]);
    return true;
  }
  const ConvexPolyhedron& q = *q_geometry.piece;
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
