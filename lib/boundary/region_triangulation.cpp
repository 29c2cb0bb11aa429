// SPDX-License-Identifier: MIT
// The triangulation of region_triangulation.hpp: the holes bridged to the
// outer loop (hole_bridges.hpp) make one weakly simple polygon, counterclockwise,
// and so does a region that touches itself at a point (its loop passes
// there twice, each passage bounding its own wedge); ear clipping
// (ear_clipping.hpp) cuts it without new vertices.
#include "region_triangulation.hpp"

#include "cvms/error.hpp"
#include "ear_clipping.hpp"
#include "hole_bridges.hpp"

namespace cvms::detail {

void triangulate_region(std::span<const Vec2> points, const RegionLoops& region,
                        std::vector<std::array<std::uint32_t, 3>>& out) {
  EarClipper clipper(points, bridge_holes(points, region), 1);
  if (!clipper.run(out))
    throw Error(ErrorCategory::invalid_argument, "assemble_boundary: a plane region could not be triangulated");
}

}  // namespace cvms::detail
