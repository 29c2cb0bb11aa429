// SPDX-License-Identifier: MIT
// Greedy merging of interior-disjoint convex cells whose union is convex.
#pragma once

#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/vec.hpp"
#include "progress_reporter.hpp"

namespace cvms::decomposition {

// Six times the exact volume of a convex polyhedron (a fan of signed
// tetrahedra over its counterclockwise facets).
Rational six_volume(const ConvexPolyhedron& polyhedron);

// Convex pieces with the same union as the cells (given by their vertices;
// interior-disjoint), fewer where two of them form a convex body.
// Deterministic: the cells are visited in the order given.
// Reports the stage "decomposition: merge" (units: two per cell) to `progress`.
// \throw Error(cancelled) when progress's callback asks to stop.
std::vector<ConvexPolyhedron> merge_convex_cells(const std::vector<std::vector<Vec3>>& cells,
                                                 detail::ProgressReporter& progress);

}  // namespace cvms::decomposition
