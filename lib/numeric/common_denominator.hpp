// SPDX-License-Identifier: MIT
// Rationals brought to integers over one common denominator: the exact
// stages of the proximity queries compute in integers (no gcd per
// operation) and divide once at the end.
#pragma once

#include <cstddef>

#include "cvms/rational.hpp"

namespace cvms::detail {

/// out[i] := values[i] * L for L the lcm of the values' denominators, which
/// is written to lcm (L > 0, every out[i] an integer; out's and lcm's limbs
/// are reused, so a loop over many rows allocates nothing once they are
/// large enough). Values read from doubles have powers of two as
/// denominators: then L is the largest of them and each out[i] a shift, with
/// no gcd (the same L and out as the general path).
void scale_to_common_denominator(const Rational* const values[], std::size_t count, mpz_class out[],
                                 mpz_class& lcm);

/// The same, L returned.
inline mpz_class scale_to_common_denominator(const Rational* const values[], std::size_t count,
                                             mpz_class out[]) {
  mpz_class lcm;
  scale_to_common_denominator(values, count, out, lcm);
  return lcm;
}

}  // namespace cvms::detail
