// SPDX-License-Identifier: MIT
/// \file
/// Diagnostic counters of one Minkowski sum: how much search and exact
/// arithmetic it took. For profiling and for comparing the algorithms; the
/// counters' meaning follows the algorithms' internals and may change
/// between minor versions, unlike Stats (cvms/minkowski.hpp), which counts
/// the output's facets by kind.
#pragma once

#include <cstdint>

namespace cvms {

/// What minkowski_sum fills when Options::diagnostics points to one. Every
/// counter starts at 0 for each call (the sum overwrites the whole struct).
struct SumDiagnostics {
  /// Facets of A and of B with 2 or more contributing vertices (CVMS, ESSDMS).
  std::uint64_t contributing_ties = 0;
  /// CVMS: the steps of all arc walks (with the paper's horizon-edge
  /// search: the (edge of A, horizon edge of B) pairs that passed Property 1
  /// and were tested with the normal-orientation criterion). ESSDMS: the
  /// (arc of A, arc of B) pairs that passed the contributing-vertex
  /// pre-check and were tested for a proper crossing.
  std::uint64_t edge_candidates = 0;
  /// With the paper's horizon-edge search: candidates the paper's criterion
  /// alone (Eq. 4 with "not invisible" including parallel facets, plus
  /// Eq. 5) would accept but the exact Gaussian-map test rejects: the facet
  /// of B is parallel to the edge of A, and the true facet is the corner
  /// facet f_B + e_A.
  std::uint64_t edge_paper_rejections = 0;
  std::uint64_t predicate_filtered = 0;  ///< predicate calls the double filter answered
  std::uint64_t predicate_exact = 0;     ///< predicate calls that needed exact arithmetic
};

}  // namespace cvms
