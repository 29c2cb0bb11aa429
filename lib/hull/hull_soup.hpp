// SPDX-License-Identifier: MIT
// Private entry point of the exact 3D quickhull: the hull as a plain polygon
// soup, so that it can be tested (and used by CHMS) without the mesh layer.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "cvms/polygon_soup.hpp"
#include "cvms/sign.hpp"
#include "cvms/vec.hpp"
#include "progress_reporter.hpp"

namespace cvms {

/// The convex hull of points as a soup with MAXIMAL polygonal facets: every
/// facet is a strictly convex polygon, counterclockwise seen from outside,
/// no two facets sharing an edge are coplanar, and the points of the soup are
/// exactly the extreme points of the input (copied, each once, numbered in
/// order of first use by the faces).
/// If source_index is given, it receives for every soup point the index of
/// one input point at that position.
/// \throw Error(degenerate) if the points do not span 3D, saying whether there
///   are none, or they are all equal, all collinear or all coplanar.
/// \throw Error(limit) for 2^32 - 1 or more points.
/// Reports the stage "hull" (points settled) to `progress` if given, and
/// stops by its Error(cancelled).
/// Complexity: O(n log n) expected for random input, O(n) extra memory.
PolygonSoup hull_soup(std::span<const Vec3> points, std::vector<std::uint32_t>* source_index = nullptr,
                      detail::ProgressReporter* progress = nullptr);

/// The same for points given as doubles, each taken exactly: only the points
/// that an undecided predicate or the output needs become rationals.
/// \throw Error(invalid_argument) for a NaN or infinite coordinate, naming
///   the point's index; otherwise as above.
PolygonSoup hull_soup(std::span<const std::array<double, 3>> points,
                      std::vector<std::uint32_t>* source_index = nullptr);

/// Points known by double approximations, every coordinate within max_error
/// of the exact value, whose exact values exact(i) makes on demand (at most
/// once per point: for the output and for the predicates the filters cannot
/// decide). Non-finite approximations or error are allowed (then everything
/// is decided exactly).
struct ApproximatePoints {
  std::span<const std::array<double, 3>> approx;  ///< one per point
  double max_error;                               ///< bounds every |approx - exact|
  std::function<Vec3(std::uint32_t)> exact;       ///< the exact point i
};
/// The same for points known by approximations.
PolygonSoup hull_soup(const ApproximatePoints& points, std::vector<std::uint32_t>* source_index = nullptr,
                      detail::ProgressReporter* progress = nullptr);

/// The sign of orient3d (predicates.hpp) of the exact input points with the
/// given indices.
using ExactOrient = std::function<Sign(std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t)>;
/// The sign of orient3d(a, b, c, p) − orient3d(a, b, c, q) (the values, not
/// their signs) of the exact input points with the given indices, i.e.
/// compare_dot(p, q, cross(b − a, c − a)): which of two points is farther
/// above the triangle (a, b, c).
using ExactCompareOrient =
    std::function<Sign(std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t)>;
/// The same, with every orient3d that the filters leave undecided answered
/// by `orient` instead of by the exact points (from_halfspaces' dual points
/// have an integer predicate that needs no rational), every undecided
/// comparison of the farthest point by `compare` (when given), and the
/// soup's points left empty: the caller knows them by index, from
/// source_index, and builds only those it needs. points.exact is still used
/// for the few other exact decisions (the initial simplex, and the farthest
/// point when `compare` is empty).
/// \pre orient agrees with orient3d of points.exact, compare (if given) with
///   compare_dot as above.
/// If face_planes is given, it receives for every face three input points
/// spanning its plane, counterclockwise seen from outside: the plane triple
/// that the exact predicates were asked about for the triangles of that
/// plane (so that a caller that caches work per triple finds it there). They
/// lie on the face's plane but need not be corners of the face.
PolygonSoup hull_soup(const ApproximatePoints& points, ExactOrient orient, ExactCompareOrient compare,
                      std::vector<std::uint32_t>& source_index,
                      std::vector<std::array<std::uint32_t, 3>>* face_planes = nullptr,
                      detail::ProgressReporter* progress = nullptr);

}  // namespace cvms
