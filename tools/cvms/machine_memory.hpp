// SPDX-License-Identifier: MIT
// The command-line tool's defaults for a sum's output limits, fitted to the
// machine it runs on: a sum too big for the machine must end in a `limit`
// error naming the option, never in the kernel's OOM killer.
//
// The library's own defaults (SumLimits: 4 GiB) stay fixed on purpose: a
// library must not consult the machine behind its caller's back, and what it
// accepts must not depend on where it runs. The tool is the caller that knows
// it owns the machine, so it measures it.
#pragma once

#include <cstdint>
#include <optional>

#include "cvms/minkowski.hpp"

namespace cvms::cli {

/// The memory this process may use: the physical memory, or a smaller cgroup
/// (container) limit when one is set; nullopt where neither can be read.
std::optional<std::uint64_t> usable_memory_bytes();

/// The library's SumLimits, with max_memory_bytes lowered to half of `usable`
/// (rounded down to whole MiB) on a machine with less than twice the
/// library's 4 GiB: the estimate covers the output only, and the operands and
/// the search's working memory come on top. It is not raised on bigger
/// machines: the search that finds a sum too big runs until the count passes
/// the budget (about 0.5 us per facet), so a bigger default would only make
/// the refusal of a hostile pair slower; users raise it with --max-memory.
/// Unchanged when `usable` is unknown or below 4 MiB.
SumLimits sum_limits_for_memory(std::optional<std::uint64_t> usable);

}  // namespace cvms::cli
