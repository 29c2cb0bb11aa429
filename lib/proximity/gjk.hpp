// SPDX-License-Identifier: MIT
// The exact GJK of this layer: the point of C = A + (-B) nearest to the
// origin, from support walks on A and B (gjk.cpp has the algorithm and the
// termination proof); A and B are any SupportOperand (a placed polyhedron or
// a convex set of any dimension).
#pragma once

#include <array>

#include "cvms/proximity.hpp"
#include "double_gjk.hpp"
#include "support_operand.hpp"

namespace cvms::detail {

/// One point of the simplex: a vertex of A, a vertex of B (moved), their
/// difference. The vertices' positions are not kept: only the final simplex's
/// are needed (the witnesses), and copying every candidate's was a third of
/// a query's allocations.
struct GjkPoint {
  VertexId vertex_a, vertex_b;
  Vec3 c;  ///< a - b, a point of C
};

/// What the loop found.
struct GjkOutcome {
  bool intersect = false;   ///< the origin is in C
  Vec3 nearest;             ///< the point of C nearest to the origin (0 if intersect)
  Rational squared_norm;    ///< |nearest|^2
  std::array<GjkPoint, 4> simplex;
  /// nearest = sum weight_num_i simplex_i.c / weight_den; weights positive, sum 1.
  std::array<mpz_class, 4> weight_num;
  mpz_class weight_den;
  int size = 0;                    ///< points in the simplex
  int iterations = 0;
};

/// How far to go.
enum class GjkGoal {
  distance,     ///< to the nearest point
  intersection  ///< stop at the first separating direction (nearest and weights then unset)
};

/// \pre both operands non-empty. With b_offset, B is moved further by that
/// exact vector (the simplex's b points include it).
GjkOutcome exact_gjk(const SupportOperand& a, const SupportOperand& b, GjkGoal goal,
                     const Vec3* b_offset = nullptr);

/// exact_gjk started from `guess` instead of the double GJK's (the tests
/// pass wrong guesses): the same answer for any guess, only the time
/// differs. \pre the guess's vertex ids are valid (any pairs, repeated or not).
GjkOutcome exact_gjk_from(const SupportOperand& a, const SupportOperand& b, GjkGoal goal, const Vec3* b_offset,
                          const GjkCandidate& guess);

}  // namespace cvms::detail
