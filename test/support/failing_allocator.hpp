// SPDX-License-Identifier: MIT
// A global operator new that fails on the k-th call once armed, for the
// allocation-failure sweep (test/allocation_failure_test.cpp): the practice
// of SQLite's malloc tests, which run each operation with the first, second,
// third ... allocation failing until it completes without reaching the
// failure, so that every path that unwinds from a failed allocation runs.
//
// Linked only into the sweep's executables (test/CMakeLists.txt keeps it out
// of cvms_test_support): it replaces every replaceable form of operator new
// and operator delete (plain, array, sized, aligned, nothrow) for the whole
// program. Disarmed, it is malloc and free. Armed, each call counts, and the
// k-th fails (throws std::bad_alloc, or returns null for the nothrow
// forms); with `persistent`, every later call fails as well, as when memory
// stays exhausted. The counter is one atomic for the whole process, so that
// allocations on worker threads count too, in an order that only a run on
// one thread makes repeatable.
//
// The library maps its largest blocks itself, past operator new, in
// optimised builds: the hook it calls for each (cvms_huge_pages_mapped) is
// defined here too, so that a sweep can check that it saw every block.
//
// GMP allocates through malloc (its own allocation functions), which this
// does not see: the library protects GMP by its memory budget, taken before
// the numbers are made, since GMP may not fail an allocation.
#pragma once

#include <cstdint>

namespace cvms::test {

/// While alive, the `fail_at`-th call of operator new from its construction
/// on fails (1 is the first), and with `persistent` every later one too.
/// One at a time (not reentrant); the destructor disarms.
class FailingAllocations {
 public:
  explicit FailingAllocations(std::uint64_t fail_at, bool persistent = false) noexcept;
  ~FailingAllocations();
  FailingAllocations(const FailingAllocations&) = delete;
  FailingAllocations& operator=(const FailingAllocations&) = delete;

  /// The calls of operator new counted since construction.
  [[nodiscard]] static std::uint64_t calls() noexcept;
  /// The calls that were made to fail since construction.
  [[nodiscard]] static std::uint64_t failures() noexcept;
  /// The blocks the library mapped on huge pages since construction,
  /// bypassing operator new (lib/numeric/huge_page_blocks.hpp): none where
  /// this build routes them through operator new (sanitizers,
  /// CVMS_HUGE_PAGE_BLOCKS=OFF) or the inputs are small.
  [[nodiscard]] static std::uint64_t mapped_blocks() noexcept;
};

/// Every call of operator new since the program started, armed or not (to
/// check that a path allocates at all).
[[nodiscard]] std::uint64_t total_allocations() noexcept;

}  // namespace cvms::test
