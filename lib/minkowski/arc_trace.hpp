// SPDX-License-Identifier: MIT
// Edge facets of CVMS by tracing Gaussian arcs (output-sensitive step 3 of
// paper Section 4.3): the edges of B whose arcs the arc of one edge of A
// properly crosses, found by walking on B instead of testing every facet and
// edge of B. Private to the library.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "plane_filter.hpp"
#include "polyhedron_builder.hpp"

namespace cvms::detail {

/// What trace_edge_facets reuses from edge to edge, one per thread: an
/// exact difference of two vertices made anew would be three heap blocks or
/// more at every edge of A (30 % of a sum's heap blocks on Sphere6 + rotated
/// Sphere6); written into the same rationals, their limbs serve again.
struct ArcTraceScratch {
  std::vector<HalfedgeId> crossed;  ///< the output, see trace_edge_facets
  Vec3 edge_direction;              ///< d_A of the latest edge traced
  /// The extent of the normals' approximations of normals_of, gathered for
  /// the first edge traced against it (the sides' semi-static filter).
  PlaneFilterExtent normals_extent;
  const ConvexPolyhedron* normals_of = nullptr;
};

/// For the edge of halfedge ha of a, whose two facets have the disjoint
/// contributing-vertex lists c1 (face(ha)) and c2 (face(twin(ha))) in b,
/// appends to scratch.crossed every halfedge g of b such that e_A + e_B is an edge
/// facet of A + B, oriented as the paper's search orients it: face(g)
/// strictly visible from d_A = edge_vector(ha), face(twin(g)) strictly
/// invisible, so that the facet's outward normal is cross(d_A, d_g).
/// In the order met along the arc. See lib/minkowski/arc_trace.cpp for the walk and
/// its degenerate cases.
/// \pre c1 and c2 are the exact contributing-vertex lists (non-empty) and
///   are disjoint. Nothing is checked: every ConvexPolyhedron meets the
///   guarantees the walk relies on, since only the checked from_mesh and the
///   library's own builders make one.
/// Cost: O(the degrees of the vertices of b the arc passes) predicates.
void trace_edge_facets(const ConvexPolyhedron& a, HalfedgeId ha, const ConvexPolyhedron& b,
                       std::span<const VertexId> c1, std::span<const VertexId> c2, ArcTraceScratch& scratch,
                       std::uint64_t& steps);

}  // namespace cvms::detail
