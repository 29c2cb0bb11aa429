// SPDX-License-Identifier: MIT
// The largest common slack of a system a_i·u <= b_i in d <= 3 unknowns:
// max t subject to a_i·u + t <= b_i and t <= 1, solved exactly by a
// one-phase simplex in rationals. The first step of from_halfspaces: t > 0
// gives a strict interior point, t == 0 implied equalities (the rows with a
// positive dual multiplier y_i: sum y_i (a_i, b_i) == 0 with y >= 0 and
// sum y_i >= 1, so sum y_i (b_i − a_i·u) == 0 for every feasible u and each
// such row is tight on the whole set), t < 0 an empty set.
#pragma once

#include <cstddef>
#include <vector>

#include "cvms/rational.hpp"

namespace cvms::detail {

/// One row a·u <= b in the unknowns u (a.size() == the dimension).
struct LpRow {
  std::vector<Rational> a;
  Rational b;
};

/// The optimum of the max-slack LP.
struct MaxSlack {
  Rational slack;                 ///< t*, at most 1
  std::vector<Rational> point;    ///< a maximiser u*
  std::vector<std::size_t> tight; ///< rows with a positive dual multiplier, in increasing order
  std::size_t pivots = 0;         ///< simplex pivots taken (for tests of the order's effect)
};

/// Solves the LP for the rows in `dimension` unknowns (at least one row).
/// The rows are taken in a pseudo-random order seeded from their contents
/// (the same rows in the same order give the same order, so the answer is
/// deterministic): Bland's rule prefers low row indices, and rows sorted by
/// an adversary (tangent planes of a sphere, farthest first) would make it
/// walk over every row, a quadratic time where a random order takes few
/// pivots.
MaxSlack max_slack(const std::vector<LpRow>& rows, int dimension);

}  // namespace cvms::detail
