// SPDX-License-Identifier: MIT
// The EPA in plain doubles on the operands' approximations: a guess of the
// support points the exact EPA will need, which it then inserts before its
// own loop (epa.cpp). A heuristic only: the exact EPA proves everything.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "support_operand.hpp"

namespace cvms::detail {

/// A support point of M = A + (-B) as its vertex pair (a of A, b of B).
using VertexPair = std::pair<VertexId, VertexId>;

/// The support points a floating-point EPA adds, in order, to the
/// tetrahedron `start` (four pairs whose points hold the origin) before it
/// stops; empty when rounding gives it nothing to work with.
std::vector<VertexPair> double_epa(const SupportOperand& a, const SupportOperand& b,
                                   const std::array<VertexPair, 4>& start);

}  // namespace cvms::detail
