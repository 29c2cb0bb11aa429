// SPDX-License-Identifier: MIT
// The vertices of a bounded full-dimensional intersection of half-spaces in
// R^3 from the exact hull of its homogeneous integer dual points
// (homogeneous_dual.hpp): the hull's filters run on the doubles of a_i/s_i,
// its exact fallback is the integer determinant (homogeneous_orient.hpp),
// and of the hull only the combinatorics are used (the dual facets' corners
// as rows, from which intersection_polyhedron.hpp reads the polyhedron). Each facet of the dual
// hull is a vertex x of the set, where the rows of the facet's corners are
// tight. The hull reports for each facet three dual points i, j, k spanning
// its plane (hull_soup's plane triple, not necessarily corners of the
// facet): they are affinely independent, and the plane misses the origin
// exactly when the set is bounded there, so a_i, a_j, a_k are linearly
// independent and x solves their three equations, as every row whose dual
// point is on the plane is tight at x. With y the Cramer solution of
// a·y == s at those rows (the pole of the facet's plane, homogeneous_hull.hpp),
//   y = (s_i (a_j × a_k) + s_j (a_k × a_i) + s_k (a_i × a_j)) / det[a_i; a_j; a_k],
// and s = D b − a·X for x0 = X / D, x = (X + y) / D.
// With the triple counterclockwise from outside, orient3d(q_i, q_j, q_k, 0)
// = −sign det[(a_i, s_i); (a_j, s_j); (a_k, s_k); (0, 0, 0, 1)] = −sign
// det[a_i; a_j; a_k] (homogeneous_orient.cpp), so the origin is strictly
// inside the facet's half-space (c > 0 in from_halfspaces.cpp) iff that
// determinant is positive: the same determinant decides boundedness.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "cvms/vec.hpp"
#include "homogeneous_dual.hpp"
#include "max_slack_lp.hpp"
#include "progress_reporter.hpp"

namespace cvms::detail {

/// The vertices of a bounded set and the rows tight at each.
struct DualVertices {
  LimbArena limbs;                        ///< declared first: the vertices' and planes' limbs
  HomogeneousDual dual;                   ///< the rows, index by index
  std::vector<Vec3> vertices;             ///< one per facet of the dual hull
  std::vector<std::uint32_t> tight_offsets{0};  ///< vertex v: tight[tight_offsets[v] .. tight_offsets[v + 1])
  std::vector<std::uint32_t> tight;             ///< the rows at the corners of each dual facet, counterclockwise from outside
};

/// The vertices of {x : rows} (3 unknowns, no zero normal) in the order of
/// the dual hull's facets, as from_halfspaces.cpp's rational dual hull
/// around the same x0 gives them; nothing if the set is unbounded (the
/// caller names a direction from the rational dual hull).
/// \pre a_i·x0 < b_i for every row.
/// The dual hull reports its stage to `progress` (hull_soup).
std::optional<DualVertices> bounded_vertices(const std::vector<LpRow>& rows, const std::vector<Rational>& x0,
                                             ProgressReporter* progress = nullptr);

/// The same from the rows' dual (homogeneous_dual.hpp), taken over.
std::optional<DualVertices> bounded_vertices(HomogeneousDual dual, ProgressReporter* progress = nullptr);

}  // namespace cvms::detail
