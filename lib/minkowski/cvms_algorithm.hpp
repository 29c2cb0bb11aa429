// SPDX-License-Identifier: MIT
// Private entry point of the CVMS algorithm (paper Section 4), called by
// minkowski_sum.
#pragma once

#include <cstddef>

#include "cvms/minkowski.hpp"
#include "stitch.hpp"

namespace cvms::detail {

/// How much work Options::threads > 1 needs before a worker thread starts:
/// starting one costs tens of microseconds, more than a small sum takes in
/// all. Tests pass zeros to run the threaded paths on small inputs.
struct WorkerMinimums {
  /// min(edges of A, facets of B): the smaller of the two steps that overlap
  /// (edge-facet tracing, corner facets).
  std::size_t trace = 256;
  std::size_t output_facets = 512;  ///< facets of A + B, for the output build
};

/// A + B by contributing vertices. Adds its facet counts, ties and edge
/// candidate counts to `stats` (not the predicate counters: the caller
/// measures those). \pre a and b are non-empty.
ConvexPolyhedron cvms_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Options& options,
                          Stats& stats, WorkerMinimums minimums = {});

/// The facets cvms_sum glues, before gluing (for benchmarks that time the
/// output construction alone). The builder refers to a and b.
SumFacetBuilder cvms_facets(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Options& options,
                            Stats& stats, WorkerMinimums minimums = {});

}  // namespace cvms::detail
