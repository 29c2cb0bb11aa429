// SPDX-License-Identifier: MIT
// The sums f + B of convex polygons f (a solid's boundary cut into convex
// parts, facet_polygons.hpp) with one convex polyhedron B: each a convex
// polyhedron, by the sets layer's polygon + polyhedron sum, which builds it
// directly from the two Gaussian maps without a hull. Their union is
// dA + B, the part of A + B that A + b (b in B) does not already cover.
#pragma once

#include <span>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/vec.hpp"

namespace cvms::detail {

/// polygon + b for every polygon, in the polygons' order, whatever
/// options.threads (the polygons are shared out over that many threads, no
/// more than the machine has cores). Limits as minkowski_sum of unions
/// (cvms/convex_union.hpp): options.limits bounds each sum and the total of
/// output facets (the memory at SumLimits::bytes_per_output_facet per
/// facet), checked before any sum (at least 4 facets a piece) and as the
/// sums arrive; the error names the first polygon in order that fails or
/// passes the total, the same for every thread count. options.progress hears
/// the stage "solid sum: faces", in polygons summed.
/// \pre every polygon is convex with at least 3 corners, not all collinear.
/// \throw Error(limit) naming the limit; Error(cancelled) if
///   options.progress returns false.
std::vector<ConvexPolyhedron> face_sums(std::span<const std::vector<Vec3>> polygons,
                                        const ConvexPolyhedron& b, const Options& options);

}  // namespace cvms::detail
