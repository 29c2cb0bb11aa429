// SPDX-License-Identifier: MIT
// common_denominator.hpp. The lcm of powers of two is the largest one, and
// scaling p / 2^k to the denominator 2^m multiplies p by 2^(m - k): so for
// dyadic values the general lcm-and-divide path and the shifts below agree.
#include "common_denominator.hpp"

#include <algorithm>

namespace cvms::detail {
namespace {

bool is_power_of_two(const mpz_class& x) { return mpz_popcount(x.get_mpz_t()) == 1; }

// The largest exponent if every denominator is a power of two.
bool dyadic_exponent(const Rational* const values[], std::size_t count, mp_bitcnt_t& exponent) {
  exponent = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const mpz_class& den = values[i]->get_den();
    if (!is_power_of_two(den)) return false;
    exponent = std::max(exponent, mpz_scan1(den.get_mpz_t(), 0));
  }
  return true;
}

}  // namespace

mpz_class scale_to_common_denominator(const Rational* const values[], std::size_t count, mpz_class out[]) {
  mpz_class l = 1;
  mp_bitcnt_t exponent = 0;
  if (dyadic_exponent(values, count, exponent)) {
    mpz_mul_2exp(l.get_mpz_t(), l.get_mpz_t(), exponent);
    for (std::size_t i = 0; i < count; ++i)
      mpz_mul_2exp(out[i].get_mpz_t(), values[i]->get_num_mpz_t(),
                   exponent - mpz_scan1(values[i]->get_den_mpz_t(), 0));
    return l;
  }
  for (std::size_t i = 0; i < count; ++i) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), values[i]->get_den_mpz_t());
  for (std::size_t i = 0; i < count; ++i) {
    mpz_divexact(out[i].get_mpz_t(), l.get_mpz_t(), values[i]->get_den_mpz_t());
    out[i] *= values[i]->get_num();
  }
  return l;
}

}  // namespace cvms::detail
