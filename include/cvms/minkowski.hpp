// SPDX-License-Identifier: MIT
/// \file
/// The Minkowski sum of two convex polyhedra: one entry point, three algorithms.
#pragma once

#include <cstdint>

#include "cvms/convex_polyhedron.hpp"

namespace cvms {

/// Which algorithm minkowski_sum runs. All three compute the same exact
/// polyhedron (same vertex and facet sets; the numbering may differ); they
/// differ in speed.
enum class Algorithm {
  cvms,    ///< contributing vertices (paper Section 4)
  essdms,  ///< slope diagrams with contributing vertices (paper Section 5.2)
  chms,    ///< exact hull of all pairwise vertex sums (the reference oracle)
};

/// The algorithm's name as the cvms tool's --algorithm spells it: "cvms",
/// "essdms" or "chms" ("unknown" for a value outside the enum).
const char* to_string(Algorithm algorithm) noexcept;

/// How minkowski_sum computes the sum. The default is CVMS with the
/// output-sensitive searches (contributing vertices by hill-climbing, edge
/// facets by tracing Gaussian arcs) on the calling thread.
struct Options {
  Algorithm algorithm = Algorithm::cvms;  ///< which algorithm
  /// CVMS only: 1 (the default) computes everything on the calling thread;
  /// 2 or more also use one worker thread at a time inside the call: it
  /// traces the edge facets (arc walk) while the calling thread finds the
  /// corner facets, then computes the output's facet planes while the
  /// calling thread builds the vertices and mesh, which then helps with the
  /// planes (more threads are not used yet). Small sums stay on the calling
  /// thread, where starting a thread would cost more than it saves. The
  /// result, Stats included, is identical.
  unsigned threads = 1;
};

/// What an algorithm did. For CVMS, translated + corner + edge facets equals
/// the number of facets of the result.
struct Stats {
  std::uint64_t translated_facets = 0;  ///< facets parallel to a facet of A
  std::uint64_t corner_facets = 0;      ///< facets parallel to a facet of B only
  std::uint64_t edge_facets = 0;        ///< edge(A) + edge(B) facets
  /// Facets of A and of B with 2 or more contributing vertices (CVMS, ESSDMS).
  std::uint64_t contributing_ties = 0;
  /// (edge of A, horizon edge of B) pairs that passed Property 1 and were
  /// tested with the normal-orientation criterion (CVMS, paper search); for
  /// CVMS with the walk, the steps of all arc walks; for
  /// ESSDMS, the (arc of A, arc of B) pairs that passed the contributing-vertex
  /// pre-check and were tested for a proper crossing.
  std::uint64_t edge_candidates = 0;
  /// Candidates the paper's criterion alone (Eq. 4 with "not invisible"
  /// including parallel facets, plus Eq. 5) would accept but the exact
  /// Gaussian-map test rejects: the facet of B is parallel to the edge of A,
  /// and the true facet is the corner facet f_B + e_A (see lib/minkowski/cvms_algorithm.cpp).
  std::uint64_t edge_paper_rejections = 0;
  std::uint64_t predicate_filtered = 0;  ///< predicate calls the double filter answered
  std::uint64_t predicate_exact = 0;     ///< predicate calls that needed exact arithmetic
};

/// The sum and how it was computed.
struct MinkowskiResult {
  ConvexPolyhedron polyhedron;  ///< A + B, with maximal facets and extreme vertices
  Stats stats;                  ///< counters of the algorithm that ran
};

/// A + B = {a + b : a in A, b in B}. Exact. Thread-safe (no shared state).
/// CVMS costs O(f_A + f_B + e_A' + k) predicates times the vertex degrees met
/// (k = the output facets, e_A' the edges of A that pass Property 1), plus the
/// climbs between neighbouring facets' answers (short for operands of
/// similar resolution; O(v) in the worst case), plus the output;
/// ESSDMS costs O(f_A f_B + f_A e_B + f_B e_A + e_A' e_B' + f_A v_B + f_B v_A).
/// \throw Error(invalid_argument) for an empty (default-constructed) operand
///   or an unknown option value.
MinkowskiResult minkowski_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                              const Options& options = {});

/// CHMS: the exact convex hull of all v_A * v_B pairwise vertex sums.
/// Complexity: O(v_A v_B log(v_A v_B)) expected.
/// \throw Error(limit) if v_A v_B >= 2^32 - 1 (the hull's 32-bit indices).
ConvexPolyhedron chms(const ConvexPolyhedron& a, const ConvexPolyhedron& b);

}  // namespace cvms
