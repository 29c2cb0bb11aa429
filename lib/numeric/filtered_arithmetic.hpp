// SPDX-License-Identifier: MIT
// Running error analysis for the predicate filters: double arithmetic on
// Approx values that carries, next to each computed value, a proven bound on
// its distance to the exact (rational) result. Private to the library.
//
// Notation. u = 2^-53 (unit roundoff of binary64, round to nearest),
// fl(x) = x rounded to the nearest double, F = 1 + 8u (a double), eta =
// 2^-1021. For an Approx a, A denotes the exact number it stands for, and the
// invariant is |a.value - A| <= a.error. A plain double operand is an Approx
// with error 0 (the overloads on double only drop zero terms).
//
// Facts about IEEE binary64 with round to nearest (Higham, "Accuracy and
// Stability of Numerical Algorithms", 2.2 and 2.5), as long as nothing
// overflows (an overflow gives an infinity, handled below):
//  (R1) fl(x op y) = (x op y) / (1 + d) with |d| <= u when the exact result
//       is zero or at least 2^-1022 in magnitude (normal range); so
//       |fl(z) - z| <= u |fl(z)|.
//  (R2) In the subnormal range |fl(z) - z| <= 2^-1075 (half the spacing
//       2^-1074); with (R1): |fl(x*y) - x*y| <= u |fl(x*y)| + 2^-1075.
//  (R3) A sum or difference of doubles is exact when its result is
//       subnormal (both operands are multiples of 2^-1074), so
//       |fl(x +- y) - (x +- y)| <= u |fl(x +- y)| always.
//  (R4) For x, y >= 0: fl(x + y) >= (x + y) / (1 + u) (from R1 and R3), and
//       fl(x * y) >= x y / (1 + u) - 2^-1075 (from R1 and R2).
//
// Bounds of one operation, c = fl(a op b):
//  add/sub: |c - (A +- B)| <= a.error + b.error + u|c|                   (R3)
//  mul:     AB - a.value b.value = a.value beta + b.value alpha + alpha beta
//           with |alpha| <= a.error, |beta| <= b.error, so
//           |c - AB| <= |a.value| b.error + |b.value| a.error
//                       + a.error b.error + u|c| + 2^-1075               (R2)
// Each right-hand side is E = P + s with P = p_1 + ... + p_k a sum of k <= 4
// nonnegative terms, each a double or an exact product of two doubles (u|c|
// is one: u is a double), and s in {0, 2^-1075}.
//
// Rounding of the bound itself. We compute e = fl(fl(t_1 + ... + t_k + eta)
// * F) with t_i = fl(p_i), summing left to right. By (R4) every t_i >=
// p_i / (1 + u) - 2^-1075, and the k additions give
//   S >= (sum t_i + eta) / (1 + u)^k >= (P + eta - 4 * 2^-1075) / (1 + u)^5,
// using eta - 4 * 2^-1075 > 0. S >= eta / (1 + u)^4 > 2^-1022 is normal, so
// by (R1) e >= S F / (1 + u) >= (P + eta - 4 * 2^-1075) F / (1 + u)^6
// >= P + eta - 4 * 2^-1075 >= P + 2^-1075 >= E, because (1 + u)^6 < 1 + 7u
// < F. So the invariant holds for c with c.error = e. eta is the absolute
// term that absorbs underflow (of the operation and of the bound); taking it
// normal keeps the whole bound computation in the normal range. The price is
// that results below about 2^-1020 in magnitude are never certified: tiny
// inputs fall back to exact arithmetic, as they should.
//
// Overflow and NaN. An infinite value makes its own error infinite (u|c| =
// inf), and an infinite or NaN error stays infinite or NaN through every
// later operation (sums and products of nonnegative terms; 0 * inf = NaN).
// A finite error therefore implies every value it was computed from was
// finite, i.e. the analysis above applied. certain() also rejects a
// non-finite value explicitly, and NaN compares false.
//
// Contraction into FMA (a*b + c rounded once) can only remove roundings:
// each bound above still covers the unrounded intermediate, so the analysis
// stays valid; x86-64 without -mfma never contracts anyway. The rounding mode
// must be the default round to nearest (the library never changes it).
#pragma once

#include <cfloat>
#include <cmath>
#include <limits>

#include "approx.hpp"
#include "cvms/sign.hpp"

namespace cvms::filtered {

static_assert(std::numeric_limits<double>::is_iec559, "the error analysis assumes IEEE binary64");
static_assert(FLT_EVAL_METHOD == 0, "the error analysis assumes no extended-precision intermediates");

inline constexpr double unit_roundoff = 0x1p-53;      ///< u
inline constexpr double inflation = 1.0 + 0x1p-50;    ///< F = 1 + 8u
inline constexpr double underflow_slack = 0x1p-1021;  ///< eta

// Finishes a bound: fl(fl(sum + eta) * F), see the proof above. `sum` is the
// left-to-right floating sum of the k <= 4 terms.
inline double finish(double sum) noexcept { return (sum + underflow_slack) * inflation; }

inline Approx add(Approx a, Approx b) noexcept {
  double v = a.value + b.value;
  return {v, finish(a.error + b.error + unit_roundoff * std::fabs(v))};
}
inline Approx sub(Approx a, Approx b) noexcept {
  double v = a.value - b.value;
  return {v, finish(a.error + b.error + unit_roundoff * std::fabs(v))};
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
