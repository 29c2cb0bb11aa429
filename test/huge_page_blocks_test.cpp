// SPDX-License-Identifier: MIT
// allocate_block, ScratchVector, KeptVector and HugePageArray
// (lib/numeric/huge_page_blocks.hpp): every block is writable over its whole
// length and keeps what is written while other blocks come and go, mapped
// blocks start at a 2 MiB boundary and are wholly unmapped when freed, a
// vector keeps its contents while it grows across the thresholds, and
// impossible sizes throw instead of crashing. Builds under ASan take operator
// new for every block (ASan then checks bounds and frees); the mapped path is
// checked here and by the suites that run on it.
#include <gtest/gtest.h>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

#include <cerrno>
#include <cstdint>
#include <limits>
#include <new>
#include <utility>
#include <vector>

#include "huge_page_blocks.hpp"

namespace cvms::detail {
namespace {

constexpr std::size_t MiB = std::size_t{1} << 20;
constexpr BlockLife lives[] = {BlockLife::scratch, BlockLife::kept, BlockLife::slab};

unsigned char pattern(std::size_t i, std::size_t seed) { return static_cast<unsigned char>(i * 7 + seed); }

void fill(unsigned char* block, std::size_t bytes, std::size_t seed) {
  for (std::size_t i = 0; i < bytes; ++i) block[i] = pattern(i, seed);
}

bool holds(const unsigned char* block, std::size_t bytes, std::size_t seed) {
  for (std::size_t i = 0; i < bytes; ++i)
    if (block[i] != pattern(i, seed)) return false;
  return true;
}

#if defined(__linux__)
std::size_t page_bytes() { return static_cast<std::size_t>(sysconf(_SC_PAGESIZE)); }

// Whether the page at `address` is mapped: mincore fails with ENOMEM exactly
// on unmapped ranges.
bool page_mapped(const unsigned char* address) {
  unsigned char residency = 0;
  const auto page = reinterpret_cast<std::uintptr_t>(address) & ~std::uintptr_t{page_bytes() - 1};
  return mincore(reinterpret_cast<void*>(page), 1, &residency) == 0 || errno != ENOMEM;
}

// The length a mapped block takes (huge_page_blocks.hpp): whole huge pages
// for scratch, and for a slab when they add at most a quarter.
std::size_t mapped_length(std::size_t bytes, BlockLife life) {
  const std::size_t huge = 2 * MiB, whole_huge_pages = (bytes + huge - 1) / huge * huge;
  if (life == BlockLife::scratch || (life == BlockLife::slab && 4 * (whole_huge_pages - bytes) <= bytes))
    return whole_huge_pages;
  return (bytes + page_bytes() - 1) / page_bytes() * page_bytes();
}
#endif

const std::vector<std::size_t> sizes = {1,
                                        4096,
                                        scratch_threshold - 1,
                                        scratch_threshold,
                                        scratch_threshold + 1,
                                        kept_threshold - 1,
                                        kept_threshold,
                                        kept_threshold + 1,
                                        5 * MiB + 3};

TEST(HugePageBlocks, EveryByteOfEverySizeIsUsableWhileOthersComeAndGo) {
  for (const BlockLife life : lives) {
    std::vector<std::pair<unsigned char*, std::size_t>> alive;
    for (std::size_t k = 0; k < sizes.size(); ++k) {
      SCOPED_TRACE(sizes[k]);
      auto* block = static_cast<unsigned char*>(allocate_block(sizes[k], life));
      ASSERT_NE(block, nullptr);
      EXPECT_EQ(reinterpret_cast<std::uintptr_t>(block) % alignof(std::max_align_t), 0u);
      if (life == BlockLife::slab) {
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(block) % slab_block_alignment, 0u);
      }
      if (on_huge_pages(sizes[k], life)) {
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(block) % (2 * MiB), 0u);
      }
      fill(block, sizes[k], k);
      alive.emplace_back(block, sizes[k]);
      if (k % 3 == 2) {  // free every third block's predecessor: its neighbours must be unharmed
        auto [freed, bytes] = alive[alive.size() - 2];
        free_block(freed, bytes, life);
        alive.erase(alive.end() - 2);
      }
    }
    for (std::size_t k = 0; k < alive.size(); ++k) {
      const auto [block, bytes] = alive[k];
      std::size_t seed = 0;
      while (sizes[seed] != bytes) ++seed;
      EXPECT_TRUE(holds(block, bytes, seed)) << "block of " << bytes << " bytes";
      free_block(block, bytes, life);
    }
  }
}

