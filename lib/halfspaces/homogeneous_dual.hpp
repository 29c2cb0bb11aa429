// SPDX-License-Identifier: MIT
// The rows of a full-dimensional system a_i·x <= b_i in R^3 dualised around
// a strict interior point x0, in homogeneous integer coordinates. With the
// row scaled to primitive integers (a positive factor: the same half-space)
// and x0 = X / D (D > 0, X integer), the dual point a/(b − a·x0) of
// from_halfspaces.cpp is a / (s / D) with s = b D − a·X > 0, i.e. the point
// with homogeneous coordinates (D a, s) — and, the weight being positive,
// the homogeneous point (a, s) stands for a scaled dual hull around the same
// origin: q_i' = q_i / D, a dilation, which changes no orientation and no
// facet structure. So every decision of the dual hull is a sign of an
// integer determinant (homogeneous_orient.hpp), and no rational with a
// per-row denominator is ever reduced.
#pragma once

#include <span>
#include <vector>

#include <gmpxx.h>

#include "cvms/halfspaces.hpp"
#include "homogeneous_orient.hpp"
#include "limb_arena.hpp"
#include "max_slack_lp.hpp"

namespace cvms::detail {

/// The rows as homogeneous dual points. Their integers (not the origin's)
/// keep their limbs in `limbs`, one arena for all rows instead of a heap
/// block per integer: read-only views (limb_arena.hpp), valid while it lives.
struct HomogeneousDual {
  LimbArena limbs;                       ///< declared first: it outlives the views
  std::vector<HomogeneousPoint> points;  ///< (a_i, s_i): a_i the primitive row normal, s_i > 0
  std::vector<mpz_class> offsets;        ///< b_i of the primitive row (a_i, b_i)
  /// gcd(a_i) of the primitive row (usually 1): the facet's primitive
  /// normal is a_i / c_i and its offset b_i / c_i, with no gcd to compute
  /// later (the gcd of the four entries is taken through it anyway).
  std::vector<mpz_class> normal_contents;
  HomogeneousPoint origin;  ///< x0 = X / D as (X, D)
};

/// The dual of rows in 3 unknowns (no zero normal) around x0.
/// \pre a_i·x0 < b_i for every row.
HomogeneousDual homogeneous_dual(const std::vector<LpRow>& rows, const std::vector<Rational>& x0);

/// The same for rows in space, as given (no chart, no copy).
/// \pre as above.
HomogeneousDual homogeneous_dual(std::span<const HalfspaceRow> rows, const std::vector<Rational>& x0);

}  // namespace cvms::detail
