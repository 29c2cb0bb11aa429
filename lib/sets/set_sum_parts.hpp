// SPDX-License-Identifier: MIT
// The direct constructions behind minkowski_sum of convex sets (set_sum.cpp
// dispatches), one file each: planar_set_sum.cpp, segment_sum.cpp,
// polygon_sum.cpp, sweep_sum.cpp.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "cvms/convex_set.hpp"
#include "output_budget.hpp"

namespace cvms::detail {

/// A + B for point lists that are each a point, a segment or a polygon
/// counterclockwise seen from `normal`, all in planes orthogonal to it.
ConvexSet coplanar_sum(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const Vec3& normal);

/// The facet f of P plus the segment [from, to] parallel to its plane, as
/// (corner of f, 0 for `from` or 1 for `to`) pairs counterclockwise from f's
/// outward normal. \pre dot(normal(f), to - from) == 0.
std::vector<std::pair<VertexId, std::uint32_t>> stretched_facet(const ConvexPolyhedron& p, FaceId f, const Vec3& from,
                                                                const Vec3& to);

/// [start, start + direction] + P, from P's facets split by the sign of
/// dot(normal, direction) and its silhouette edges. \pre direction != 0.
/// \throw Error(limit) if its facets, counted first, exceed `budget`.
ConvexSet segment_polyhedron_sum(const Vec3& start, const Vec3& direction, const ConvexPolyhedron& p,
                                 const OutputBudget& budget);

/// [start, start + direction] + Q for a polygon Q and a direction not in its
/// plane: the prism. \pre dot(direction, Q.normal()) != 0.
ConvexPolyhedron prism(const ConvexSet& polygon, const Vec3& start, const Vec3& direction);

/// X given R = X + [0, sweep] (X a polygon or a polyhedron), exactly: the
/// facets of R below the sweep, those above moved back, the side facets shrunk.
ConvexSet unswept(const ConvexPolyhedron& r, const Vec3& sweep);

/// Q + P for a polygon Q and a polyhedron P, from the Gaussian maps
/// (polygon_sum.cpp), as the polyhedron itself (the face sums of a solid keep
/// thousands of them: no copy out of a ConvexSet).
/// \throw Error(limit) if its facets, counted first, exceed `budget`; the
///   message names the sum as `what` ("polygon + polyhedron").
ConvexPolyhedron polygon_polyhedron_sum(const ConvexSet& polygon, const ConvexPolyhedron& p,
                                        const OutputBudget& budget, const std::string& what);

}  // namespace cvms::detail
