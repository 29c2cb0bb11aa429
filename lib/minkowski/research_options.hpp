// SPDX-License-Identifier: MIT
// The switches that exist for research, testing and benchmarking rather than
// for users: CVMS's paper-faithful search modes (paper Section 4.3, the
// reference the output-sensitive walks are checked against) and the sizes at
// which Options::threads > 1 starts a worker. A user chooses the algorithm
// and the threads (cvms/minkowski.hpp); these stay private so that the public
// Options promise nothing about them.
#pragma once

#include <cstddef>
#include <cstdint>

#include "cvms/minkowski.hpp"
#include "sum_counters.hpp"

namespace cvms::detail {

/// How CVMS finds its edge facets (paper Section 4.3, step 3).
enum class EdgeFacetSearch {
  /// The paper's search: for every edge of A that passes Property 1, the
  /// visibility of every facet of B (Eq. 4) gives the horizon edges, and the
  /// normal-orientation criterion (Eq. 5) selects among them; the final
  /// decision is made exact with the Gaussian-map crossing test.
  /// O(e_A (f_B + e_B)) predicates: the reference for faster variants.
  paper,
  /// Output-sensitive: for each edge of A that passes Property 1, walk on B
  /// along the edge's Gaussian arc from the region of one contributing
  /// vertex to the other, crossing exactly the arcs of the edges of B that
  /// give edge facets (lib/minkowski/arc_trace.cpp). Same result as `paper`.
  walk,
};

/// How CVMS finds the contributing vertices of every facet (paper Section 4.3,
/// steps 1 and 2).
enum class ContributingVertexSearch {
  /// The paper's search: a linear scan over the vertices of the other
  /// operand for every facet, O(f_A v_B + f_B v_A) predicates.
  scan,
  /// Output-sensitive: facets in breadth-first order, each maximiser found by
  /// hill-climbing from the neighbouring facet's answer. Same result as `scan`.
  walk,
};

/// How much work Options::threads > 1 needs before a worker thread starts:
/// starting one costs tens of microseconds, more than a small sum takes in
/// all. Tests pass zeros to run the threaded paths on small inputs.
struct WorkerMinimums {
  /// min(edges of A, facets of B): the smaller of the two steps that overlap
  /// (edge-facet tracing, corner facets).
  std::size_t trace = 256;
  std::size_t output_facets = 512;  ///< facets of A + B, for the output build
  /// Options::threads beyond std::thread::hardware_concurrency() only on
  /// request: the tests run 4 and 8 threads on two cores to shuffle the
  /// interleavings. A sum does not: nothing runs sooner, and every extra
  /// worker brings a malloc arena of its own (docs/performance.md).
  bool oversubscribe = false;
};

/// ResearchOptions::walk_piece_facets by default.
inline constexpr std::uint32_t default_walk_piece_facets = 8192;

/// The defaults are what minkowski_sum runs; {scan, paper} is the
/// paper-faithful reference mode. CVMS only.
struct ResearchOptions {
  ContributingVertexSearch contributing_vertex_search = ContributingVertexSearch::walk;
  EdgeFacetSearch edge_facet_search = EdgeFacetSearch::walk;
  WorkerMinimums worker_minimums;
  /// The contributing-vertex walk's facets per piece (walk_pieces): the
  /// pieces of A's walk share the threads. Part of the search, so that
  /// every thread count evaluates the same predicates.
  std::uint32_t walk_piece_facets = default_walk_piece_facets;
};

/// The paper-faithful CVMS: linear scans and the horizon-edge search.
inline ResearchOptions paper_search() {
  return {ContributingVertexSearch::scan, EdgeFacetSearch::paper, {}, default_walk_piece_facets};
}

/// minkowski_sum with the research switches; the same checks, result, Stats
/// and diagnostics.
/// \throw Error(invalid_argument) also for an unknown search mode.
MinkowskiResult minkowski_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Options& options,
                              const ResearchOptions& research);

}  // namespace cvms::detail
