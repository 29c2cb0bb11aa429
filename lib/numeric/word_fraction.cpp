// SPDX-License-Identifier: MIT
// Sums of one-word fractions in 128-bit words (see the header).
#include "word_fraction.hpp"

#include <gmp.h>

#include "limb_arena.hpp"

namespace cvms::detail {
namespace {

using Int128 = WordFraction::Int128;
using Uint128 = WordFraction::Uint128;

// A value's one-limb numerator magnitude, its sign and its one-limb
// denominator, read with GMP's inline accessors only; false when a part
// needs more than one limb.
struct OneWord {
  std::uint64_t magnitude;
  bool negative;
  std::uint64_t denominator;
};

bool read_one_word(const Rational& q, OneWord& out) noexcept {
  mpz_srcptr num = q.get_num_mpz_t();
  mpz_srcptr den = q.get_den_mpz_t();
  if (mpz_size(num) > 1 || mpz_size(den) != 1) return false;
  out = {mpz_getlimbn(num, 0), mpz_sgn(num) < 0, mpz_getlimbn(den, 0)};
  return true;
}

// (negative ? -1 : 1) * magnitude * factor as a signed 128-bit value, when
// the product is below 2^126 (so that the sum of two stays below 2^127).
bool signed_product(std::uint64_t magnitude, bool negative, std::uint64_t factor, Int128& out) noexcept {
  const Uint128 p = Uint128{magnitude} * factor;
  if ((p >> 126) != 0) return false;
  out = negative ? -static_cast<Int128>(p) : static_cast<Int128>(p);
  return true;
}

// gcd(dx, dy) for nonzero one-limb denominators. Decimals' denominators are
// powers of ten, equal or one dividing the other: one word division then,
// else GMP's one-limb gcd (a data-dependent binary gcd loop in C++ costs
// more than the rest of the sum).
std::uint64_t denominator_gcd(std::uint64_t dx, std::uint64_t dy) noexcept {
  if (dx == dy) return dx;
  const std::uint64_t high = dx > dy ? dx : dy, low = dx > dy ? dy : dx;
  if (high % low == 0) return low;
  const mp_limb_t limb = high;
  return mpn_gcd_1(&limb, 1, low);
}

}  // namespace

std::optional<WordFraction> word_fraction_sum(const Rational& x, const Rational& y) noexcept {
  OneWord a, b;
  if (!read_one_word(x, a) || !read_one_word(y, b)) return std::nullopt;
  const std::uint64_t g = denominator_gcd(a.denominator, b.denominator);
  const std::uint64_t ya = b.denominator / g, xb = a.denominator / g;  // dy / g and dx / g
  Int128 tx, ty;
  if (!signed_product(a.magnitude, a.negative, ya, tx) || !signed_product(b.magnitude, b.negative, xb, ty))
    return std::nullopt;
  const Int128 t = tx + ty;  // below 2^127 in magnitude: both terms are below 2^126
  if (t == 0) return WordFraction{0, 1};
  const Uint128 magnitude = t < 0 ? -static_cast<Uint128>(t) : static_cast<Uint128>(t);
  // gcd(t, g): GMP's one-limb gcd reduces the two-limb t modulo g first.
  const mp_limb_t t_limbs[2] = {static_cast<mp_limb_t>(magnitude), static_cast<mp_limb_t>(magnitude >> 64)};
  const std::uint64_t h = g == 1 ? 1 : mpn_gcd_1(t_limbs, t_limbs[1] != 0 ? 2 : 1, g);
  const Uint128 numerator = h == 1 ? magnitude : magnitude / h;
  return WordFraction{t < 0 ? -static_cast<Int128>(numerator) : static_cast<Int128>(numerator),
                      Uint128{xb} * (b.denominator / h)};
}

void store_word_fraction(LimbArena& arena, Rational& out, const WordFraction& value) {
  const bool negative = value.numerator < 0;
  const Uint128 m = negative ? -static_cast<Uint128>(value.numerator) : static_cast<Uint128>(value.numerator);
  mp_limb_t num[2] = {static_cast<mp_limb_t>(m), static_cast<mp_limb_t>(m >> 64)};
  mp_limb_t den[2] = {static_cast<mp_limb_t>(value.denominator), static_cast<mp_limb_t>(value.denominator >> 64)};
  // Read-only views; mpz_roinit_n drops high zero limbs (zero has size 0).
  mpz_t num_view, den_view;
  mpz_roinit_n(num_view, num, negative ? -2 : 2);
  mpz_roinit_n(den_view, den, 2);
  arena.store(out, num_view, den_view);
}

}  // namespace cvms::detail
