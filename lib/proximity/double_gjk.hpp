// SPDX-License-Identifier: MIT
// GJK in plain doubles on the operands' approximations: a guess of the
// final simplex of the exact GJK, which then starts from it (gjk.cpp).
// A heuristic only: nothing it returns is trusted without exact checks.
#pragma once

#include <array>

#include "support_operand.hpp"

namespace cvms::detail {

/// The vertex pairs (a vertex of A, a vertex of B) of a guessed simplex of
/// C = A + (-B): the points a_i - b_i whose hull holds the nearest point.
struct GjkCandidate {
  int size = 0;  ///< 0: no guess (non-finite numbers)
  std::array<VertexId, 4> vertex_a, vertex_b;
};

/// B moved further by b_offset (rounded); finite or not, never throws.
/// With `until_separated`, it stops at the first direction that separates
/// in doubles (the exact GjkGoal::intersection test then needs no more).
GjkCandidate double_gjk(const SupportOperand& a, const SupportOperand& b, const std::array<double, 3>& b_offset,
                        bool until_separated = false);

}  // namespace cvms::detail
