// SPDX-License-Identifier: MIT
/// \file
/// Exact 3D convex hull (quickhull) over the predicates module.
#pragma once

#include <array>
#include <span>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/convex_set.hpp"
#include "cvms/polygon_soup.hpp"
#include "cvms/progress.hpp"
#include "cvms/vec.hpp"

namespace cvms {

/// The convex hull of a point set, with maximal polygonal facets and only
/// extreme points as vertices. Duplicates, collinear and coplanar points are
/// handled exactly.
/// \throw Error(degenerate) if the points do not span 3D (fewer than 4
///   points, or all coplanar, collinear or equal), saying which
///   (convex_hull_set takes such input).
/// Complexity: O(n log n) expected for points in general position.
ConvexPolyhedron convex_hull(std::span<const Vec3> points);

/// convex_hull(points), reporting the stage "hull" (input points settled:
/// on or inside the hull built so far) to `progress`, which may stop it
/// (cvms/progress.hpp). Same result.
/// \throw Error(cancelled) if `progress` returns false; else as above.
ConvexPolyhedron convex_hull(std::span<const Vec3> points, const ProgressCallback& progress);

/// The convex hull of points given as doubles, each coordinate taken as the
/// exact binary number it is (no rounding anywhere; the vertices of the
/// result are exactly the extreme input points). Same result as converting
/// every point to Vec3 first, but faster: only the points that the output or
/// an exact fallback of a predicate needs are converted to rationals.
/// \throw Error(invalid_argument) if a coordinate is NaN or infinite,
///   naming the point's index and the coordinate.
/// \throw Error(degenerate) as above.
/// Complexity: O(n log n) expected for points in general position.
ConvexPolyhedron convex_hull(std::span<const std::array<double, 3>> points);

/// The convex hull of any points, in the dimension they span: the empty set
/// for no points, a point, a segment (the two extreme points), a polygon (an
/// exact planar hull with orientation predicates in the plane's chart) or
/// the polyhedron convex_hull computes. Never throws degenerate.
/// Complexity: O(n) predicates to find the dimension, then O(n log n).
ConvexSet convex_hull_set(std::span<const Vec3> points);

/// convex_hull_set(points), reporting the hull of points that span 3D to
/// `progress` as convex_hull does (the flat cases take linear time and
/// report nothing). Same result.
/// \throw Error(cancelled) if `progress` returns false.
ConvexSet convex_hull_set(std::span<const Vec3> points, const ProgressCallback& progress);

/// The same for points given as doubles, each coordinate taken as the exact
/// binary number it is.
/// \throw Error(invalid_argument) if a coordinate is NaN or infinite, naming
///   the point's index and the coordinate.
/// Complexity: as above, plus the exact conversion of every point.
ConvexSet convex_hull_set(std::span<const std::array<double, 3>> points);

/// The convex set a soup describes, for files that may be flat:
///  - no faces: the hull of all the points (convex_hull_set), e.g. a
///    points-only OFF or an `x y z` list;
///  - faces whose points span 3D: ConvexPolyhedron::from_soup (the soup must
///    be a closed convex surface, with its errors);
///  - faces whose points all lie in one plane: the polygon they cover. One
///    face must be a convex polygon (ConvexSet::polygon); several faces must
///    be consistently oriented and tile a convex polygon: every directed
///    edge used at most once, the edges used once forming one cycle, which
///    must be a convex polygon, and every face planar, convex and oriented as
///    that cycle. Points used by no face are ignored.
/// \throw Error(not_convex) naming the face for a non-convex or wrongly
///   oriented face or boundary, or for a single face that is not planar
///   (naming a vertex off its plane), Error(topology) for a repeated directed edge
///   or a boundary that is not one cycle, Error(degenerate) for faces of zero
///   area, and the errors of ConvexPolyhedron::from_soup for solids.
ConvexSet convex_set_from_soup(PolygonSoup soup);

}  // namespace cvms
