// SPDX-License-Identifier: MIT
// Power-of-two tests on GMP integers without a library call. Every dyadic
// fast path asks this of each denominator it touches, and mpz_popcount (an
// out-of-line loop over the limbs) costs several percent of a whole
// Minkowski sum; the denominators asked about are almost always a single
// limb.
#pragma once

#include <gmp.h>

#include <bit>

namespace cvms::detail {

/// Whether x is 2^k for some k >= 0 (1 included; zero and negatives are not).
[[nodiscard]] inline bool is_power_of_two(mpz_srcptr x) noexcept {
  if (mpz_sgn(x) <= 0) return false;
  const mp_size_t top_index = static_cast<mp_size_t>(mpz_size(x)) - 1;
  for (mp_size_t i = 0; i < top_index; ++i)
    if (mpz_getlimbn(x, i) != 0) return false;
  const mp_limb_t top = mpz_getlimbn(x, top_index);
  return (top & (top - 1)) == 0;
}

/// k for x = 2^k.
/// \pre is_power_of_two(x)
[[nodiscard]] inline mp_bitcnt_t log2_of_power_of_two(mpz_srcptr x) noexcept {
  const mp_size_t top_index = static_cast<mp_size_t>(mpz_size(x)) - 1;
  return static_cast<mp_bitcnt_t>(top_index) * GMP_NUMB_BITS +
         static_cast<mp_bitcnt_t>(std::countr_zero(mpz_getlimbn(x, top_index)));
}

}  // namespace cvms::detail
