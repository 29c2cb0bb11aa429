// SPDX-License-Identifier: MIT
// The exact quickhull (hull_soup.hpp) of points in homogeneous integer
// coordinates (homogeneous_orient.hpp): its filters run on the doubles of
// the quotients, each within a proven bound; what they leave undecided goes
// to the integer determinant, so no rational is reduced for a decision.
// Used by from_halfspaces for the dual points a/s of the rows.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "cvms/polygon_soup.hpp"
#include "homogeneous_orient.hpp"
#include "limb_arena.hpp"
#include "progress_reporter.hpp"

namespace cvms::detail {

/// The point p stands for, reduced.
Vec3 standing_for(const HomogeneousPoint& p);

/// The poles of the hull's facets' planes, facet by facet, their integers'
/// limbs in one arena (read-only views, limb_arena.hpp) instead of a heap
/// block each.
struct FacePoles {
  LimbArena limbs;  ///< declared first: it outlives the views
  std::vector<HomogeneousPoint> poles;
};

/// hull_soup of the points the homogeneous points stand for, with the same
/// decisions (hence the same faces) as on those rational points, but no
/// soup points: source_index maps each face index to its input point.
/// exact(i) makes point i's rational value, for the few other exact
/// decisions.
/// If face_poles is given, it receives for every face the pole y of its
/// plane, from three points i, j, k spanning it (the face's plane triple
/// from hull_soup, counterclockwise seen from outside; not necessarily
/// corners of the face) by Cramer's rule in integers: y = (s_i (a_j × a_k) + s_j (a_k ×
/// a_i) + s_k (a_i × a_j)) / det[a_i; a_j; a_k] for the points (a, s), so
/// that a·y == s at each of them, i.e. the plane is {q : q·y == 1} of the
/// points q = a/s. Its weight w = det[a_i; a_j; a_k] may be zero or
/// negative: w > 0 exactly when the origin is strictly below the plane
/// (integer_dual_hull.hpp). These are the last-row cofactors C of the
/// triple's 4×4 determinant, y = (−C_0, −C_1, −C_2, C_3), which the exact
/// predicates have mostly computed for that plane already.
/// \pre exact(i) == standing_for(points[i]).
/// Reports the hull's stage to `progress` (hull_soup).
/// \throw Error(degenerate) as hull_soup; Error(cancelled) if progress asks.
PolygonSoup homogeneous_hull(const std::vector<HomogeneousPoint>& points, const std::function<Vec3(std::uint32_t)>& exact,
                             std::vector<std::uint32_t>& source_index, FacePoles* face_poles = nullptr,
                             ProgressReporter* progress = nullptr);

}  // namespace cvms::detail
