// SPDX-License-Identifier: MIT
// Approx::of: the double of a rational with a proven error bound, without
// allocating (the plain-vector predicates call it on every evaluation).
#include "approx.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "error_bounds.hpp"
#include "exact_double.hpp"

namespace cvms {

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
  // Integers (the primitive normals of edge facets reach 2^125): mpz_get_d
  // truncates toward zero too, without mpq_get_d's division.
  const bool integer = mpz_cmp_ui(den, 1) == 0;
  if (is_double_exact_fast(q))
    return {integer ? mpz_get_d(num) : q.get_d(), 0.0};  // truncation of a double is itself
  double d = integer ? mpz_get_d(num) : q.get_d();
  if (!std::isfinite(d)) return {d, std::numeric_limits<double>::infinity()};
  return {d, filtered::truncation_error(d)};
}

}  // namespace cvms
