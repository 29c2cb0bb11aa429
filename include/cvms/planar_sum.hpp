// SPDX-License-Identifier: MIT
/// \file
/// Minkowski sum of two convex polygons in the plane by convolution: merge the
/// two edge sequences by direction (ccw_in_between, never angles), exact.
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
/// The output has at most |p| + |q| vertices; p[i] + q[j] for each pair.
/// \throw Error(invalid_argument) for empty input, and for the precondition
///   violations found at no extra cost: coinciding consecutive vertices, and
///   a polygon (3 or more vertices) whose edge directions do not strictly
///   increase over one counterclockwise turn (clockwise, collinear consecutive
///   vertices, reflex or self-overlapping). The message names the operand and
///   the vertex.
/// Complexity: O(|p| + |q|) predicates, O(|p| + |q|) memory.
std::vector<IndexPair> planar_sum_indices(std::span<const Vec2> p, std::span<const Vec2> q);

/// The same sum as points: p[i] + q[j] for each pair of planar_sum_indices.
/// \throw Error(invalid_argument) as planar_sum_indices.
/// Complexity: as planar_sum_indices.
///
/// \code
/// std::vector<cvms::Vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
/// std::vector<cvms::Vec2> triangle{{0, 0}, {1, 0}, {0, 1}};
/// auto sum = cvms::planar_sum(square, triangle);  // 5 vertices, from (0, 0)
/// \endcode
std::vector<Vec2> planar_sum(std::span<const Vec2> p, std::span<const Vec2> q);

}  // namespace cvms
