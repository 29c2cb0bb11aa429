// SPDX-License-Identifier: MIT
// Running error analysis for the predicate filters: double arithmetic on
// Approx values that carries, next to each computed value, a proven bound on
// its distance to the exact (rational) result. Private to the library.
//
// The notation, the facts (R1)-(R4) about binary64 and the rounding of each
// bound (finish) are in error_bounds.hpp, with the bound of a sum or
// difference (sum_error). The product, c = fl(a * b):
//   AB - a.value b.value = a.value beta + b.value alpha + alpha beta
//   with |alpha| <= a.error, |beta| <= b.error, so
//   |c - AB| <= |a.value| b.error + |b.value| a.error
//               + a.error b.error + u|c| + 2^-1075                       (R2)
// which has the form E = P + s that finish() covers (k = 4 terms). A plain
// double operand is an Approx with error 0; the overloads on doubles only
// drop zero terms.
//
// Overflow and NaN. An infinite value makes its own error infinite (u|c| =
// inf), and an infinite or NaN error stays infinite or NaN through every
// later operation (sums and products of nonnegative terms; 0 * inf = NaN).
// A finite error therefore implies every value it was computed from was
// finite, i.e. the analysis applied. certain() also rejects a non-finite
// value explicitly, and NaN compares false.
#pragma once

#include <cmath>
#include <limits>

#include "approx.hpp"
#include "cvms/sign.hpp"
#include "error_bounds.hpp"

namespace cvms::filtered {

inline Approx add(Approx a, Approx b) noexcept {
  double v = a.value + b.value;
  return {v, sum_error(a.error, b.error, v)};
}
inline Approx sub(Approx a, Approx b) noexcept {
  double v = a.value - b.value;
  return {v, sum_error(a.error, b.error, v)};
}
inline Approx mul(Approx a, Approx b) noexcept {
  double v = a.value * b.value;
  return {v, finish(std::fabs(a.value) * b.error + std::fabs(b.value) * a.error + a.error * b.error +
                    unit_roundoff * std::fabs(v))};
}

// Exact double operands (error 0): the same bounds with the zero terms
// dropped, which is cheaper and (fewer roundings) still covered by the proof.
inline Approx add(double a, double b) noexcept {
  double v = a + b;
  return {v, finish(unit_roundoff * std::fabs(v))};
}
inline Approx sub(double a, double b) noexcept {
  double v = a - b;
  return {v, finish(unit_roundoff * std::fabs(v))};
}
inline Approx mul(double a, double b) noexcept {
  double v = a * b;
  return {v, finish(unit_roundoff * std::fabs(v))};
}
inline Approx mul(Approx a, double b) noexcept {
  double v = a.value * b;
  return {v, finish(std::fabs(b) * a.error + unit_roundoff * std::fabs(v))};
}
inline Approx mul(double a, Approx b) noexcept { return mul(b, a); }

/// True iff r proves the sign of its exact value: |value| > error (so the
/// exact value lies strictly on the same side of zero), both finite.
inline bool certain(Approx r) noexcept {
  return std::fabs(r.value) > r.error && std::fabs(r.value) <= std::numeric_limits<double>::max();
}

/// The sign of r.value; the exact sign when certain(r).
inline Sign sign(Approx r) noexcept { return r.value > 0 ? Sign::positive : Sign::negative; }

}  // namespace cvms::filtered
