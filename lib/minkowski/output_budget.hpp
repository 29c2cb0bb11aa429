// SPDX-License-Identifier: MIT
// The bound on a Minkowski sum's output decided before the memory is spent
// (the output can be quadratic in the input). CVMS and ESSDMS know the number of translated and
// corner facets exactly after their contributing-vertex searches, before
// anything of the exact output exists, and count the edge facets as they
// find them; each count is checked here against SumLimits, so that a sum
// beyond the limits stops with Error(limit) once its running count passes
// the budget. Until then the searches hold 48 bytes per facet found (the
// builder's index pairs), a small part of what the output would need.
#pragma once

#include <cstdint>
#include <string>

#include "cvms/minkowski.hpp"

namespace cvms::detail {

/// The most facets a sum may have under `limits`, and the check of a count
/// against it.
class OutputBudget {
 public:
  /// `algorithm` names the caller in messages ("cvms", "essdms").
  OutputBudget(const SumLimits& limits, const char* algorithm);

  /// min(max_output_facets, max_memory_bytes / bytes_per_output_facet).
  [[nodiscard]] std::uint64_t max_facets() const noexcept { return max_facets_; }

  /// \throw Error(limit) if translated + corner + edge facets exceed
  ///   max_facets(). The counts are those found so far: the message says
  ///   the sum has at least their total.
  void check(std::uint64_t translated, std::uint64_t corner, std::uint64_t edge) const;

  /// \throw Error(limit) if `facets` exceed max_facets(), with the message
  ///   `what` (which states the count) followed by the limit that binds and
  ///   the SumLimits field to raise. For the sums of convex sets, which
  ///   count their output facets their own way (lib/sets/).
  void check_count(std::uint64_t facets, const std::string& what) const;

 private:
  SumLimits limits_;
  const char* algorithm_;
  std::uint64_t max_facets_;
};

/// a x b, saturating at 2^64 - 1 (counts of pairs of input features).
[[nodiscard]] std::uint64_t saturating_product(std::uint64_t a, std::uint64_t b) noexcept;
/// a + b, saturating at 2^64 - 1.
[[nodiscard]] std::uint64_t saturating_sum(std::uint64_t a, std::uint64_t b) noexcept;

}  // namespace cvms::detail
