// SPDX-License-Identifier: MIT
// The tool's machine-fitted sum limits (tools/cvms/machine_memory.hpp: a
// sum's output can be quadratic in its input) and its inputs' memory
// estimate (input_memory.hpp), on hand-picked memory sizes and address-space
// limits.
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>

#include "input_memory.hpp"
#include "machine_memory.hpp"

namespace {

constexpr std::uint64_t MiB = std::uint64_t{1} << 20;
constexpr std::uint64_t GiB = std::uint64_t{1} << 30;

TEST(CliMachineMemory, SmallMachinesGetHalfTheirMemoryInWholeMiB) {
  EXPECT_EQ(cvms::cli::sum_limits_for_memory(2 * GiB).max_memory_bytes, 1 * GiB);
  EXPECT_EQ(cvms::cli::sum_limits_for_memory(512 * MiB + 3 * MiB + 12345).max_memory_bytes, 257 * MiB);
  EXPECT_EQ(cvms::cli::sum_limits_for_memory(4 * MiB).max_memory_bytes, 2 * MiB);
  EXPECT_EQ(cvms::cli::sum_limits_for_memory(8 * GiB - MiB).max_memory_bytes, 4 * GiB - MiB);
}

TEST(CliMachineMemory, BigOrUnknownMachinesKeepTheLibraryDefaults) {
  const cvms::SumLimits library;
  for (const auto usable : {std::optional<std::uint64_t>{}, std::optional<std::uint64_t>{8 * GiB},
                            std::optional<std::uint64_t>{24 * GiB}, std::optional<std::uint64_t>{4 * MiB - 1},
                            std::optional<std::uint64_t>{0}}) {
    const cvms::SumLimits limits = cvms::cli::sum_limits_for_memory(usable);
    EXPECT_EQ(limits.max_memory_bytes, library.max_memory_bytes) << usable.value_or(0);
    EXPECT_EQ(limits.max_output_facets, library.max_output_facets);
    EXPECT_EQ(limits.max_pair_tests, library.max_pair_tests);
  }
}

TEST(CliMachineMemory, TheMachineIsReadAndSmallerThanNothing) {
  const auto usable = cvms::cli::usable_memory_bytes();
#if defined(__linux__)
  ASSERT_TRUE(usable.has_value());
  EXPECT_GE(*usable, 64 * MiB);  // no Linux machine that builds this has less
#endif
  if (usable) {
    EXPECT_LE(cvms::cli::sum_limits_for_memory(usable).max_memory_bytes, *usable / 2 + 1);
  }
}

TEST(CliMachineMemory, TheAddressSpaceLimitLessTheProgramsShareBounds) {
  using cvms::cli::usable_memory_bytes;
  const std::optional<std::uint64_t> none;
  // ulimit -v 150000 (KiB): 146.5 MiB less 64 MiB for the program.
  EXPECT_EQ(usable_memory_bytes(16 * GiB, none, 150'000 * std::uint64_t{1024}),
            150'000 * std::uint64_t{1024} - 64 * MiB);
  EXPECT_EQ(usable_memory_bytes(none, none, 8 * GiB), 8 * GiB - 64 * MiB);
  EXPECT_EQ(usable_memory_bytes(2 * GiB, 1 * GiB, 8 * GiB), 1 * GiB);
  EXPECT_EQ(usable_memory_bytes(2 * GiB, 3 * GiB, 1 * GiB), 1 * GiB - 64 * MiB);
  EXPECT_EQ(usable_memory_bytes(2 * GiB, none, none), 2 * GiB);
  EXPECT_EQ(usable_memory_bytes(none, none, none), none);
  // A limit the program itself barely fits in still gives a small budget, not the library's 4 GiB.
  EXPECT_EQ(usable_memory_bytes(16 * GiB, none, 64 * MiB), 4 * MiB);
  EXPECT_EQ(usable_memory_bytes(16 * GiB, none, 0), 4 * MiB);
  EXPECT_EQ(cvms::cli::sum_limits_for_memory(usable_memory_bytes(16 * GiB, none, 64 * MiB)).max_memory_bytes,
            2 * MiB);
}

TEST(CliMachineMemory, TheDefaultBudgetIsHalfOfWhatTheAddressSpaceLeaves) {
  using cvms::cli::sum_limits_for_memory;
  using cvms::cli::usable_memory_bytes;
  const std::optional<std::uint64_t> none;
  EXPECT_EQ(sum_limits_for_memory(usable_memory_bytes(16 * GiB, none, 150'000 * std::uint64_t{1024}))
                .max_memory_bytes,
            41 * MiB);  // (146.48 - 64) / 2 = 41.24 MiB, in whole MiB
  EXPECT_EQ(sum_limits_for_memory(usable_memory_bytes(16 * GiB, none, 1 * GiB + 64 * MiB)).max_memory_bytes,
            512 * MiB);
  EXPECT_EQ(sum_limits_for_memory(usable_memory_bytes(16 * GiB, none, 64 * GiB)).max_memory_bytes, 4 * GiB);
}

TEST(CliInputMemory, TheEstimateIsLinearInTheInputAndSaturates) {
  using cvms::cli::estimated_input_memory;
  using cvms::cli::InputCost;
  EXPECT_EQ(cvms::cli::memory_per_input_byte(InputCost::mesh), 144u);
  EXPECT_EQ(cvms::cli::memory_per_input_byte(InputCost::rows_or_points), 256u);
  EXPECT_EQ(estimated_input_memory(0, InputCost::mesh), 0u);
  EXPECT_EQ(estimated_input_memory(1, InputCost::mesh), 144u);
  EXPECT_EQ(estimated_input_memory(8'000'000, InputCost::mesh), 1'152'000'000u);
  EXPECT_EQ(estimated_input_memory(8'000'000, InputCost::rows_or_points), 2'048'000'000u);
  constexpr std::uint64_t max = ~std::uint64_t{0};
  EXPECT_EQ(estimated_input_memory(max / 144, InputCost::mesh), max / 144 * 144);
  EXPECT_EQ(estimated_input_memory(max / 144 + 1, InputCost::mesh), max);
  EXPECT_EQ(estimated_input_memory(max / 256 + 1, InputCost::rows_or_points), max);
  EXPECT_EQ(estimated_input_memory(max, InputCost::rows_or_points), max);
}

}  // namespace
