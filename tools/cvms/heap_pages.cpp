// SPDX-License-Identifier: MIT
// See heap_pages.hpp.
#include "heap_pages.hpp"

#include <cstdint>
#include <cstdlib>  // first: it defines __GLIBC__, tested below

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace cvms::cli {

void prefer_huge_heap_pages() noexcept {
#if defined(__linux__) && defined(__GLIBC__)
  constexpr std::uintptr_t huge = std::uintptr_t{2} << 20;  // x86-64 and most arm64 kernels
  constexpr int reserve = 64 << 20;             // virtual: nothing is backed until touched
  constexpr int largest_heap_block = 32 << 20;  // glibc's maximum for M_MMAP_THRESHOLD
  constexpr int default_top_pad = 128 << 10;    // glibc's
  // Blocks up to 32 MiB come from the heap (glibc would map each block above
  // 128 KiB on its own, with 4 KiB pages again), and free() does not give
  // the advised region back (a heap regrown there would not be advised).
  if (mallopt(M_MMAP_THRESHOLD, largest_heap_block) == 0 || mallopt(M_TRIM_THRESHOLD, 2 * reserve) == 0) return;
  // The next growth of the heap reserves `reserve` beyond the probe; later
  // growths are glibc's usual small steps again (ordinary pages).
  if (mallopt(M_TOP_PAD, reserve) == 0) return;
  void* probe = std::malloc(1 << 20);  // more than is left at the heap's top: it grows now
  (void)mallopt(M_TOP_PAD, default_top_pad);
  if (probe == nullptr) return;
  const auto at = reinterpret_cast<std::uintptr_t>(probe);
  const auto begin = (at + huge - 1) & ~(huge - 1);
  const auto end = reinterpret_cast<std::uintptr_t>(sbrk(0)) & ~(huge - 1);
  std::free(probe);
  // The probe lies on the heap below the break unless glibc had to map it
  // elsewhere (no room to grow the heap): then nothing is advised.
  if (at < end && begin < end)
    (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // fails harmlessly without THP
#endif
}

}  // namespace cvms::cli
