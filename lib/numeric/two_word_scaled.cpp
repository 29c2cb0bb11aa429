// SPDX-License-Identifier: MIT
// scale_to_two_words: two passes over the coordinates, the first for the lcm
// of their denominators, the second for the scaled numerators; and the
// overflow-checked bound of the sums (see the header).
#include "two_word_scaled.hpp"

#include <gmp.h>

#include "gcd128.hpp"

namespace cvms::detail {
namespace {

using Int128 = TwoWordScaledPoints::Int128;
using Uint128 = TwoWordScaledPoints::Uint128;

// The magnitude of an integer of at most two limbs; false for a longer one.
bool two_limbs(mpz_srcptr x, Uint128& out) noexcept {
  const std::size_t n = mpz_size(x);
  if (n > 2) return false;
  out = n == 2 ? (Uint128{mpz_getlimbn(x, 1)} << 64) | mpz_getlimbn(x, 0) : Uint128{mpz_getlimbn(x, 0)};
  return true;
}

// The lcm of d and q's denominator, when below the bound; false for a
// longer denominator or numerator, or an lcm beyond the bound.
bool widen(Uint128& d, const Rational& q) noexcept {
  Uint128 e = 0, unused = 0;
  if (!two_limbs(q.get_den_mpz_t(), e) || !two_limbs(q.get_num_mpz_t(), unused)) return false;
  if (d % e == 0) return true;  // decimals: 10^k divides the largest 10^k seen
  Uint128 lcm = 0;
  if (__builtin_mul_overflow(d / gcd128(d, e), e, &lcm) || lcm >= two_word_limit) return false;
  d = lcm;
  return true;
}

// q times d (a multiple of q's denominator), when below the bound in magnitude.
bool scale(const Rational& q, Uint128 d, Uint128& largest, Int128& out) noexcept {
  Uint128 num = 0, den = 0;
  two_limbs(q.get_num_mpz_t(), num);  // widen() checked both sizes
  two_limbs(q.get_den_mpz_t(), den);
  Uint128 magnitude = 0;
  if (__builtin_mul_overflow(num, d / den, &magnitude) || magnitude >= two_word_limit) return false;
  if (magnitude > largest) largest = magnitude;
  const auto m = static_cast<Int128>(magnitude);
  out = mpz_sgn(q.get_num_mpz_t()) < 0 ? -m : m;
  return true;
}

}  // namespace

std::optional<TwoWordScaledPoints> scale_to_two_words(std::span<const Vec3> points) {
  TwoWordScaledPoints scaled;
  for (const Vec3& p : points)
    for (int axis = 0; axis < 3; ++axis)
      if (!widen(scaled.denominator, p[axis])) return std::nullopt;
  scaled.numerators.resize(3 * points.size());
  Int128* out = scaled.numerators.data();
  for (const Vec3& p : points)
    for (int axis = 0; axis < 3; ++axis)
      if (!scale(p[axis], scaled.denominator, scaled.largest, *out++)) return std::nullopt;
  return scaled;
}

std::optional<TwoWordSum> two_word_sum_fits(const TwoWordScaledPoints& a, const TwoWordScaledPoints& b) {
  constexpr Uint128 denominator_limit = Uint128{1} << 126;
  constexpr Uint128 numerator_limit = Uint128{1} << 125;
  const Uint128 g = gcd128(a.denominator, b.denominator);
  TwoWordSum sum{0, b.denominator / g, a.denominator / g};
  Uint128 term_a = 0, term_b = 0, bound = 0;
  if (__builtin_mul_overflow(a.denominator, sum.factor_a, &sum.denominator) || sum.denominator >= denominator_limit ||
      __builtin_mul_overflow(a.largest, sum.factor_a, &term_a) ||
      __builtin_mul_overflow(b.largest, sum.factor_b, &term_b) || __builtin_add_overflow(term_a, term_b, &bound) ||
      bound >= numerator_limit)
    return std::nullopt;
  return sum;
}

}  // namespace cvms::detail
