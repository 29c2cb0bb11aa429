// SPDX-License-Identifier: MIT
// The tool's machine-fitted sum limits (tools/cvms/machine_memory.hpp: a
// sum's output can be quadratic in its input), on hand-picked memory sizes.
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>

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

}  // namespace
