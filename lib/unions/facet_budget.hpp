// SPDX-License-Identifier: MIT
// The output facets a union of sums may have in all (SumLimits: the facet
// limit, and the memory limit at SumLimits::bytes_per_output_facet per
// facet), and the words that name whichever of the two is the bound, for
// the limit errors of the sums that make many pieces.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>

#include "cvms/minkowski.hpp"

namespace cvms::detail {

/// The most output facets in all that `limits` allow.
inline std::uint64_t facet_budget(const SumLimits& limits) {
  return std::min(limits.max_output_facets, limits.max_memory_bytes / SumLimits::bytes_per_output_facet);
}

/// "<n> facets (SumLimits::max_output_facets)" or "<n> bytes
/// (SumLimits::max_memory_bytes, at <b> bytes per facet)", whichever sets
/// facet_budget.
inline std::string facet_limit_text(const SumLimits& limits) {
  if (limits.max_memory_bytes / SumLimits::bytes_per_output_facet < limits.max_output_facets)
    return std::to_string(limits.max_memory_bytes) + " bytes (SumLimits::max_memory_bytes, at " +
           std::to_string(SumLimits::bytes_per_output_facet) + " bytes per facet)";
  return std::to_string(limits.max_output_facets) + " facets (SumLimits::max_output_facets)";
}

}  // namespace cvms::detail
