// SPDX-License-Identifier: MIT
// The approximations and canonical rationals of scaled points (see the header).
#include "scaled_points.hpp"

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "error_bounds.hpp"
#include "gcd128.hpp"

namespace cvms::detail {
namespace {

using Int128 = ScaledPoints::Int128;
using Uint128 = ScaledPoints::Uint128;

Uint128 magnitude_of(Int128 n) noexcept { return n < 0 ? -static_cast<Uint128>(n) : static_cast<Uint128>(n); }

// gcd(m, d) for d > 0: GMP's one-limb gcd when d fits one limb (it reduces
// the two-limb m modulo d first), else the binary gcd on two words
// (gcd128.hpp: each of Euclid's steps would be a 128-bit division, a library
// call of about a hundred cycles).
Uint128 fraction_gcd(Uint128 m, Uint128 d) noexcept {
  if (m == 0) return d;
  if ((d >> 64) == 0) {
    const mp_limb_t limbs[2] = {static_cast<mp_limb_t>(m), static_cast<mp_limb_t>(m >> 64)};
    return mpn_gcd_1(limbs, limbs[1] != 0 ? 2 : 1, static_cast<mp_limb_t>(d));
  }
  return gcd128(m, d);
}

}  // namespace

ScaledPoints::DecimalDenominator ScaledPoints::DecimalDenominator::of(Uint128 d) noexcept {
  DecimalDenominator out;
  out.twos = trailing_zeros128(d);  // d > 0
  d >>= out.twos;
  while (divide_by_5(d)) ++out.fives;
  if (d != 1) out.fives = -1;
  return out;
}

bool ScaledPoints::reduces_below_2_53(Uint128 n) const noexcept {
  constexpr Uint128 limit = Uint128{1} << 53;
  if (decimal_.fives < 0) {
    const Uint128 g = fraction_gcd(n, denominator_);
    return n / g < limit && denominator_ / g < limit;
  }
  // gcd(n, 2^t 5^f) = 2^a 5^b: a = min(t, trailing zeros of n), b the
  // number of times 5 divides n, at most f.
  const int a = std::min(decimal_.twos, trailing_zeros128(n));
  n >>= a;
  int b = 0;
  while (b < decimal_.fives && divide_by_5(n)) ++b;
  if (n >= limit) return false;
  // The reduced denominator 2^(t - a) 5^(f - b): below 2^53 when its factors are.
  Uint128 den = Uint128{1} << std::min(decimal_.twos - a, 53);
  for (int k = b; k < decimal_.fives && den < limit; ++k) den *= 5;
  return den < limit;
}

// Approx::of of the canonical fraction, without making it. Approx::of
// gives the nearest double with the bound u |v| when the reduced numerator
// and denominator are both below 2^53, else the truncation t toward zero
// with truncation_error(t) (error 0 only for a double, which a fraction
// strictly between two doubles is not). The quotient is first worked out in
// long double: each of the two conversions and the division is within
// 2^-64 relative, so |ld - q| < 2^-62 |ld| =: e. When no double and no
// midpoint between two doubles lies within e of ld, q lies strictly
// between the same two doubles t < q < t' as ld, on the same side of their
// midpoint, so its truncation is t and its nearest double the one ld
// rounds to. Otherwise (q within e of a double or a midpoint: rare, apart
// from values that are doubles) the canonical rational is made and
// Approx::of called. Whether the reduced integers are below 2^53 (which
// needs their gcd) is asked only when the nearest double is not t; when it
// is t, the bound is truncation_error(t) >= u |t|, which covers both cases.
Approx ScaledPoints::approx(Int128 numerator) const {
  if (numerator == 0) return {0.0, 0.0};
  const bool negative = numerator < 0;
  const Uint128 m = magnitude_of(numerator);
  constexpr Uint128 exact_limit = Uint128{1} << 53;
  const auto sign = [negative](double v) { return negative ? -v : v; };
  if (m < exact_limit && denominator_ < exact_limit) {  // so are the reduced ones
    const double v = static_cast<double>(static_cast<std::uint64_t>(m)) / denominator_value_;
    return {sign(v), v * filtered::unit_roundoff};
  }
  const long double n =
      (m >> 64) == 0 ? static_cast<long double>(static_cast<std::uint64_t>(m)) : static_cast<long double>(m);
  const long double ld = n / denominator_long_;
  const long double e = ld * 0x1p-62L;
  double t = static_cast<double>(ld);  // nearest
  if (static_cast<long double>(t) > ld) t = std::nextafter(t, 0.0);
  const double next = std::nextafter(t, std::numeric_limits<double>::infinity());
  const long double middle = (static_cast<long double>(t) + static_cast<long double>(next)) / 2;
  if (ld - e > t && ld + e < next && (ld + e < middle || ld - e > middle)) {
    if (ld + e < middle) return {sign(t), filtered::truncation_error(t)};  // nearest is t too
    if (reduces_below_2_53(m)) return {sign(next), next * filtered::unit_roundoff};
    return {sign(t), filtered::truncation_error(t)};
  }
  LimbArena scratch;
  Rational q;
  store_fraction(numerator, scratch, q);
  return Approx::of(q);
}

void ScaledPoints::store(std::size_t j, int axis, LimbArena& arena, Rational& out) const {
  store_fraction(numerator(j, axis), arena, out);
}

void ScaledPoints::store_fraction(Int128 n, LimbArena& arena, Rational& out) const {
  const Uint128 m = magnitude_of(n);
  const Uint128 g = fraction_gcd(m, denominator_);
  const Uint128 reduced = m / g, den = denominator_ / g;
  const mp_limb_t num_limbs[2] = {static_cast<mp_limb_t>(reduced), static_cast<mp_limb_t>(reduced >> 64)};
  const mp_limb_t den_limbs[2] = {static_cast<mp_limb_t>(den), static_cast<mp_limb_t>(den >> 64)};
  // Read-only views; mpz_roinit_n drops high zero limbs (zero has size 0).
  mpz_t num_view, den_view;
  mpz_roinit_n(num_view, num_limbs, n < 0 ? -2 : 2);
  mpz_roinit_n(den_view, den_limbs, 2);
  arena.store(out, num_view, den_view);
}

Vec3 ScaledPoints::point(std::size_t j) const {
  LimbArena scratch;
  Vec3 stored, owned;
  for (int axis = 0; axis < 3; ++axis) {
    store(j, axis, scratch, stored[axis]);
    owned[axis] = Rational(stored[axis]);  // a copy owns its limbs
  }
  return owned;
}

}  // namespace cvms::detail
