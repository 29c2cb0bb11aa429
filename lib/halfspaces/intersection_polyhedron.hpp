// SPDX-License-Identifier: MIT
// The polyhedron of a bounded full-dimensional intersection of half-spaces
// read off the dual hull (integer_dual_hull.hpp), with no second hull: the
// set is the polar of the dual hull, so its vertices are the dual facets,
// its facets the dual vertices (the irredundant rows) and its edges the dual
// edges. A facet's vertices are the dual facets around its row's dual point,
// in the order of the walk around that point (intersection_polyhedron.cpp
// shows it is counterclockwise from outside); they are pairwise distinct
// dual facets (maximal: no two coplanar facets share an edge), hence
// pairwise distinct vertices of a strictly convex facet. A facet's plane is
// its row's, made primitive.
//
// The order, which the docs of from_halfspaces state: facets in the order of
// their rows (for duplicated rows, the row the dual hull kept), each starting
// at the dual facet whose next corner is the row with the smallest index;
// vertices numbered in order of first use by the facets.
#pragma once

#include "cvms/convex_polyhedron.hpp"
#include "integer_dual_hull.hpp"

namespace cvms::detail {

/// The polyhedron, the same (vertices, oriented facets, exact planes) as
/// convex_hull(v.vertices), in the order stated above.
/// \pre v is the answer of bounded_vertices.
ConvexPolyhedron intersection_polyhedron(DualVertices v);

}  // namespace cvms::detail
