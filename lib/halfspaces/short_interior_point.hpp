// SPDX-License-Identifier: MIT
// A strict interior point with short coordinates near the max-slack LP's
// optimum. The dual points of the integer path are (a_i, s_i) with
// s_i = b_i D − a_i·X for x0 = X/D (homogeneous_dual.hpp): an LP vertex has
// the long denominators of a 3×3 solve, which lengthen every s_i and so every
// exact determinant of the dual hull. A dyadic x0 = X/2^k with small k keeps
// s_i as short as the rows allow. Any strict interior point gives the same
// set (from_halfspaces.cpp: the polar argument holds around any of them),
// so this is a choice of speed only; it changes the dual points projectively
// (not by a dilation), hence the dual hull's order of work and so the order
// of the output's vertices and facets' first vertices, never the set.
#pragma once

#include <vector>

#include "cvms/rational.hpp"
#include "max_slack_lp.hpp"

namespace cvms::detail {

/// The first of x0 rounded to the nearest multiple of 2^-k, k = 0, 4, 16,
/// 64, that satisfies a·x < b for every row strictly (checked exactly), or
/// x0 itself if none does.
/// \pre a·x0 < b for every row.
std::vector<Rational> short_interior_point(const std::vector<LpRow>& rows, const std::vector<Rational>& x0);

}  // namespace cvms::detail
