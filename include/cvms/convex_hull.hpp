// SPDX-License-Identifier: MIT
/// \file
/// Exact 3D convex hull (quickhull) over the predicates module.
#pragma once

#include <array>
#include <span>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/vec.hpp"

namespace cvms {

/// The convex hull of a point set, with maximal polygonal facets and only
/// extreme points as vertices. Duplicates, collinear and coplanar points are
/// handled exactly.
/// \throw Error(degenerate) if the points do not span 3D (fewer than 4
///   points, or all coplanar, collinear or equal), saying which.
/// Complexity: O(n log n) expected for points in general position.
ConvexPolyhedron convex_hull(std::span<const Vec3> points);

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

}  // namespace cvms
