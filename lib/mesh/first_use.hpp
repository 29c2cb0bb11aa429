// SPDX-License-Identifier: MIT
// Deduplication without hashing: a hash container keyed
// by input-derived values goes quadratic when an input makes the keys
// collide (hash_value(Vec3) is invertible; std::hash of an integer is the
// identity, so index keys j * n + v collide modulo a bucket count that n
// hits). Sorting costs O(n log n) comparisons whatever the keys. The
// numbering is by first use, as an insert-if-new map would give it, so the
// results do not depend on how the duplicates were found.
//
// Integer keys under std::less (the sums' vertex keys a * n_B + b) take a
// radix sort instead of the comparison sort: key and position packed into
// one word and sorted on the key's digits, least significant first, each
// pass stable, so equal keys keep their positions' order, exactly the
// comparison sort's stable order. No comparison runs through an index array
// into the keys (a cache miss per comparison): that sort was 40 M of
// Sphere6 + rot. Sphere6's 540 M instructions (callgrind).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <functional>
#include <numeric>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "huge_page_blocks.hpp"

namespace cvms::detail {

/// For keys in order of use: keys[i] is the distinct key number index[i],
/// distinct keys numbered by first use; first[k] is the position of the
/// first use of key number k.
struct FirstUse {
  std::vector<std::uint32_t> index;
  ScratchVector<std::size_t> first;
};

/// FirstUse from leader[i], the position of the first key equal to keys[i].
inline FirstUse number_by_first_use(const ScratchVector<std::size_t>& leader) {
  FirstUse out;
  out.index.reserve(leader.size());  // not resized: no pass to zero what is written next
  for (std::size_t i = 0; i < leader.size(); ++i) {
    if (leader[i] == i) {
      out.index.push_back(static_cast<std::uint32_t>(out.first.size()));
      out.first.push_back(i);
    } else {
      out.index.push_back(out.index[leader[i]]);  // leader[i] < i: numbered already
    }
  }
  return out;
}

/// FirstUse of `keys` under the strict weak order `less` (its equivalence
/// is the keys' equality), by a stable comparison sort: O(n log n)
/// comparisons.
template <class Keys, class Less>
FirstUse first_use_by_comparison(const Keys& keys, Less less) {
  ScratchVector<std::size_t> order(keys.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  // Stable: within a run of equal keys the first use comes first.
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return less(keys[a], keys[b]); });
  ScratchVector<std::size_t> leader(keys.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    leader[order[k]] = k > 0 && !less(keys[order[k - 1]], keys[order[k]]) ? leader[order[k - 1]] : order[k];
  return number_by_first_use(leader);
}

/// FirstUse of integer keys under <, by the radix sort of the file comment
/// when each key and position fit one word together (else by comparison).
/// O(n) per 11 bits of the largest key.
inline FirstUse first_use_of_integers(std::span<const std::uint64_t> keys) {
  const std::size_t n = keys.size();
  const int position_bits = std::bit_width(n);
  const int key_bits = n == 0 ? 0 : std::bit_width(*std::max_element(keys.begin(), keys.end()));
  if (position_bits + key_bits > 63) return first_use_by_comparison(keys, std::less<>{});
  ScratchVector<std::uint64_t> packed(n), buffer(n);
  for (std::size_t i = 0; i < n; ++i) packed[i] = (keys[i] << position_bits) | i;
  constexpr int digit_bits = 11;
  constexpr std::uint64_t digit_mask = (std::uint64_t{1} << digit_bits) - 1;
  for (int shift = position_bits; shift < position_bits + key_bits; shift += digit_bits) {
    std::array<std::size_t, std::size_t{1} << digit_bits> start{};
    for (std::uint64_t v : packed) ++start[(v >> shift) & digit_mask];
    std::exclusive_scan(start.begin(), start.end(), start.begin(), std::size_t{0});
    for (std::uint64_t v : packed) buffer[start[(v >> shift) & digit_mask]++] = v;
    std::swap(packed, buffer);
  }
  const std::uint64_t position_mask = (std::uint64_t{1} << position_bits) - 1;
  ScratchVector<std::size_t> leader(n);
  std::size_t run_leader = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t position = packed[k] & position_mask;
    if (k == 0 || (packed[k] >> position_bits) != (packed[k - 1] >> position_bits)) run_leader = position;
    leader[position] = run_leader;
  }
  return number_by_first_use(leader);
}

/// FirstUse of `keys` under the strict weak order `less` (its equivalence
/// is the keys' equality): first_use_of_integers for 64-bit keys under <,
/// else first_use_by_comparison.
template <class Keys, class Less>
FirstUse first_use(const Keys& keys, Less less) {
  if constexpr (std::is_same_v<typename Keys::value_type, std::uint64_t> &&
                std::is_same_v<Less, std::less<>>) {
    return first_use_of_integers(keys);
  } else {
    return first_use_by_comparison(keys, less);
  }
}

}  // namespace cvms::detail
