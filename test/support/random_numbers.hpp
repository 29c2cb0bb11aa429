// SPDX-License-Identifier: MIT
// Seeded random doubles and rationals of every awkward kind (subnormals,
// extremes, non-dyadic fractions, huge and tiny) for the numeric tests.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "cvms/rational.hpp"

namespace cvms::test {

using Rng = std::mt19937_64;

/// A finite double with uniformly random bits: every exponent (subnormals
/// included) is equally likely.
inline double random_double_bits(Rng& rng) {
  for (;;) {
    double d = std::bit_cast<double>(rng());
    if (std::isfinite(d)) return d;
  }
}

/// Uniform in [lo, hi).
inline double random_uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

/// A double of random sign with exponent uniform in [min_exp, max_exp].
inline double random_magnitude(Rng& rng, int min_exp, int max_exp) {
  double m = random_uniform(rng, 1.0, 2.0);
  int e = std::uniform_int_distribution<int>(min_exp, max_exp)(rng);
  return ((rng() & 1) ? -1.0 : 1.0) * std::ldexp(m, e);
}

/// 2^e as an exact rational (any integer e).
inline Rational power_of_two(long e) {
  mpz_class p = 1;
  mpz_mul_2exp(p.get_mpz_t(), p.get_mpz_t(), static_cast<mp_bitcnt_t>(e < 0 ? -e : e));
  return e >= 0 ? Rational(p) : Rational(mpz_class(1), p);
}

/// 10^e as an exact rational (any integer e).
inline Rational power_of_ten(long e) {
  mpz_class p;
  mpz_ui_pow_ui(p.get_mpz_t(), 10, static_cast<unsigned long>(e < 0 ? -e : e));
  return e >= 0 ? Rational(p) : Rational(mpz_class(1), p);
}

/// A random integer with up to `bits` bits, random sign.
inline mpz_class random_integer(Rng& rng, unsigned bits) {
  mpz_class z = 0;
  for (unsigned done = 0; done < bits; done += 64) {
    z <<= 64;
    std::uint64_t limb = rng();
    if (bits - done < 64) limb >>= 64 - (bits - done);
    z += mpz_class(std::to_string(limb));
  }
  return (rng() & 1) ? mpz_class(-z) : z;
}

/// num / den, canonicalised (gmpxx's two-argument constructor does not).
inline Rational fraction(const mpz_class& num, const mpz_class& den) {
  Rational q(num, den);
  q.canonicalize();
  return q;
}

/// A random rational of a random kind: small fractions, decimals, doubles
/// (all exponents), huge and tiny non-dyadic values, values just off a
/// double.
inline Rational random_rational(Rng& rng) {
  switch (rng() % 8) {
    case 0:
      return fraction(static_cast<long>(rng() % 2001) - 1000, static_cast<long>(rng() % 99) + 1);
    case 1:  // a decimal with up to 12 digits and exponent in [-20, 20]
      return Rational(random_integer(rng, 40)) * power_of_ten(static_cast<long>(rng() % 41) - 20);
    case 2:
      return Rational(random_double_bits(rng));
    case 3:
      return Rational(random_magnitude(rng, -80, 80));
    case 4: {  // huge or tiny, non-dyadic
      return fraction(random_integer(rng, 200) * 3 + 1, 3) *
             power_of_two(static_cast<long>(rng() % 2400) - 1200);
    }
    case 5: {  // a double plus a tiny non-dyadic perturbation
      double d = random_magnitude(rng, -30, 30);
      return Rational(d) + Rational(d) * Rational(1, 7) * power_of_two(-60);
    }
    case 6:  // a long random fraction
      return fraction(random_integer(rng, 150), random_integer(rng, 150) * 2 + 1);
    default:
      return Rational(random_integer(rng, 53)) * power_of_two(static_cast<long>(rng() % 2200) - 1100);
  }
}

}  // namespace cvms::test
