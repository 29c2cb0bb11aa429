// SPDX-License-Identifier: MIT
// The inside cells of a binary space partition of the solid's bounding box
// by the solid's own facet planes (an auto-partition): convex, interior-
// disjoint, and together exactly the solid.
#pragma once

#include <cstdint>
#include <vector>

#include "boundary_planes.hpp"
#include "cvms/decomposition.hpp"
#include "cvms/vec.hpp"
#include "progress_reporter.hpp"

namespace cvms::decomposition {

// The vertices of each inside cell, in depth-first order (the part behind a
// splitting plane before the part in front).
// Reports the stage "decomposition: partition" to `progress` after every
// node, and passes `callback` to the hulls of the convexity test.
// \throw Error(limit) when the estimated working memory would exceed
//   limits.max_memory_bytes; Error(cancelled) when the callback asks to stop.
std::vector<std::vector<Vec3>> inside_cells(const Solid& solid, BoundaryPlanes& planes,
                                            const DecompositionLimits& limits,
                                            detail::ProgressReporter& progress, const ProgressCallback& callback);

}  // namespace cvms::decomposition
