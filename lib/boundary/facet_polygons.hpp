// SPDX-License-Identifier: MIT
// A solid's boundary cut into few convex polygons, each within one facet:
// the operands of the sums f + B that make the boundary part of A + B when
// B is convex (solid_sum.cpp). Fewer polygons mean fewer pieces in the
// union, so each facet's triangles are merged greedily: a polygon grows by
// a neighbouring triangle of its facet (one sharing an edge with it) as long
// as both corners at that edge stay convex, which keeps it convex (the
// triangle lies beyond the shared edge, so the new corner is strictly
// convex, and the two old ones are tested). A rectangle made of two
// triangles comes back whole; a facet with holes or reflex corners comes
// back as several convex polygons covering it without overlap.
#pragma once

#include <vector>

#include "cvms/solid.hpp"
#include "cvms/vec.hpp"

namespace cvms::detail {

/// Convex polygons with disjoint interiors whose union is the boundary of
/// `solid`, each inside one facet, corners counterclockwise seen from
/// outside (collinear corners may remain). Deterministic.
/// Complexity: O(sum over polygons of k^2) for k triangles in a polygon.
std::vector<std::vector<Vec3>> facet_polygons(const Solid& solid);

}  // namespace cvms::detail
