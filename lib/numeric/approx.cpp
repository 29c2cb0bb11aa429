// SPDX-License-Identifier: MIT
// Approx::of: the double of a rational with a proven error bound, without
// allocating (the plain-vector predicates call it on every evaluation).
#include "approx.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "error_bounds.hpp"
#include "exact_double.hpp"

namespace cvms {
namespace {

static_assert(GMP_NUMB_BITS == 64, "top_bits reads 64-bit limbs");

__extension__ using Uint128 = unsigned __int128;

// The top 64 bits t of |x| (x != 0), highest bit set, and the shift s =
// bit length - 64 (negative for short x), so |x| = t 2^s + r with
// 0 <= r < 2^s, and r = 0 when s <= 0.
std::uint64_t top_bits(mpz_srcptr x, long& shift) noexcept {
  const std::size_t n = mpz_size(x);
  const mp_limb_t* limbs = mpz_limbs_read(x);
  const std::uint64_t high = limbs[n - 1];
  const int zeros = std::countl_zero(high);
  shift = static_cast<long>(64 * (n - 1)) - zeros;
  if (n == 1 || zeros == 0) return high << zeros;
  return (high << zeros) | (limbs[n - 2] >> (64 - zeros));
}

// Whether r != 0 above: any bit of |x| below the top 64.
bool bits_below(mpz_srcptr x, long shift) noexcept {
  if (shift <= 0) return false;
  const std::size_t n = mpz_size(x);
  const mp_limb_t* limbs = mpz_limbs_read(x);
  const long zeros = static_cast<long>(64 * (n - 1)) - shift;
  if ((limbs[n - 2] << zeros) != 0) return true;  // the bits the window left out of the second limb
  for (std::size_t i = 0; i + 2 < n; ++i)
    if (limbs[i] != 0) return true;
  return false;
}

// num / 2^k for a one-limb power-of-two denominator 2^k and a numerator of
// any size (the primitive normals, up to 2^125, and the planes' offsets,
// n . p over the denominator of p): the value mpq_get_d gives, truncated
// toward zero, with the error Approx::of gives, read off the numerator's
// top limbs. Dividing by 2^k only moves the exponent, so truncating num to
// its top 53 bits and scaling is the truncation of the quotient, as long as
// the result is a normal double; otherwise nullopt (the general path).
std::optional<Approx> truncated_dyadic(mpz_srcptr num, mpz_srcptr den) noexcept {
  if (mpz_size(den) != 1 || mpz_size(num) == 0) return std::nullopt;
  const mp_limb_t den_limb = mpz_getlimbn(den, 0);
  if (!std::has_single_bit(den_limb)) return std::nullopt;
  long shift = 0;
  const std::uint64_t window = top_bits(num, shift);
  const mp_limb_t mantissa = window >> 11;  // the top 53 bits, truncated
  const bool exact = !bits_below(num, shift) && (window & 0x7ff) == 0;
  // value = mantissa 2^(bits - 53 - k), bits = shift + 64.
  const long exponent = shift + 11 - std::countr_zero(den_limb);
  // mantissa is in [2^52, 2^53): the value is normal when the exponent of
  // its leading bit, exponent + 52, is in [-1022, 1023].
  if (exponent + 52 < -1022 || exponent + 52 > 1023) return std::nullopt;
  const double d = std::ldexp(static_cast<double>(mantissa), static_cast<int>(exponent));
  const double value = mpz_sgn(num) < 0 ? -d : d;
  return Approx{value, exact ? 0.0 : filtered::truncation_error(value)};
}

// n / d truncated toward zero to a double, as mpq_get_d gives it, for words
// n > 0 and d > 1 (what a decimal of up to 19 significant digits reduces
// to): one 128-by-64-bit division instead of GMP's general one. With b_n,
// b_d the bit lengths, n / d lies in [2^(b_n - b_d - 1), 2^(b_n - b_d + 1)),
// so for s = 54 + b_d - b_n the quotient floor(n 2^s / d) lies in [2^53,
// 2^55): 54 or 55 bits, of which the top 53 are the truncated significand
// (floor(floor(x) / 2^k) = floor(x / 2^k), and a negative s drops low bits of
// n first, floor(floor(n / 2^j) / d) = floor(n / (2^j d))). n 2^s has at
// most 54 + b_d <= 118 bits. The result lies in (2^-64, 2^64): a normal
// double, and its scaling by a power of two is exact.
double truncated_word_quotient(std::uint64_t n, std::uint64_t d) noexcept {
  const int s = 54 + std::bit_width(d) - std::bit_width(n);
  const Uint128 scaled = s >= 0 ? Uint128{n} << s : Uint128{n >> -s};
  const auto quotient = static_cast<std::uint64_t>(scaled / d);
  const int drop = std::bit_width(quotient) - 53;
  const std::uint64_t significand = quotient >> drop;
  // 2^(drop - s), with drop - s in [-116, 12]: a normal double.
  const double scale = std::bit_cast<double>(static_cast<std::uint64_t>(1023 + drop - s) << 52);
  return static_cast<double>(significand) * scale;
}

}  // namespace

Approx Approx::of(const Rational& q) noexcept {
  // The general case truncates q toward zero (mpq_get_d, mpz_get_d), whose
  // error truncation_error bounds (error_bounds.hpp, "Approx::of").
  mpz_srcptr num = q.get_num_mpz_t();
  mpz_srcptr den = q.get_den_mpz_t();
  // Fast path, all inline: one-limb numerator and power-of-two one-limb
  // denominator (every double of moderate magnitude). A numerator of at most
  // 53 significant bits converts exactly, and scaling by 2^-k (k < 64, a
  // normal double) is then exact too.
  if (mpz_size(den) == 1 && mpz_size(num) <= 1) {
    mp_limb_t den_limb = mpz_getlimbn(den, 0);
    mp_limb_t num_limb = mpz_getlimbn(num, 0);  // 0 when q == 0
    if (std::has_single_bit(den_limb) &&
        (num_limb == 0 || std::bit_width(num_limb) - std::countr_zero(num_limb) <= 53)) {
      int k = std::countr_zero(den_limb);
      double scale = std::bit_cast<double>(static_cast<std::uint64_t>(1023 - k) << 52);
      double m = static_cast<double>(num_limb) * scale;
      return {mpz_sgn(num) < 0 ? -m : m, 0.0};
    }
  }
  // Second fast path: a fraction of two integers below 2^53 (small decimals
  // like 0.1 = 1/10). Both convert exactly, the quotient is rounded to
  // nearest once, and |q| > 2^-64 is normal, so |fl(n/d) - q| <= u |fl(n/d)|
  // (Higham, 2.5): the bound u |value| is exact and sufficient.
  if (mpz_size(den) == 1 && mpz_size(num) == 1) {
    mp_limb_t den_limb = mpz_getlimbn(den, 0);
    mp_limb_t num_limb = mpz_getlimbn(num, 0);
    if (std::bit_width(num_limb) <= 53 && std::bit_width(den_limb) <= 53) {
      double v = static_cast<double>(num_limb) / static_cast<double>(den_limb);
      return {mpz_sgn(num) < 0 ? -v : v, v * filtered::unit_roundoff};
    }
  }
  if (mpz_size(den) == 1 && mpz_size(num) == 1 && !std::has_single_bit(mpz_getlimbn(den, 0))) {
    const double magnitude = truncated_word_quotient(mpz_getlimbn(num, 0), mpz_getlimbn(den, 0));
    const double value = mpz_sgn(num) < 0 ? -magnitude : magnitude;
    // Not a double: the reduced denominator has an odd factor above 1.
    return {value, filtered::truncation_error(value)};
  }
  if (const std::optional<Approx> a = truncated_dyadic(num, den)) return *a;
  // Integers (the primitive normals of edge facets reach 2^125): mpz_get_d
  // truncates toward zero too, without mpq_get_d's division.
  const bool integer = mpz_cmp_ui(den, 1) == 0;
  if (is_double_exact_fast(q))
    return {integer ? mpz_get_d(num) : q.get_d(), 0.0};  // truncation of a double is itself
  double d = integer ? mpz_get_d(num) : q.get_d();
  if (!std::isfinite(d)) return {d, std::numeric_limits<double>::infinity()};
  return {d, filtered::truncation_error(d)};
}

// Proof of the bound. With the top bits t_n 2^s_n of |n| and t_d 2^s_d of d
// as in top_bits, |n| = t_n 2^s_n (1 + e_n) and d = t_d 2^s_d (1 + e_d) with
// 0 <= e < 2^-63 (the bits below t are less than 2^s <= t 2^-63 when s > 0,
// and there are none when s <= 0). Converting t_n and t_d to doubles and
// dividing are three roundings of relative error at most u = 2^-53 each
// (Higham, 2.2), so v / (n/d) = (1 + d1)(1 + d3)(1 + e_d) / ((1 + d2)(1 +
// e_n)) is within 3.01 u of 1, and |v - n/d| <= 3.01 u |n/d| <= 3.01 u (1 +
// 3.01 u) |v| < 4 u |v| = |v| 2^-51. The tops are in [2^63, 2^64), so the
// quotient of the rounded tops lies in [2^-1, 2] (a top of 2^64 - 1 rounds
// up to 2^64), and with |s_n - s_d| <= 900 the scaling by 2^(s_n - s_d) is
// exact and |v| is in [2^-901, 2^901], normal, and so is |v| 2^-51 >=
// 2^-952: the bound is computed exactly. Beyond that range mpq_get_d truncates the unreduced
// fraction (read in place: it needs no canonical form), which
// truncation_error bounds.
Approx Approx::of_quotient(mpz_srcptr n, mpz_srcptr d) noexcept {
  if (mpz_sgn(n) == 0) return {0.0, 0.0};
  long shift_n = 0, shift_d = 0;
  const std::uint64_t top_n = top_bits(n, shift_n), top_d = top_bits(d, shift_d);
  const long exponent = shift_n - shift_d;
  if (exponent >= -900 && exponent <= 900) {
    const double magnitude =
        std::ldexp(static_cast<double>(top_n) / static_cast<double>(top_d), static_cast<int>(exponent));
    return {mpz_sgn(n) < 0 ? -magnitude : magnitude, magnitude * 0x1p-51};
  }
  mpq_t fraction;
  mpz_roinit_n(mpq_numref(fraction), mpz_limbs_read(n), static_cast<mp_size_t>(mpz_size(n)) * mpz_sgn(n));
  mpz_roinit_n(mpq_denref(fraction), mpz_limbs_read(d), static_cast<mp_size_t>(mpz_size(d)));
  const double v = mpq_get_d(fraction);
  if (!std::isfinite(v)) return {v, std::numeric_limits<double>::infinity()};
  return {v, filtered::truncation_error(v)};
}

}  // namespace cvms
