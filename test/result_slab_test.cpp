// SPDX-License-Identifier: MIT
// ResultSlab, SlabPlan and KeptAllocator (lib/numeric/result_slab.hpp,
// kept_allocator.hpp): carved arrays are aligned, disjoint and inside
// the slab, a plan is exactly what its arrays carve, what does not fit gets
// a block of its own with its contents intact, copies never carve, and the
// slab lives exactly as long as the last array carved from it. Whether a
// sum's output is carved from its slabs is asked in arena_storage_test.
#include "result_slab.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <thread>
#include <utility>
#include <vector>

#include "huge_page_blocks.hpp"

namespace cvms::detail {
namespace {

TEST(SlabPlan, RoundsEachArrayToACacheLine) {
  SlabPlan plan;
  plan.add<std::uint32_t>(3).add<char>(65).add<std::uint64_t>(8).add<double>(0);
  EXPECT_EQ(plan.bytes(), 64u + 128u + 64u);
}

TEST(SlabPlan, AbsurdCountsSaturateAndAllocationRefusesThem) {
  SlabPlan plan;
  plan.add<std::uint64_t>(std::numeric_limits<std::size_t>::max() / 4).add<char>(1);
  EXPECT_EQ(plan.bytes(), std::numeric_limits<std::size_t>::max());
  if (!huge_page_blocks_enabled()) GTEST_SKIP() << "operator new under a sanitizer reports, not throws";
  EXPECT_THROW((void)ResultSlab::make(plan), std::bad_alloc);
}

TEST(ResultSlab, CarvesAlignedDisjointPiecesUntilFull) {
  for (const std::size_t bytes : {std::size_t{640}, kept_threshold + 4096, 5 * kept_threshold / 2}) {
    SCOPED_TRACE(bytes);
    SlabPlan plan;
    plan.add<char>(bytes);
    const auto slab = ResultSlab::make(plan);
    ASSERT_EQ(slab->size(), bytes);
    EXPECT_FALSE(slab->refused());
    std::vector<std::pair<unsigned char*, std::size_t>> pieces;
    std::size_t total = 0;
    for (std::size_t k = 1;; ++k) {
      const std::size_t length = 37 * k;
      auto* piece = static_cast<unsigned char*>(slab->carve(length));
      const std::size_t rounded =
          (length + slab_block_alignment - 1) / slab_block_alignment * slab_block_alignment;
      if (piece == nullptr) {
        EXPECT_GT(total + rounded, bytes) << "refused a piece that fits";
        break;
      }
      EXPECT_EQ(reinterpret_cast<std::uintptr_t>(piece) % slab_block_alignment, 0u);
      EXPECT_TRUE(slab->holds(piece));
      EXPECT_TRUE(slab->holds(piece + length - 1));
      std::fill(piece, piece + length, static_cast<unsigned char>(k));
      pieces.emplace_back(piece, length);
      total += rounded;
      EXPECT_EQ(slab->carved(), total);
    }
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const auto [piece, length] = pieces[k];
      EXPECT_TRUE(std::all_of(piece, piece + length,
                              [&](unsigned char c) { return c == static_cast<unsigned char>(k + 1); }))
          << "piece " << k << " was overwritten";
    }
    EXPECT_TRUE(slab->refused());
    EXPECT_EQ(slab->carve(1), nullptr) << "a refusal leaves nothing to carve";
    EXPECT_EQ(slab->carved(), total);
    EXPECT_EQ(slab->carve(0), nullptr);
    unsigned char outside = 0;
    EXPECT_FALSE(slab->holds(&outside));
  }
}

TEST(ResultSlab, ThreadsCarveDisjointPieces) {
  constexpr std::size_t per_thread = 2000, threads = 4;
  SlabPlan plan;
  for (std::size_t i = 0; i < per_thread * threads; ++i) plan.add<std::uint64_t>(1 + i % 5);
  const auto slab = ResultSlab::make(plan);
  std::vector<std::vector<std::uint64_t*>> carved(threads);
  std::vector<std::thread> workers;
  for (std::size_t t = 0; t < threads; ++t)
    workers.emplace_back([&, t] {
      for (std::size_t i = t; i < per_thread * threads; i += threads) {
        auto* piece = static_cast<std::uint64_t*>(slab->carve(sizeof(std::uint64_t) * (1 + i % 5)));
        if (piece != nullptr) std::fill(piece, piece + 1 + i % 5, i);
        carved[t].push_back(piece);
      }
    });
  for (std::thread& w : workers) w.join();
  EXPECT_EQ(slab->carved(), slab->size());
  EXPECT_FALSE(slab->refused());
  for (std::size_t t = 0; t < threads; ++t)
    for (std::size_t k = 0; k < carved[t].size(); ++k) {
      const std::size_t i = t + k * threads;
      ASSERT_NE(carved[t][k], nullptr) << "piece " << i << " was refused though the plan had room";
      EXPECT_TRUE(
          std::all_of(carved[t][k], carved[t][k] + 1 + i % 5, [&](std::uint64_t x) { return x == i; }))
          << "piece " << i << " overlaps another";
    }
}

TEST(KeptAllocator, PlannedVectorsAreCarvedAndGrowOutOfTheSlabIntact) {
  SlabPlan plan;
  plan.add<std::uint32_t>(1000).add<double>(3000);
  auto slab = ResultSlab::make(plan);
  KeptVector<std::uint32_t> small{KeptAllocator<std::uint32_t>(slab)};
  KeptVector<double> large{KeptAllocator<double>(slab)};
  small.reserve(1000);
  large.resize(3000, 0.5);
  EXPECT_TRUE(slab->holds(small.data()));
  EXPECT_TRUE(slab->holds(large.data()));
  EXPECT_EQ(slab->carved(), slab->size());
  EXPECT_FALSE(slab->refused());
  for (std::uint32_t i = 0; i < 5000; ++i) small.push_back(i * 7);  // past its room: a block of its own
  EXPECT_FALSE(slab->holds(small.data()));
  EXPECT_TRUE(slab->refused());
  for (std::uint32_t i = 0; i < 5000; ++i) ASSERT_EQ(small[i], i * 7) << "at " << i;
  EXPECT_EQ(large[2999], 0.5);
}

TEST(KeptAllocator, CopiesOwnTheirStorageAndTheSlabGoesWithItsLastArray) {
  SlabPlan plan;
  plan.add<int>(100).add<int>(100);
  auto slab = ResultSlab::make(plan);
  const std::weak_ptr<ResultSlab> watch = slab;
  KeptVector<int> first(100, 1, KeptAllocator<int>(slab));
  KeptVector<int> second(100, 2, KeptAllocator<int>(slab));
  slab.reset();  // the arrays keep it
  ASSERT_FALSE(watch.expired());
  const KeptVector<int> copy = first;
  EXPECT_EQ(copy.get_allocator().slab(), nullptr);
  EXPECT_FALSE(watch.lock()->holds(copy.data()));
  KeptVector<int> moved = std::move(first);
  EXPECT_TRUE(watch.lock()->holds(moved.data()));
  first = KeptVector<int>();
  moved = KeptVector<int>();  // move-assigned: the allocator (and the slab) goes too
  EXPECT_FALSE(watch.expired()) << "second still holds it";
  const KeptVector<int> longer(300, 3);
  second = longer;  // copy-assigned: second keeps its allocator, which has no room left
  EXPECT_FALSE(watch.lock()->holds(second.data()));
  EXPECT_EQ(second[299], 3);
  second = KeptVector<int>();
  EXPECT_TRUE(watch.expired());
  EXPECT_EQ(copy[99], 1);
}

}  // namespace
}  // namespace cvms::detail
