// SPDX-License-Identifier: MIT
// Numbering by first use, both sorts, against the insert-if-new map it
// replaced (the oracle): random keys with many repeats, keys too wide for
// the radix sort's packing, one key, none.
#include "first_use.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <map>
#include <random>
#include <vector>

namespace cvms::detail {
namespace {

FirstUse by_map(const std::vector<std::uint64_t>& keys) {
  std::map<std::uint64_t, std::uint32_t> numbers;
  FirstUse out;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const auto [it, inserted] = numbers.emplace(keys[i], static_cast<std::uint32_t>(numbers.size()));
    if (inserted) out.first.push_back(i);
    out.index.push_back(it->second);
  }
  return out;
}

void expect_same(const FirstUse& got, const FirstUse& expected, const std::string& what) {
  EXPECT_EQ(got.index, expected.index) << what;
  EXPECT_EQ(got.first, expected.first) << what;
}

TEST(FirstUse, IntegerKeysAreNumberedAsAnInsertIfNewMapDoes) {
  const std::uint64_t seed = 20261204;
  std::mt19937_64 rng(seed);
  // Key ranges: a few keys (long runs), a sum's a * n_B + b keys, keys of
  // 40 and 58 bits (the radix sort's packing fits, or not, with the
  // positions), and the full 64 bits.
  for (const std::uint64_t range : {std::uint64_t{3}, std::uint64_t{1} << 27, std::uint64_t{1} << 40,
                                    std::uint64_t{1} << 58, ~std::uint64_t{0}})
    for (const std::size_t n :
         {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{1000}, std::size_t{70000}}) {
      std::vector<std::uint64_t> keys(n);
      std::vector<std::uint64_t> pool(n / 3 + 1);
      for (std::uint64_t& k : pool) k = std::uniform_int_distribution<std::uint64_t>(0, range)(rng);
      for (std::uint64_t& k : keys)
        k = pool[std::uniform_int_distribution<std::size_t>(0, pool.size() - 1)(rng)];
      const std::string what =
          "seed " + std::to_string(seed) + " range " + std::to_string(range) + " n " + std::to_string(n);
      const FirstUse expected = by_map(keys);
      expect_same(first_use(keys, std::less<>{}), expected, what + " (first_use)");
      expect_same(first_use_by_comparison(keys, std::less<>{}), expected, what + " (comparison)");
    }
}

}  // namespace
}  // namespace cvms::detail
