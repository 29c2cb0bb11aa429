// SPDX-License-Identifier: MIT
// What the algorithms count while they sum: the output's facets by kind
// (the public Stats) and the search's diagnostic counters (the public
// SumDiagnostics), filled in one place and handed out by minkowski_sum.
#pragma once

#include <cstdint>

#include "cvms/diagnostics.hpp"
#include "cvms/minkowski.hpp"

namespace cvms::detail {

struct SumCounters : SumDiagnostics {
  std::uint64_t translated_facets = 0;  ///< Stats::translated_facets
  std::uint64_t corner_facets = 0;      ///< Stats::corner_facets
  std::uint64_t edge_facets = 0;        ///< Stats::edge_facets

  /// The public counters, the deprecated copies of the diagnostics included.
  [[nodiscard]] Stats stats() const {
    Stats s;
    s.translated_facets = translated_facets;
    s.corner_facets = corner_facets;
    s.edge_facets = edge_facets;
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
    s.contributing_ties = contributing_ties;
    s.edge_candidates = edge_candidates;
    s.edge_paper_rejections = edge_paper_rejections;
    s.predicate_filtered = predicate_filtered;
    s.predicate_exact = predicate_exact;
#pragma GCC diagnostic pop
    return s;
  }
};

}  // namespace cvms::detail
