// SPDX-License-Identifier: MIT
// The polyhedron of a bounded full-dimensional intersection of half-spaces
// from its vertices and the rows tight at each (integer_dual_hull.hpp):
// the exact hull of the vertices, decided on their Cramer numerators
// (homogeneous_hull.hpp), so it is the soup convex_hull builds from the
// rational vertices, and the planes read off the rows instead of recomputed
// from the vertices. A facet's plane is the plane of any row tight at three
// of its corners: three corners of a strictly convex facet are not
// collinear, so only one plane holds them. The facet's row is such a row: a
// facet of the set is an irredundant row, whose dual point is a corner of
// the dual facet of each of the facet's vertices.
#pragma once

#include "cvms/convex_polyhedron.hpp"
#include "integer_dual_hull.hpp"

namespace cvms::detail {

/// The polyhedron, identical to convex_hull(v.vertices).
/// \pre v is the answer of bounded_vertices.
ConvexPolyhedron intersection_polyhedron(const DualVertices& v);

}  // namespace cvms::detail
