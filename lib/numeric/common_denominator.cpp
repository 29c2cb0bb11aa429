// SPDX-License-Identifier: MIT
// common_denominator.hpp. The lcm of powers of two is the largest one, and
// scaling p / 2^k to the denominator 2^m multiplies p by 2^(m - k): so for
// dyadic values the general lcm-and-divide path and the shifts below agree.
#include "common_denominator.hpp"

#include <algorithm>

#include "dyadic.hpp"

namespace cvms::detail {
namespace {

// The largest exponent if every denominator is a power of two.
bool dyadic_exponent(const Rational* const values[], std::size_t count, mp_bitcnt_t& exponent) {
  exponent = 0;
  for (std::size_t i = 0; i < count; ++i) {
    if (!is_dyadic(*values[i])) return false;
    exponent = std::max(exponent, log2_of_power_of_two(values[i]->get_den_mpz_t()));
  }
  return true;
}

}  // namespace

void scale_to_common_denominator(const Rational* const values[], std::size_t count, mpz_class out[],
                                 mpz_class& l) {
  l = 1;
  mp_bitcnt_t exponent = 0;
  if (dyadic_exponent(values, count, exponent)) {
    mpz_mul_2exp(l.get_mpz_t(), l.get_mpz_t(), exponent);
    for (std::size_t i = 0; i < count; ++i)
      mpz_mul_2exp(out[i].get_mpz_t(), values[i]->get_num_mpz_t(),
                   exponent - log2_of_power_of_two(values[i]->get_den_mpz_t()));
    return;
  }
  for (std::size_t i = 0; i < count; ++i)
    if (mpz_cmp_ui(values[i]->get_den_mpz_t(), 1) != 0)
      mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), values[i]->get_den_mpz_t());
  for (std::size_t i = 0; i < count; ++i) {
    if (mpz_cmp(l.get_mpz_t(), values[i]->get_den_mpz_t()) == 0) {  // no quotient or product
      out[i] = values[i]->get_num();
      continue;
    }
    mpz_divexact(out[i].get_mpz_t(), l.get_mpz_t(), values[i]->get_den_mpz_t());
    out[i] *= values[i]->get_num();
  }
}

}  // namespace cvms::detail
