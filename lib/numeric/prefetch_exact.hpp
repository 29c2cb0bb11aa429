// SPDX-License-Identifier: MIT
// Fetching exact points ahead of the loops that read them (issue 14). A
// point's exact coordinates sit behind two dependent loads, its mpq_structs
// and then their limbs, and loops that visit vertices in facet order find
// neither in cache: perf put 72 % of the sum's plane offsets (Sphere6 + rot.
// Sphere6) and most of a loaded Sphere6's own planes on those two misses.
// Fetching the structs `far` iterations ahead and the limbs `near` ones
// ahead (by then their structs have arrived) lets the misses overlap.
#pragma once

#include <cstddef>

#include "cvms/vec.hpp"

namespace cvms::detail {

inline constexpr std::size_t prefetch_far = 16;
inline constexpr std::size_t prefetch_near = 8;

/// The cache lines of p's three mpq_structs.
inline void prefetch_structs(const Vec3& p) noexcept {
  __builtin_prefetch(&p);
  __builtin_prefetch(reinterpret_cast<const char*>(&p) + 64);
}

/// The first limb of each numerator and denominator of p (read through the
/// structs: call it once prefetch_structs had time to bring them).
inline void prefetch_limbs(const Vec3& p) noexcept {
  for (int k = 0; k < 3; ++k) {
    __builtin_prefetch(p[k].get_num_mpz_t()->_mp_d);
    __builtin_prefetch(p[k].get_den_mpz_t()->_mp_d);
  }
}

}  // namespace cvms::detail
