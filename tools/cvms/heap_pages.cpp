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
  constexpr int step = 256 << 20;                           // virtual: nothing is backed until touched
  constexpr int largest_heap_block = 32 << 20;              // glibc's maximum for M_MMAP_THRESHOLD
  // Blocks up to 32 MiB come from the heap (glibc would map each block above
  // 128 KiB on its own, 4 KiB pages again), the heap grows `step` beyond each
  // request, and free() keeps that much instead of returning it.
  if (mallopt(M_MMAP_THRESHOLD, largest_heap_block) == 0 || mallopt(M_TOP_PAD, step) == 0 ||
      mallopt(M_TRIM_THRESHOLD, 2 * step) == 0)
    return;
  // A block bigger than what is left at the heap's top makes it grow now.
  void* probe = std::malloc(1 << 20);
  if (probe == nullptr) return;
  const auto begin = (reinterpret_cast<std::uintptr_t>(probe) + huge - 1) & ~(huge - 1);
  const auto end = reinterpret_cast<std::uintptr_t>(sbrk(0)) & ~(huge - 1);
  std::free(probe);
  // The probe lies on the heap below the break unless glibc had to map it
  // elsewhere (no room to grow the heap): then nothing is advised.
  if (begin < end && reinterpret_cast<std::uintptr_t>(probe) < end)
    (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // fails harmlessly without THP
#endif
}

}  // namespace cvms::cli
