// SPDX-License-Identifier: MIT
// A plane region's boundary edges traced into closed loops, and the loops
// grouped into regions (an outer loop and the holes inside it), in an exact
// chart of the plane: the input of the triangulation (region_triangulation.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "cvms/vec.hpp"

namespace cvms::detail {

/// One connected region: its outer loop, counterclockwise, and its holes,
/// clockwise, as lists of point indices.
struct RegionLoops {
  std::vector<std::uint32_t> outer;
  std::vector<std::vector<std::uint32_t>> holes;
};

/// The regions bounded by `edges` (directed, between indices of `points`,
/// the region on the left; every point has as many edges in as out). Where
/// several edges leave one point (the region touches itself there), a loop
/// arriving there leaves by the first edge clockwise from the one it came
/// by, so that each passage of a loop through the point bounds one wedge of
/// the region. Each hole goes to the smallest outer loop around it.
/// Deterministic: the order of the edges decides the order of the output.
/// \throw Error(invalid_argument) if the edges do not close into loops.
std::vector<RegionLoops> region_loops(std::span<const Vec2> points, std::span<const std::array<std::uint32_t, 2>> edges);

}  // namespace cvms::detail
