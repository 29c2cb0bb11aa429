// SPDX-License-Identifier: MIT
// The tool's machine- and process-fitted memory budget (see machine_memory.hpp).
#include "machine_memory.hpp"

#include <algorithm>
#include <fstream>
#include <string>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/resource.h>
#include <unistd.h>
#endif

namespace cvms::cli {
namespace {

std::optional<std::uint64_t> physical_memory_bytes() {
#if defined(_SC_PHYS_PAGES) && defined(_SC_PAGESIZE)
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGESIZE);
  if (pages > 0 && page_size > 0) return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size);
#endif
  return std::nullopt;
}

// cgroup v2 writes "max" when unlimited; anything unreadable counts as no limit.
std::optional<std::uint64_t> cgroup_memory_limit() {
  std::ifstream in("/sys/fs/cgroup/memory.max");
  std::string text;
  if (!(in >> text) || text.empty() || text.find_first_not_of("0123456789") != std::string::npos ||
      text.size() > 19)
    return std::nullopt;
  return std::stoull(text);
}

}  // namespace

std::optional<std::uint64_t> usable_memory_bytes(std::optional<std::uint64_t> physical,
                                                 std::optional<std::uint64_t> cgroup,
                                                 std::optional<std::uint64_t> address_space) {
  constexpr std::uint64_t least = std::uint64_t{4} << 20;
  std::optional<std::uint64_t> usable = physical;
  const auto lower_to = [&usable](std::uint64_t bytes) {
    if (!usable || bytes < *usable) usable = bytes;
  };
  if (cgroup) lower_to(*cgroup);
  if (address_space)
    lower_to(*address_space > program_address_space + least ? *address_space - program_address_space : least);
  return usable;
}

std::optional<std::uint64_t> address_space_limit() {
#if defined(RLIMIT_AS)
  struct rlimit limit {};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    return static_cast<std::uint64_t>(limit.rlim_cur);
#endif
  return std::nullopt;
}

std::optional<std::uint64_t> usable_memory_bytes() {
  return usable_memory_bytes(physical_memory_bytes(), cgroup_memory_limit(), address_space_limit());
}

SumLimits sum_limits_for_memory(std::optional<std::uint64_t> usable) {
  SumLimits limits;
  // Whole MiB, so that --help shows a short size ("12046M").
  constexpr std::uint64_t mebibyte = std::uint64_t{1} << 20;
  if (usable && *usable >= 4 * mebibyte)
    limits.max_memory_bytes = std::min(limits.max_memory_bytes, *usable / 2 / mebibyte * mebibyte);
  return limits;
}

}  // namespace cvms::cli
