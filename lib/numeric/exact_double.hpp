// SPDX-License-Identifier: MIT
// Allocation-free test whether a rational is exactly a double (used by
// Approx::of on every plain-vector predicate call, and by is_double_exact).
#pragma once

#include "cvms/rational.hpp"
#include "power_of_two.hpp"

namespace cvms {

/// True iff q is exactly representable as a finite double. q = n / 2^k
/// (canonical, so n is odd when k > 0) is a double iff its significant bits
/// fit in 53, its lowest set bit is at least 2^-1074 and its highest below
/// 2^1024.
inline bool is_double_exact_fast(const Rational& q) noexcept {
  mpz_srcptr num = q.get_num_mpz_t();
  mpz_srcptr den = q.get_den_mpz_t();
  if (mpz_sgn(num) == 0) return true;
  if (!detail::is_power_of_two(den)) return false;
  long k = static_cast<long>(detail::log2_of_power_of_two(den));
  long bits = static_cast<long>(mpz_sizeinbase(num, 2));  // of |num|
  long low = static_cast<long>(mpz_scan1(num, 0));        // same for -num
  return bits - low <= 53 && low - k >= -1074 && bits - 1 - k <= 1023;
}

}  // namespace cvms
