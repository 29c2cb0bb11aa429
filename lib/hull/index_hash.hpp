// SPDX-License-Identifier: MIT
// The slot of a few point indices in a cache of exact work: the quickhull's
// exact answers (direct-mapped), the cofactors of the dual hull's triangles
// (the set of 8 entries, homogeneous_hull.cpp). Each index is multiplied by its own odd constant (Knuth's
// golden-ratio multiplier and MurmurHash3's finaliser constants); only the
// high bits of such products depend on every bit of the indices, so the
// slot is taken from the top.
#pragma once

#include <cstddef>
#include <cstdint>

namespace cvms::detail {

// The size of such a cache as a power of two: at least half as many slots
// as points, between 2^min_bits and 2^max_bits.
[[nodiscard]] inline int cache_bits(std::size_t points, int min_bits, int max_bits) {
  int bits = min_bits;
  while (bits < max_bits && (std::size_t{2} << bits) < points) ++bits;
  return bits;
}

// The top `bits` bits (1..32) of the indices' hash.
[[nodiscard]] inline std::size_t index_slot(int bits, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                                            std::uint32_t d = 0) {
  const std::uint32_t h = a * 0x9E3779B1u ^ b * 0x85EBCA77u ^ c * 0xC2B2AE3Du ^ d * 0x27D4EB2Fu;
  return static_cast<std::size_t>(h >> (32 - bits));
}

}  // namespace cvms::detail
