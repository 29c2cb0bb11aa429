// SPDX-License-Identifier: MIT
// Soak: CVMS and ESSDMS against CHMS on >= 100,000 seeded random pairs each (label "soak",
// not run by default: ctest --preset soak). CVMS_SOAK_PAIRS and
// CVMS_SOAK_FIRST_SEED override the count and the first seed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "cvms/minkowski.hpp"
#include "support/minkowski_check.hpp"
#include "support/random_clouds.hpp"

namespace cvms {
namespace {

std::uint64_t env_or(const char* name, std::uint64_t fallback) {
  const char* v = std::getenv(name);
  return v ? std::strtoull(v, nullptr, 10) : fallback;
}

class CvmsSoak : public ::testing::TestWithParam<Algorithm> {};

INSTANTIATE_TEST_SUITE_P(Algorithms, CvmsSoak, ::testing::Values(Algorithm::cvms, Algorithm::essdms),
                         [](const ::testing::TestParamInfo<Algorithm>& info) {
                           return std::string(to_string(info.param));
                         });

TEST_P(CvmsSoak, RandomPairsAgreeWithChms) {
  Options options;
  options.algorithm = GetParam();
  const std::uint64_t pairs = env_or("CVMS_SOAK_PAIRS", 100000);
  const std::uint64_t first = env_or("CVMS_SOAK_FIRST_SEED", 1000000);
  std::uint64_t failures = 0;
  for (std::uint64_t seed = first; seed < first + pairs; ++seed) {
    const test::RandomPair p = test::random_pair(seed, 100);
    const std::string msg = test::check_sum(p.a, p.b, test::chms_shape(p.a, p.b), options);
    if (!msg.empty()) {
      ADD_FAILURE() << "seed " << seed << " (" << p.description << "): " << msg;
      if (++failures >= 10) break;
    }
  }
  EXPECT_EQ(failures, 0u);
}

}  // namespace
}  // namespace cvms
