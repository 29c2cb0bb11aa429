// SPDX-License-Identifier: MIT
// Soak (label "soak", not run by default): distance, intersection and
// penetration against the CHMS + brute-force oracle on many more seeded
// random pairs than the default run (CVMS_PROXIMITY_SOAK_PAIRS, default
// 50,000), seeds after the default run's.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "support/proximity_oracle.hpp"

namespace {

TEST(ProximitySoak, SeededRandomPairsAgreeWithTheOracle) {
  const char* env = std::getenv("CVMS_PROXIMITY_SOAK_PAIRS");
  const std::uint64_t count = env != nullptr ? std::strtoull(env, nullptr, 10) : 50000;
  for (std::uint64_t seed = 1000001; seed < 1000001 + count; ++seed) {
    const cvms::test::RandomPlacementCheck c = cvms::test::check_random_placement(seed);
    ASSERT_EQ(c.failure, "") << "seed " << seed << ": " << c.description;
  }
}

}  // namespace
