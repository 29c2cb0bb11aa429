// SPDX-License-Identifier: MIT
// Soak run of the sums of convex sets (label soak): many more seeded random
// pairs than the default run, with bigger operands on a wider grid, every
// dimension pair and every algorithm, against the exact hull of the
// pairwise vertex sums; and n-ary sums of random lists in two orders.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "cvms/set_sum.hpp"
#include "support/random_sets.hpp"
#include "support/set_oracle.hpp"

namespace cvms {
namespace {

TEST(SetsSoak, RandomPairsAgainstOracle) {
  for (std::uint64_t seed = 0; seed < 20000; ++seed) {
    std::mt19937_64 rng(seed ^ 0x5e75);
    const Vec3 origin{Rational(static_cast<long>(seed % 11)) - 5, 0, Rational(1, 3)};
    const ConvexSet a = test::random_set(rng, static_cast<int>(seed % 4), origin, 4, 20);
    const ConvexSet b = test::random_set(rng, static_cast<int>((seed / 4) % 4), Vec3{0, 0, 0}, 4, 20);
    Options options;
    options.algorithm = seed % 3 == 0 ? Algorithm::essdms : (seed % 3 == 1 ? Algorithm::cvms : Algorithm::chms);
    ASSERT_EQ(test::check_set_sum(a, b, options), "") << "seed " << seed;
  }
}

TEST(SetsSoak, ManyOperandsInTwoOrders) {
  for (std::uint64_t seed = 0; seed < 500; ++seed) {
    std::mt19937_64 rng(seed);
    std::vector<ConvexSet> operands;
    for (int i = 0; i < 2 + static_cast<int>(seed % 7); ++i)
      operands.push_back(test::random_set(rng, static_cast<int>(rng() % 4), Vec3{0, 0, 0}, 3, 10));
    const test::SetShape forward = test::describe_set(minkowski_sum(operands));
    std::reverse(operands.begin(), operands.end());
    ASSERT_EQ(test::describe_set(minkowski_sum(operands)), forward) << "seed " << seed;
  }
}

}  // namespace
}  // namespace cvms
