// SPDX-License-Identifier: MIT
// See heap_pages.hpp.
#include "heap_pages.hpp"

#include <climits>
#include <cstdint>
#include <cstdlib>  // first: it defines __GLIBC__, tested below

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace cvms::cli {

#if defined(__linux__) && defined(__GLIBC__)
namespace {
// The block that covers the heap below its first huge page (see below),
// held for the process's life: reachable, for leak checkers, and volatile,
// or the compiler drops an allocation that nothing reads.
void* volatile below_first_huge_page = nullptr;
}  // namespace
#endif

void prefer_huge_heap_pages() noexcept {
#if defined(__linux__) && defined(__GLIBC__)
  constexpr std::uintptr_t huge = std::uintptr_t{2} << 20;  // x86-64 and most arm64 kernels
  // Address space: nothing is backed until touched, but it counts against
  // RLIMIT_AS/RLIMIT_DATA and strict overcommit; where the heap cannot grow
  // that far, the probe below is mapped elsewhere and nothing is advised.
  // It covers the peak heap of the largest benchmark sum (Sphere6 + rotated
  // Sphere6, 74 MiB) with room to spare.
  constexpr int reserve = 256 << 20;
  static_assert(reserve <= INT_MAX / 2, "M_TRIM_THRESHOLD takes 2 * reserve as an int");
  constexpr int largest_heap_block = 32 << 20;  // glibc's maximum for M_MMAP_THRESHOLD (64-bit)
  constexpr int default_top_pad = 128 << 10;    // glibc's
  // Blocks up to 32 MiB come from the heap (glibc would map each block above
  // 128 KiB on its own, with 4 KiB pages again), and free() does not give
  // the advised region back (a heap regrown there would not be advised).
  if (mallopt(M_MMAP_THRESHOLD, largest_heap_block) == 0 || mallopt(M_TRIM_THRESHOLD, 2 * reserve) == 0) return;
  // The next growth of the heap reserves `reserve` beyond the probe; later
  // growths are glibc's usual small steps again (ordinary pages).
  if (mallopt(M_TOP_PAD, reserve) == 0) return;
  constexpr std::uintptr_t probe_size = 1 << 20;  // more than is left at the heap's top: it grows now
  const auto old_break = reinterpret_cast<std::uintptr_t>(sbrk(0));
  void* probe = std::malloc(probe_size);
  (void)mallopt(M_TOP_PAD, default_top_pad);
  if (probe == nullptr) return;
  const auto at = reinterpret_cast<std::uintptr_t>(probe);
  // glibc wrote the header of the heap's new top just past the probe. That
  // page is backed already (an ordinary one), and a 2 MiB window with one
  // ordinary page in it never gets a huge page: the advice starts at the
  // first window after it.
  const std::uintptr_t touched_end = at + probe_size + std::uintptr_t{4096};
  const auto begin = (touched_end + huge - 1) & ~(huge - 1);
  const auto end = reinterpret_cast<std::uintptr_t>(sbrk(0)) & ~(huge - 1);
  std::free(probe);
  // The probe straddles the old break when it grew the heap; if glibc had to
  // map it elsewhere (no room to grow the heap), or another allocator serves
  // malloc (valgrind), nothing is advised or held.
  if (!(at <= old_break && old_break < at + probe_size && begin < end)) return;
  if (madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE) != 0) return;  // no THP
  // The freed probe went back to the top of the heap, from which glibc
  // carves new blocks in address order: the next ones would fill [at, begin)
  // first, 1 to 3 MiB of ordinary pages below the first huge one (a fault
  // each: hundreds for `cvms check sphere6.off`, depending on where the
  // randomised heap starts). A block that lives as long as the process
  // takes that stretch; of its pages only its first (the probe's header)
  // and the one that held the top's header are ever backed. (Were there
  // fastbin blocks, free() would consolidate them and the top would start a
  // little lower: then a page or two below `begin` serve small blocks.)
  below_first_huge_page = std::malloc(begin - at);
#endif
}

}  // namespace cvms::cli
