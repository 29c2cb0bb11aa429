// SPDX-License-Identifier: MIT
// A region with holes made one weakly simple polygon without new vertices:
// each hole joined to the boundary around it by a bridge, a segment between
// two existing corners walked once each way, so that ear clipping
// (region_triangulation.hpp) can cut it into triangles.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cvms/vec.hpp"
#include "region_loops.hpp"

namespace cvms::detail {

/// The region's outer loop with every hole spliced in, as a cyclic list of
/// point indices (a bridge's two ends appear twice). The inside stays on the
/// left. \throw Error(invalid_argument) if a hole cannot be bridged (it is
/// not inside the outer loop, or crosses another loop).
std::vector<std::uint32_t> bridge_holes(std::span<const Vec2> points, const RegionLoops& region);

}  // namespace cvms::detail