TEST(HugePageBlocks, AMappedBlockHasItsLengthAndIsWhollyUnmappedWhenFreed) {
#if defined(__linux__)
  for (const BlockLife life : lives) {
    for (const std::size_t bytes : {scratch_threshold, scratch_threshold + 5000, kept_threshold,
                                    kept_threshold + 5000, 5 * MiB + 3, 7 * MiB}) {
      if (!on_huge_pages(bytes, life)) continue;
      SCOPED_TRACE(bytes);
      auto* block = static_cast<unsigned char*>(allocate_block(bytes, life));
      const std::size_t length = mapped_length(bytes, life);
      // The alignment slack around the block was given back; the block's
      // own rounding was not.
      EXPECT_TRUE(page_mapped(block + length - 1));
      EXPECT_FALSE(page_mapped(block + length));
      fill(block, bytes, 1);
      free_block(block, bytes, life);
      bool any_mapped = false;
      for (std::size_t offset = 0; offset < length; offset += page_bytes())
        any_mapped = any_mapped || page_mapped(block + offset);
      EXPECT_FALSE(any_mapped);
    }
  }
#else
  GTEST_SKIP() << "blocks are mapped on Linux only";
#endif
}

TEST(HugePageBlocks, LinuxBuildsWithoutSanitizersMapLargeBlocks) {
#if !defined(CVMS_BLOCKS_ON_HEAP_ONLY) && defined(MADV_HUGEPAGE)
  EXPECT_TRUE(huge_page_blocks_enabled());
#endif
  EXPECT_EQ(on_huge_pages(scratch_threshold, BlockLife::scratch), huge_page_blocks_enabled());
  EXPECT_EQ(on_huge_pages(kept_threshold, BlockLife::kept), huge_page_blocks_enabled());
  EXPECT_EQ(on_huge_pages(kept_threshold, BlockLife::slab), huge_page_blocks_enabled());
  EXPECT_FALSE(on_huge_pages(kept_threshold - 1, BlockLife::slab));
  EXPECT_FALSE(on_huge_pages(scratch_threshold - 1, BlockLife::scratch));
  EXPECT_FALSE(on_huge_pages(kept_threshold - 1, BlockLife::kept));
}

TEST(HugePageBlocks, VectorsKeepTheirContentsAcrossTheThresholds) {
  ScratchVector<std::uint64_t> scratch;
  KeptVector<std::uint64_t> kept;
  const std::size_t count = 3 * kept_threshold / sizeof(std::uint64_t) + 17;
  for (std::uint64_t i = 0; i < count; ++i) {
    scratch.push_back(i * i + 1);
    kept.push_back(i * 3 + 2);
  }
  ASSERT_EQ(scratch.size(), count);
  for (std::uint64_t i = 0; i < count; ++i) {
    ASSERT_EQ(scratch[i], i * i + 1) << "at " << i;
    ASSERT_EQ(kept[i], i * 3 + 2) << "at " << i;
  }
  ScratchVector<std::uint64_t> copy = scratch;  // a second mapping, freed apart
  scratch.clear();
  scratch.shrink_to_fit();
  EXPECT_EQ(copy[count - 1], (count - 1) * (count - 1) + 1);
}

TEST(HugePageBlocks, UninitialisedArraysMoveTheirBlocks) {
  HugePageArray<std::uint32_t, BlockLife::scratch> slots(
      scratch_threshold);  // 4 bytes each: above the threshold
  slots[0] = 1;
  slots[scratch_threshold - 1] = 2;
  HugePageArray<std::uint32_t, BlockLife::scratch> other(3);
  other[2] = 5;
  other = std::move(slots);  // other's old block is freed, slots is left empty
  EXPECT_EQ(other[0] + other[scratch_threshold - 1], 3u);
  HugePageArray<std::uint32_t, BlockLife::scratch> moved(std::move(other));
  EXPECT_EQ(moved[scratch_threshold - 1], 2u);
}

TEST(HugePageBlocks, ImpossibleSizesThrow) {
  HugePageAllocator<std::uint64_t, BlockLife::scratch> allocator;
  EXPECT_THROW((void)allocator.allocate(std::numeric_limits<std::size_t>::max() / 4),
               std::bad_array_new_length);
  // Operator new under AddressSanitizer reports a size this large as an
  // error instead of throwing, so only the mapped path is asked.
  if (!huge_page_blocks_enabled()) GTEST_SKIP() << "blocks come from operator new in this build";
  for (const BlockLife life : lives) {
    EXPECT_THROW((void)allocate_block(std::size_t{1} << 62, life), std::bad_alloc);
    EXPECT_THROW((void)allocate_block(std::numeric_limits<std::size_t>::max(), life), std::bad_alloc);
  }
}

}  // namespace
}  // namespace cvms::detail
