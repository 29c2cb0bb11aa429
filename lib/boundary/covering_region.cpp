// SPDX-License-Identifier: MIT
// See covering_region.hpp.
#include "covering_region.hpp"

#include <cstddef>

namespace cvms::detail {

bool covering_region(const PieceGeometry& q_geometry, bool q_before_p, const ClipPlane& plane,
                     std::vector<Sign>& sides, std::vector<ClipPlane>& region) {
  region.clear();
  const ConvexPolyhedron& q = *q_geometry.piece;
  sides.resize(q.num_vertices());
  bool any_outer = false;
  bool any_inner = false;
  std::size_t on_plane = 0;
  for (VertexId v : q.mesh().vertices()) {
    const Sign s = side(vertex_ref(q, v), plane);
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

}  // namespace cvms::detail
