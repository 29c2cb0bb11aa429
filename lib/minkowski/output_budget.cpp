// SPDX-License-Identifier: MIT
// The output budget of a Minkowski sum and its limit messages (see
// output_budget.hpp).
#include "output_budget.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "cvms/error.hpp"

namespace cvms::detail {

std::uint64_t saturating_product(std::uint64_t a, std::uint64_t b) noexcept {
  if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a) return std::numeric_limits<std::uint64_t>::max();
  return a * b;
}

std::uint64_t saturating_sum(std::uint64_t a, std::uint64_t b) noexcept {
  return b > std::numeric_limits<std::uint64_t>::max() - a ? std::numeric_limits<std::uint64_t>::max() : a + b;
}

OutputBudget::OutputBudget(const SumLimits& limits, const char* algorithm)
    : limits_(limits),
      algorithm_(algorithm),
      max_facets_(std::min(limits.max_output_facets, limits.max_memory_bytes / SumLimits::bytes_per_output_facet)) {}

void OutputBudget::check(std::uint64_t translated, std::uint64_t corner, std::uint64_t edge) const {
  const std::uint64_t facets = saturating_sum(saturating_sum(translated, corner), edge);
  if (facets <= max_facets_) return;
  check_count(facets, std::string("minkowski_sum (") + algorithm_ + "): the sum has at least " +
                          std::to_string(facets) + " facets (" + std::to_string(translated) + " translated, " +
                          std::to_string(corner) + " corner and " + std::to_string(edge) +
                          " edge facets counted when the search stopped)");
}

void OutputBudget::check_count(std::uint64_t facets, const std::string& what) const {
  if (facets <= max_facets_) return;
  std::string message = what + ", ";
  // Name the limit that binds: the facet count, or the memory it implies.
  if (limits_.max_output_facets <= limits_.max_memory_bytes / SumLimits::bytes_per_output_facet) {
    message += "beyond the limit of " + std::to_string(limits_.max_output_facets) +
               " facets (SumLimits::max_output_facets)";
  } else {
    message += "which need about " +
               std::to_string(saturating_product(facets, SumLimits::bytes_per_output_facet)) + " bytes (" +
               std::to_string(SumLimits::bytes_per_output_facet) + " per facet), beyond the limit of " +
               std::to_string(limits_.max_memory_bytes) + " bytes (SumLimits::max_memory_bytes)";
  }
  throw Error(ErrorCategory::limit, message);
}

}  // namespace cvms::detail
