// SPDX-License-Identifier: MIT
// Private entry point of the ESSDMS algorithm (slope diagrams with
// contributing vertices, paper Section 5.2), called by minkowski_sum.
#pragma once

#include "cvms/minkowski.hpp"
#include "sum_counters.hpp"

namespace cvms::detail {

/// A + B by merging the slope diagrams of A and B without embedding them.
/// Adds its facet counts, ties and arc-pair counts to `stats` (not the
/// predicate counters: the caller measures those). \pre a and b are
/// non-empty, and `stats` starts at zero (its facet counts feed the budget).
/// \throw Error(limit) beyond `limits`, before the loop or the output that
///   would pass them (output_budget.hpp).
/// \throw Error(cancelled) when `progress` (cvms/progress.hpp) asks to stop.
ConvexPolyhedron essdms_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const SumLimits& limits,
                            SumCounters& stats, const ProgressCallback& progress = {});

}  // namespace cvms::detail
