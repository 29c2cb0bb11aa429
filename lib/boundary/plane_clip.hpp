// SPDX-License-Identifier: MIT
// Convex polygons lying in one plane of R^3, cut by other planes, and the
// difference of such a polygon and a convex region given by half-spaces.
//
// Why in R^3 and not in a chart of the polygon's plane: cutting a polygon
// in the plane h by the half-space dot(m, x) <= e is cutting it, inside h,
// by the half-plane h ∩ {dot(m, x) <= e}; the crossing points a + t (b - a)
// of the polygon's edges stay exactly on h, so no chart and no lifting is
// needed, and every sign is one filtered side_of_plane on the points' cached
// approximations and the cutting plane's (integer normal, exact offset).
//
// Convexity: a strictly convex polygon cut by a half-space is strictly
// convex or has zero area. Its corners are the old corners on the kept side
// (angles unchanged) and the crossing points of edges whose ends lie
// strictly on opposite sides (inside an edge, never equal to a corner, and
// the cut line is not along that edge), so no corner repeats and no three
// consecutive corners are collinear. It has zero area iff fewer than three
// corners are left: with no corner strictly on the kept side, every corner
// left lies on the cut line, and a strictly convex polygon meets a line in
// at most two corners.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "approx.hpp"
#include "cvms/rational.hpp"
#include "cvms/sign.hpp"
#include "cvms/vec.hpp"

namespace cvms::detail {

/// A corner: its exact position and a cached approximation for the filters.
struct ClipPoint {
  Vec3 exact;
  ApproxVec3 approx;
};

/// The corners of the polygons of one plane: polygons refer to them by
/// index, so that splitting a polygon copies no exact coordinates and makes
/// only its crossing points. A deque: growing it never moves the exact
/// values (which would copy them, their moves not being noexcept).
using ClipPoints = std::deque<ClipPoint>;

/// A convex polygon in a plane: indices of its corners in order, strictly
/// convex.
using ClipPolygon = std::vector<std::uint32_t>;

/// The closed half-space dot(normal, x) <= offset. Refers to storage kept
/// elsewhere (a piece's planes), which must outlive it.
struct ClipPlane {
  const Vec3* normal = nullptr;
  const ApproxVec3* normal_approx = nullptr;
  const Rational* offset = nullptr;
  Approx offset_approx;
};

/// Sign of dot(normal, p) - offset: positive outside the half-space.
Sign side(Vec3Ref p, const ClipPlane& plane);
/// The same for a corner.
inline Sign side(const ClipPoint& p, const ClipPlane& plane) { return side(Vec3Ref{p.exact, p.approx}, plane); }

/// The parts of `polygon` inside and outside the half-space, each with
/// fewer than three corners (cleared) if it has zero area. Crossing points
/// are appended to `points`.
struct SplitPolygon {
  ClipPolygon inside;
  ClipPolygon outside;
};
SplitPolygon split(ClipPoints& points, const ClipPolygon& polygon, const ClipPlane& plane);

/// Replaces `pieces` (interior-disjoint convex polygons of one plane) by
/// convex polygons covering exactly the closure of their parts outside the
/// convex set C = the intersection of the half-spaces `region` (within the
/// pieces' plane). A piece that meets C in zero area is kept as it is; the
/// others are split along the planes in order: the part outside the first,
/// the part inside the first and outside the second, and so on, keeping the
/// parts of positive area. Any list of half-spaces whose intersection is C
/// gives a correct result; a half-space that does not cut the part left adds
/// no piece. New corners are appended to `points`.
void subtract_region(ClipPoints& points, std::vector<ClipPolygon>& pieces, const std::vector<ClipPlane>& region);

}  // namespace cvms::detail
