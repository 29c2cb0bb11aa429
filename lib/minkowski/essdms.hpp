// SPDX-License-Identifier: MIT
// Private entry point of the ESSDMS algorithm (slope diagrams with
// contributing vertices, paper Section 5.2), called by minkowski_sum.
#pragma once

#include "cvms/minkowski.hpp"

namespace cvms::detail {

/// A + B by merging the slope diagrams of A and B without embedding them.
/// Adds its facet counts, ties and arc-pair counts to `stats` (not the
/// predicate counters: the caller measures those). \pre a and b are
/// non-empty.
ConvexPolyhedron essdms_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, Stats& stats);

}  // namespace cvms::detail
