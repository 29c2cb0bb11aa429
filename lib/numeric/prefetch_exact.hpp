// SPDX-License-Identifier: MIT
// Fetching exact points ahead of the loops that read them. A
// point's exact coordinates sit behind two dependent loads, its mpq_structs
// and then their limbs, and loops that visit vertices in facet order find
// neither in cache: perf puts most of the time of a sum's plane offsets and
// of a loaded polyhedron's own planes on those two misses.
// Fetching the structs `far` iterations ahead and the limbs `near` ones
// ahead (by then their structs have arrived) lets the misses overlap.
//
// Call these from the loop itself, never from a helper that only prefetches:
// GCC (12) judges such a helper, a void function taking the loop's index and
// a lambda or a void member function alike, free of side effects (a
// prefetch has none it counts), drops the call before inlining it, and every
// prefetch is gone, with the misses back in full. Helpers may compute
// addresses; the loop issues the prefetches.
#pragma once

#include <cstddef>

#include "cvms/vec.hpp"

namespace cvms::detail {

inline constexpr std::size_t prefetch_far = 16;
inline constexpr std::size_t prefetch_near = 8;

/// Every cache line of the object at `at`, `bytes` long (its first and
/// last byte included whatever its alignment: a 96-byte Vec3 may span three
/// lines, a 48-byte ApproxVec3 two).
inline void prefetch_bytes(const void* at, std::size_t bytes) noexcept {
  const char* first = static_cast<const char*>(at);
  for (std::size_t offset = 0; offset < bytes; offset += 64) __builtin_prefetch(first + offset);
  __builtin_prefetch(first + bytes - 1);
}

/// The cache lines of p's three mpq_structs.
inline void prefetch_structs(const Vec3& p) noexcept { prefetch_bytes(&p, sizeof p); }

/// The first limb of each numerator and denominator of p (read through the
/// structs: call it once prefetch_structs had time to bring them).
inline void prefetch_limbs(const Vec3& p) noexcept {
  for (int k = 0; k < 3; ++k) {
    __builtin_prefetch(p[k].get_num_mpz_t()->_mp_d);
    __builtin_prefetch(p[k].get_den_mpz_t()->_mp_d);
  }
}

}  // namespace cvms::detail
