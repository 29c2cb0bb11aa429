// SPDX-License-Identifier: MIT
// Approx::of: the double of a rational with a proven error bound, without
// allocating (the plain-vector predicates call it on every evaluation).
#include "cvms/approx.hpp"

#include <cmath>
#include <limits>

#include "exact_double.hpp"

namespace cvms {

Approx Approx::of(const Rational& q) noexcept {
  // mpq_get_d truncates toward zero (GMP manual; subnormals included, and
  // an exponent beyond the double range gives infinity). So q lies strictly
  // between d and the next double away from zero: |q - d| < ulp(d), where
  // ulp(d) = 2^(e-52) for 2^e <= |d| < 2^(e+1), e >= -1022, and 2^-1074 for
  // subnormal d. fl(|d| 2^-52) >= 2^(e-52) (the exact product is at least
  // that, and 2^(e-52) is a double, so rounding cannot go below it), and
  // adding 2^-1074 covers the subnormal case; rounding of the sum is
  // monotone, so error >= ulp(d) > |q - d|.
  double d = q.get_d();
  if (!std::isfinite(d)) return {d, std::numeric_limits<double>::infinity()};
  if (is_double_exact_fast(q)) return {d, 0.0};
  return {d, std::fabs(d) * 0x1p-52 + 0x1p-1074};
}

}  // namespace cvms
