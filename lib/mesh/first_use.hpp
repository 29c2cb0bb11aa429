// SPDX-License-Identifier: MIT
// Deduplication without hashing (issue 18, item 1): a hash container keyed
// by input-derived values goes quadratic when an input makes the keys
// collide (hash_value(Vec3) is invertible; std::hash of an integer is the
// identity, so index keys j * n + v collide modulo a bucket count that n
// hits). Sorting costs O(n log n) comparisons whatever the keys. The
// numbering is by first use, as an insert-if-new map would give, so the
// results are those of the hash maps this replaced.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "huge_page_blocks.hpp"

namespace cvms::detail {

/// For keys in order of use: keys[i] is the distinct key number index[i],
/// distinct keys numbered by first use; first[k] is the position of the
/// first use of key number k.
struct FirstUse {
  std::vector<std::uint32_t> index;
  std::vector<std::size_t> first;
};

/// FirstUse of `keys` under the strict weak order `less` (its equivalence
/// is the keys' equality). O(n log n) comparisons.
template <class Key, class Less>
FirstUse first_use(const std::vector<Key>& keys, Less less) {
  ScratchVector<std::size_t> order(keys.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  // Stable: within a run of equal keys the first use comes first.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return less(keys[a], keys[b]); });
  ScratchVector<std::size_t> leader(keys.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    leader[order[k]] = k > 0 && !less(keys[order[k - 1]], keys[order[k]]) ? leader[order[k - 1]] : order[k];
  FirstUse out;
  out.index.resize(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (leader[i] == i) {
      out.index[i] = static_cast<std::uint32_t>(out.first.size());
      out.first.push_back(i);
    } else {
      out.index[i] = out.index[leader[i]];  // leader[i] < i: numbered already
    }
  }
  return out;
}

}  // namespace cvms::detail
