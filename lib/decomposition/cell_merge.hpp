// SPDX-License-Identifier: MIT
// Greedy merging of interior-disjoint convex cells whose union is convex.
#pragma once

#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/vec.hpp"

namespace cvms::decomposition {

// Six times the exact volume of a convex polyhedron (a fan of signed
// tetrahedra over its counterclockwise facets).
Rational six_volume(const ConvexPolyhedron& polyhedron);

// Convex pieces with the same union as the cells (given by their vertices;
// interior-disjoint), fewer where two of them form a convex body.
// Deterministic: the cells are visited in the order given.
std::vector<ConvexPolyhedron> merge_convex_cells(const std::vector<std::vector<Vec3>>& cells);

}  // namespace cvms::decomposition
