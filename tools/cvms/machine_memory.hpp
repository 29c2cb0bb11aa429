// SPDX-License-Identifier: MIT
// The command-line tool's defaults for its memory budget (a sum's output
// limits, and the memory its inputs may take: input_memory.hpp), fitted to
// the machine and the process it runs in: a sum or an input too big for them
// must end in a `limit` error naming the option, never in the kernel's OOM
// killer, and never in a failed allocation inside GMP, which aborts the
// process (GMP's allocation functions must not return on failure, and
// throwing from them is undefined).
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

/// Address space the tool keeps for itself under an address-space limit: its
/// code, libraries, stacks and allocator arenas, which the budget does not
/// count (a small run peaks near 20 MiB).
inline constexpr std::uint64_t program_address_space = std::uint64_t{64} << 20;

/// The memory a process may use given what can be read of its machine: the
/// smallest of the physical memory, the cgroup (container) limit and the
/// address-space limit (RLIMIT_AS, `ulimit -v`) less program_address_space
/// (never less than 4 MiB, so a limit too small for the program still gives
/// a budget that refuses rather than the library's); nullopt when none is known.
std::optional<std::uint64_t> usable_memory_bytes(std::optional<std::uint64_t> physical,
                                                 std::optional<std::uint64_t> cgroup,
                                                 std::optional<std::uint64_t> address_space);

/// The soft address-space limit of this process (getrlimit(RLIMIT_AS)),
/// nullopt when unlimited or unknown.
std::optional<std::uint64_t> address_space_limit();

/// usable_memory_bytes of this machine and process.
std::optional<std::uint64_t> usable_memory_bytes();

/// The library's SumLimits, with max_memory_bytes lowered to half of `usable`
/// (rounded down to whole MiB) where that is less than the library's 4 GiB:
/// the estimate covers the output only, and the operands and the search's
/// working memory come on top. It is not raised on bigger machines: the
/// search that finds a sum too big runs until the count passes the budget
/// (about 0.5 us per facet), so a bigger default would only make the refusal
/// of a hostile pair slower; users raise it with --max-memory.
/// Unchanged when `usable` is unknown or below 4 MiB.
SumLimits sum_limits_for_memory(std::optional<std::uint64_t> usable);

}  // namespace cvms::cli
