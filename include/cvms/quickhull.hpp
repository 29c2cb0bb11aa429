// SPDX-License-Identifier: MIT
/// \file
/// Exact 3D convex hull (quickhull) over the predicates module.
#pragma once

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

}  // namespace cvms
