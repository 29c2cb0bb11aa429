// SPDX-License-Identifier: MIT
// Private entry point of the CVMS algorithm (paper Section 4), called by
// minkowski_sum.
#pragma once

#include "cvms/minkowski.hpp"
#include "research_options.hpp"
#include "stitch.hpp"

namespace cvms::detail {

/// A + B by contributing vertices. Adds its facet counts, ties and edge
/// candidate counts to `stats` (not the predicate counters: the caller
/// measures those). \pre a and b are non-empty.
/// Reports its stages to options.progress (cvms/progress.hpp).
ConvexPolyhedron cvms_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Options& options,
                          const ResearchOptions& research, SumCounters& stats);

/// The facets cvms_sum glues, before gluing (for benchmarks that time the
/// output construction alone). The builder refers to a and b. Reports the
/// stage "sum: facets" (edges of A searched) to `progress` if given.
SumFacetBuilder cvms_facets(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Options& options,
                            const ResearchOptions& research, SumCounters& stats,
                            ProgressReporter* progress = nullptr);

}  // namespace cvms::detail
