// SPDX-License-Identifier: MIT
/// \file
/// Peak live heap bytes of a measured region, for the benchmarks' memory
/// column. Linking heap_counter.cpp into a program replaces the global
/// operator new/delete (every form) and installs GMP's allocation functions
/// (mp_set_memory_functions), so both C++ containers and the limbs of
/// mpz/mpq numbers are counted, and so are the library's large blocks on
/// huge pages (cvms_huge_pages_mapped, lib/numeric/huge_page_blocks.hpp).
/// Memory that a library takes with malloc directly (qhull) is not seen.
///
/// The counters are per thread (no atomics on the allocation path): the
/// benchmarks are single-threaded. Bytes are the sizes requested, without
/// the allocator's own overhead.
#pragma once

#include <cstddef>
#include <cstdint>

namespace cvms_bench {

/// Starts a measured region on this thread: peak_heap_bytes() counts from
/// the live bytes of this moment.
void reset_heap_peak() noexcept;
/// The largest number of live heap bytes above the level at the last
/// reset_heap_peak() on this thread.
std::size_t peak_heap_bytes() noexcept;
/// Live heap bytes on this thread, relative to the level at the last
/// reset_heap_peak() (negative when more was freed than allocated since).
std::int64_t live_heap_bytes() noexcept;

}  // namespace cvms_bench
