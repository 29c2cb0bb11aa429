// SPDX-License-Identifier: MIT
// scale_to_words: two passes over the coordinates, the first for the lcm of
// their denominators, the second for the scaled numerators (see the header).
#include "word_scaled.hpp"

#include <gmp.h>

#include <numeric>

namespace cvms::detail {
namespace {

constexpr std::uint64_t denominator_limit = std::uint64_t{1} << 63;
constexpr std::uint64_t numerator_limit = std::uint64_t{1} << 61;

// The lcm of d and the one-limb denominator of q, when below 2^63; false
// for a longer denominator or numerator, or an lcm beyond the bound.
bool widen(std::uint64_t& d, const Rational& q) noexcept {
  mpz_srcptr num = q.get_num_mpz_t();
  mpz_srcptr den = q.get_den_mpz_t();
  if (mpz_size(num) > 1 || mpz_size(den) != 1) return false;
  const std::uint64_t e = mpz_getlimbn(den, 0);
  if (d % e == 0) return true;  // decimals: 10^k divides the largest 10^k seen
  __extension__ using Uint128 = unsigned __int128;
  const Uint128 lcm = Uint128{d / std::gcd(d, e)} * e;
  if (lcm >= denominator_limit) return false;
  d = static_cast<std::uint64_t>(lcm);
  return true;
}

// q times d (a multiple of q's denominator), when below 2^61 in magnitude.
bool scale(const Rational& q, std::uint64_t d, std::int64_t& out) noexcept {
  mpz_srcptr num = q.get_num_mpz_t();
  const std::uint64_t factor = d / mpz_getlimbn(q.get_den_mpz_t(), 0);
  __extension__ using Uint128 = unsigned __int128;
  const Uint128 magnitude = Uint128{mpz_getlimbn(num, 0)} * factor;  // limb 0 of zero reads 0
  if (magnitude >= numerator_limit) return false;
  const auto m = static_cast<std::int64_t>(magnitude);
  out = mpz_sgn(num) < 0 ? -m : m;
  return true;
}

}  // namespace

std::optional<WordScaledPoints> scale_to_words(std::span<const Vec3> points) {
  WordScaledPoints scaled;
  for (const Vec3& p : points)
    for (int axis = 0; axis < 3; ++axis)
      if (!widen(scaled.denominator, p[axis])) return std::nullopt;
  scaled.numerators.resize(3 * points.size());
  std::int64_t* out = scaled.numerators.data();
  for (const Vec3& p : points)
    for (int axis = 0; axis < 3; ++axis)
      if (!scale(p[axis], scaled.denominator, *out++)) return std::nullopt;
  return scaled;
}

}  // namespace cvms::detail
