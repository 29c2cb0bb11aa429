// SPDX-License-Identifier: MIT
// allocate_block and HugePageVector (lib/numeric/huge_page_blocks.hpp):
// every block is writable over its whole length and keeps what is written,
// blocks on huge pages are 2 MiB aligned, a vector keeps its contents while
// it grows across the threshold, and impossible sizes throw instead of
// crashing. ASan and valgrind check that each block is freed once and that
// nothing is read or written past its end (the sanitizer builds take
// operator new: huge_page_blocks.cpp).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <new>

#include "huge_page_blocks.hpp"

namespace cvms::detail {
namespace {

constexpr std::size_t MiB = std::size_t{1} << 20;

TEST(HugePageBlocks, EveryByteOfEverySizeIsUsable) {
  for (const std::size_t bytes : {std::size_t{1}, std::size_t{4096}, huge_page_threshold - 1, huge_page_threshold,
                                  huge_page_threshold + 1, 2 * MiB - 1, 2 * MiB, 2 * MiB + 1, 5 * MiB + 3}) {
    SCOPED_TRACE(bytes);
    auto* block = static_cast<unsigned char*>(allocate_block(bytes));
    ASSERT_NE(block, nullptr);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(block) % alignof(std::max_align_t), 0u);
    if (on_huge_pages(bytes)) {
      EXPECT_EQ(reinterpret_cast<std::uintptr_t>(block) % (2 * MiB), 0u);
    }
    for (std::size_t i = 0; i < bytes; ++i) block[i] = static_cast<unsigned char>(i * 7 + 3);
    bool kept = true;
    for (std::size_t i = 0; i < bytes; ++i) kept = kept && block[i] == static_cast<unsigned char>(i * 7 + 3);
    EXPECT_TRUE(kept);
    free_block(block, bytes);
  }
}

TEST(HugePageBlocks, OnlyLargeBlocksGoOnHugePages) {
  EXPECT_FALSE(on_huge_pages(0));
  EXPECT_FALSE(on_huge_pages(huge_page_threshold - 1));
}

TEST(HugePageBlocks, AVectorKeepsItsContentsAcrossTheThreshold) {
  HugePageVector<std::uint64_t> values;
  const std::size_t count = 3 * huge_page_threshold / sizeof(std::uint64_t) + 17;
  for (std::uint64_t i = 0; i < count; ++i) values.push_back(i * i + 1);
  ASSERT_EQ(values.size(), count);
  for (std::uint64_t i = 0; i < count; ++i) ASSERT_EQ(values[i], i * i + 1) << "at " << i;
  HugePageVector<std::uint64_t> copy = values;  // a second mapping, freed apart
  values.clear();
  values.shrink_to_fit();
  EXPECT_EQ(copy[count - 1], (count - 1) * (count - 1) + 1);
}

TEST(HugePageBlocks, AnUninitialisedArrayIsWritableWhereUsed) {
  HugePageArray<std::uint32_t> slots(huge_page_threshold);  // 4 bytes each: above the threshold
  slots[0] = 1;
  slots[huge_page_threshold - 1] = 2;
  EXPECT_EQ(slots[0] + slots[huge_page_threshold - 1], 3u);
}

TEST(HugePageBlocks, ImpossibleSizesThrow) {
  HugePageAllocator<std::uint64_t> allocator;
  EXPECT_THROW((void)allocator.allocate(std::numeric_limits<std::size_t>::max() / 4), std::bad_array_new_length);
  // Operator new under AddressSanitizer reports a size this large as an
  // error instead of throwing, so only the mapped path is asked.
  if (!on_huge_pages(std::size_t{1} << 62)) GTEST_SKIP() << "blocks come from operator new in this build";
  EXPECT_THROW((void)allocate_block(std::size_t{1} << 62), std::bad_alloc);
  EXPECT_THROW((void)allocate_block(std::numeric_limits<std::size_t>::max()), std::bad_alloc);
}

}  // namespace
}  // namespace cvms::detail
