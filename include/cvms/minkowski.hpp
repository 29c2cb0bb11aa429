// SPDX-License-Identifier: MIT
// The Minkowski sum of two convex polyhedra: one entry point, three algorithms.
#pragma once

#include <cstdint>

#include "cvms/convex_polyhedron.hpp"

namespace cvms {

enum class Algorithm {
  cvms,    ///< contributing vertices (paper Section 4)
  essdms,  ///< slope diagrams with contributing vertices (paper Section 5.2)
  chms,    ///< exact hull of all pairwise vertex sums (the reference oracle)
};

struct Options {
  Algorithm algorithm = Algorithm::cvms;
};

struct Stats {
  std::uint64_t translated_facets = 0;  ///< facets parallel to a facet of A
  std::uint64_t corner_facets = 0;      ///< facets parallel to a facet of B only
  std::uint64_t edge_facets = 0;        ///< edge(A) + edge(B) facets
  std::uint64_t contributing_ties = 0;  ///< facets with 2 or more contributing vertices
  std::uint64_t predicate_filtered = 0; ///< predicate calls the double filter answered
  std::uint64_t predicate_exact = 0;    ///< predicate calls that needed exact arithmetic
};

struct MinkowskiResult {
  ConvexPolyhedron polyhedron;
  Stats stats;
};

/// A + B = {a + b : a in A, b in B}. Exact. Thread-safe (no shared state).
/// \throw Error(not_implemented) if the algorithm is not available.
MinkowskiResult minkowski_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                              const Options& options = {});

/// CHMS: the exact convex hull of all v_A * v_B pairwise vertex sums.
/// Complexity: O(v_A v_B log(v_A v_B)) expected.
ConvexPolyhedron chms(const ConvexPolyhedron& a, const ConvexPolyhedron& b);

}  // namespace cvms
