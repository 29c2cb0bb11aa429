// SPDX-License-Identifier: MIT
// Minkowski sum of two convex polygons in the plane by convolution: merge the
// two edge sequences by direction (ccw_in_between, never angles), exact.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "cvms/vec.hpp"

namespace cvms {

/// One vertex of a planar sum: p[first] + q[second].
using IndexPair = std::pair<std::uint32_t, std::uint32_t>;

/// The vertices of P + Q, counterclockwise, as index pairs into p and q.
/// Each operand is a convex polygon given counterclockwise with no repeated
/// and no collinear consecutive vertices, or a segment (2 distinct points), or
/// one point. Parallel edges are merged and collinear vertices dropped, so the
/// result is a strictly convex polygon (or a segment or a point when both
/// operands are degenerate in compatible ways). Starts at the pair of the
/// lowest (smallest y, then smallest x) vertices.
/// \throw Error(invalid_argument) for empty input.
/// Complexity: O(|p| + |q|) predicates.
std::vector<IndexPair> planar_sum_indices(std::span<const Vec2> p, std::span<const Vec2> q);

/// The same sum as points.
std::vector<Vec2> planar_sum(std::span<const Vec2> p, std::span<const Vec2> q);

}  // namespace cvms
