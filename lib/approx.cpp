// SPDX-License-Identifier: MIT
#include "cvms/approx.hpp"

#include <cmath>

namespace cvms {

Approx Approx::of(const Rational& q) noexcept {
  // mpq_get_d truncates toward zero: |q - d| < ulp(d) <= |d| 2^-52 for normal
  // d, and < 2^-1074 in the subnormal range; the sum bounds both.
  double d = q.get_d();
  if (!std::isfinite(d)) return {d, INFINITY};
  if (cmp(Rational(d), q) == 0) return {d, 0.0};
  return {d, std::fabs(d) * 0x1p-52 + 0x1p-1074};
}

}  // namespace cvms
