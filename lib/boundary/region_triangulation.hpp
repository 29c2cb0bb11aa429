// SPDX-License-Identifier: MIT
// A plane region (an outer loop with holes) cut into triangles whose corners
// are the region's own corners: no new vertex, no zero-area triangle.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "cvms/vec.hpp"
#include "region_loops.hpp"

namespace cvms::detail {

/// Appends the triangles of `region` to `out`, as point indices,
/// counterclockwise. \throw Error(invalid_argument) if the loops do not bound
/// a region (no ear is left).
void triangulate_region(std::span<const Vec2> points, const RegionLoops& region,
                        std::vector<std::array<std::uint32_t, 3>>& out);

}  // namespace cvms::detail
