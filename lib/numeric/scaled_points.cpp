// SPDX-License-Identifier: MIT
// The approximations and canonical rationals of scaled points (see the header).
#include "scaled_points.hpp"

#include <gmp.h>

#include <cstdint>
#include <utility>

namespace cvms::detail {
namespace {

using Int128 = ScaledPoints::Int128;
using Uint128 = ScaledPoints::Uint128;

Uint128 magnitude_of(Int128 n) noexcept { return n < 0 ? -static_cast<Uint128>(n) : static_cast<Uint128>(n); }

// gcd(m, d) for d > 0: GMP's one-limb gcd when d fits one limb (it reduces
// the two-limb m modulo d first), else Euclid in 128-bit words.
Uint128 gcd128(Uint128 m, Uint128 d) noexcept {
  if (m == 0) return d;
  if ((d >> 64) == 0) {
    const mp_limb_t limbs[2] = {static_cast<mp_limb_t>(m), static_cast<mp_limb_t>(m >> 64)};
    return mpn_gcd_1(limbs, limbs[1] != 0 ? 2 : 1, static_cast<mp_limb_t>(d));
  }
  while (m != 0) d = std::exchange(m, d % m);
  return d;
}

}  // namespace

// Both integers are below 2^126, so converting each to the nearest double
// and dividing are three roundings of relative error at most u = 2^-53
// (Higham, 2.2): |v - n/d| <= ((1 + u)^2 / (1 - u) - 1) |n/d| < 3.01 u (1 +
// 3.01 u) |v| < 4 u |v| = |v| 2^-51, as for Approx::of_quotient. When both
// are below 2^53 they convert exactly and the one rounding of the quotient
// gives u |v|. (An integer value gets a bound too, not error 0: finding
// it would cost a 128-bit division per coordinate.) |n/d| >= 2^-126 for n != 0, so v and the bound are normal
// and computed exactly.
Approx ScaledPoints::approx(Int128 numerator) const noexcept {
  if (numerator == 0) return {0.0, 0.0};
  const Uint128 m = magnitude_of(numerator);
  // Through a 64-bit integer when it fits: one instruction, where the
  // 128-bit conversion is a library call (the same nearest double).
  constexpr Uint128 word_limit = Uint128{1} << 63;
  const double n = m < word_limit ? static_cast<double>(static_cast<std::int64_t>(numerator))
                                  : static_cast<double>(numerator);
  const double v = n / denominator_value_;
  const double size = v < 0 ? -v : v;
  constexpr Uint128 exact_limit = Uint128{1} << 53;
  return {v, m < exact_limit && denominator_ < exact_limit ? size * 0x1p-53 : size * 0x1p-51};
}

void ScaledPoints::store(std::size_t j, int axis, LimbArena& arena, Rational& out) const {
  const Int128 n = numerator(j, axis);
  const Uint128 m = magnitude_of(n);
  const Uint128 g = gcd128(m, denominator_);
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
