// SPDX-License-Identifier: MIT
// Every error bound of the library's double filters, each constant next to
// the proof that justifies it. The filters themselves live with the code
// that uses them (filtered_arithmetic.hpp: running error; plane_filter.hpp:
// orient3d against a fixed triangle; approx.cpp: Approx::of; the dot-product
// scan of the quickhull and of the contributing-vertex walk's climbs,
// dot_order_filter.hpp); what they may assume about doubles and what each bound
// is worth is here, so that checking the numerics means reading one file.
// Private to the library.
//
// Notation. u = 2^-53 (unit roundoff of binary64, round to nearest),
// fl(x) = x rounded to the nearest double, gamma_k = k u / (1 - k u). For an
// Approx a, A denotes the exact number it stands for, and the invariant is
// |a.value - A| <= a.error. A plain double operand is an Approx with error 0.
//
// Facts about IEEE binary64 with round to nearest (Higham, "Accuracy and
// Stability of Numerical Algorithms", 2.2 and 2.5), as long as nothing
// overflows (an overflow gives an infinity, which every filter rejects):
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
// Contraction into FMA (a*b + c rounded once) can only remove roundings:
// each bound below still covers the unrounded intermediate, so the analysis
// stays valid; x86-64 without -mfma never contracts anyway. The rounding mode
// must be the default round to nearest (the library never changes it).
//
// Exact fixed-width integer arithmetic is no filter and has no error: its
// bit-length bounds (that no intermediate overflows its limbs) are next to
// the code they justify, in fixed_int.hpp and fixed_det4.hpp.
#pragma once

#include <cfloat>
#include <cmath>
#include <limits>

#include "approx.hpp"

namespace cvms::filtered {

static_assert(std::numeric_limits<double>::is_iec559, "the error analysis assumes IEEE binary64");
static_assert(FLT_EVAL_METHOD == 0, "the error analysis assumes no extended-precision intermediates");

/// u, the unit roundoff: half the spacing of the doubles in [1, 2).
inline constexpr double unit_roundoff = 0x1p-53;
/// The smallest positive (subnormal) double, the spacing of the subnormals.
inline constexpr double smallest_subnormal = 0x1p-1074;

// ---- Running error (filtered_arithmetic.hpp) --------------------------------
//
// The bound of one operation c = fl(a op b) on Approx values (the sum below;
// the product in filtered_arithmetic.hpp) is E = P + s with P = p_1 + ... +
// p_k a sum of k <= 4 nonnegative terms, each a double or an exact product of
// two doubles (u|c| is one: u is a double), and s in {0, 2^-1075}.
//
// Rounding of the bound itself. With F = 1 + 8u (a double) and eta =
// 2^-1021, we compute e = fl(fl(t_1 + ... + t_k + eta)
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

/// F = 1 + 8u, the factor that covers the rounding of a running bound.
inline constexpr double inflation = 1.0 + 0x1p-50;
/// eta = 2^-1021, the running bound's absolute term for underflow.
inline constexpr double underflow_slack = 0x1p-1021;

static_assert(inflation == 1.0 + 8.0 * unit_roundoff);
static_assert(2.0 * underflow_slack >= 5.0 * smallest_subnormal, "eta - 4 * 2^-1075 >= 2^-1075");
static_assert(underflow_slack >= 2.0 * 0x1p-1022, "eta / (1 + u)^4 > 2^-1022 is normal");

/// Finishes a running bound: fl(fl(sum + eta) * F), see the proof above.
/// `sum` is the left-to-right floating sum of the k <= 4 terms.
inline double finish(double sum) noexcept { return (sum + underflow_slack) * inflation; }

// ---- The filtered sum ---------------------------------------------------------
//
// c = fl(a + b) (or fl(a - b)) of two approximations a, b of A, B:
//   |c - (A +- B)| <= |c - (a +- b)| + |a - A| + |b - B|
//                  <= u |c| + a.error + b.error                          (R3)
// which is E = P with k = 3 terms above; finish() rounds it upward. This is
// the one bound of a sum of two approximated values: the running-error add
// and sub use it, and so does CHMS for its pairwise vertex sums a_i + b_j
// (each the rounded sum of the operands' cached approximations).
//
// The vertices a_i + b_j of a Minkowski sum that the stitching builds get a
// different approximation, and so a different bound, on purpose: there the
// exact sum is formed anyway, and a polyhedron caches Approx::of of each of
// its vertices (truncation_error below) however it was built, so that
// every predicate on it sees the same doubles; the stitching reproduces
// Approx::of's truncation of the exact sum from the operands' doubles by
// TwoSum. The inputs differ (the truncated exact sum, off by less than one
// ulp, against the rounded sum of two approximations, off by up to their
// errors plus half an ulp), so the bounds differ too.

/// A bound on |fl(a + b) - (A + B)| (or of the difference) for
/// approximations with errors error_a and error_b, where c is the computed
/// sum: finish(error_a + error_b + u |c|), see above.
inline double sum_error(double error_a, double error_b, double c) noexcept {
  return finish(error_a + error_b + unit_roundoff * std::fabs(c));
}

// ---- Approx::of (approx.cpp) --------------------------------------------------
//
// mpq_get_d and mpz_get_d truncate toward zero (GMP manual; subnormals
// included, and an exponent beyond the double range gives infinity). So a
// rational q lies strictly between its truncation d and the next double away
// from zero: |q - d| < ulp(d), where ulp(d) = 2^(e-52) for 2^e <= |d| <
// 2^(e+1), e >= -1022, and 2^-1074 for subnormal d. fl(|d| 2^-52) >= 2^(e-52)
// (the exact product is at least that, and 2^(e-52) is a double, so rounding
// cannot go below it), and adding 2^-1074 covers the subnormal case;
// rounding of the sum is monotone, so the bound is >= ulp(d) > |q - d|.

/// A bound on |q - d| for a finite double d that is q truncated toward zero
/// (at least one ulp of d).
inline double truncation_error(double d) noexcept {
  return std::fabs(d) * (2.0 * unit_roundoff) + smallest_subnormal;
}

// ---- Comparing two filtered values -------------------------------------------
//
// Let v, w be doubles within b of exact values V, W, with b >= 2^-1022 (every
// semi-static bound below is, by its absolute term). If fl(v - w) > fl(3 b),
// then V > W: fl(3 b) >= 3 b / (1 + u) by (R1), and v - w >= fl(v - w)
// (1 - u) by (R1) (or v - w = fl(v - w) by (R3)), so v - w > 3 b (1 - u) /
// (1 + u) > 2 b, and V - W >= (v - w) - |v - V| - |w - W| > 2 b - 2 b = 0.
// Hence "beyond 3 bounds": 2 for the two values, 1 for the roundings.

/// The factor m for which fl(v - w) > fl(m b) proves V > W (see above).
inline constexpr double difference_margin = 3.0;

// ---- Semi-static filters -----------------------------------------------------
//
// These bound one kind of expression for a whole point set at once: the
// exact points P are approximated by doubles p with |p_k - P_k| <= e for every
// coordinate (e = 0 when the points are doubles), and |p_k| <= M. The bounds
// hold for M, e <= filter_range; beyond it (or for non-finite M, e) they are
// infinite, which never proves anything (NaN compares false too).

/// The largest M and e for which the semi-static bounds are finite.
inline constexpr double filter_range = 0x1p300;
/// The semi-static bounds' absolute term for underflow, the unit of their
/// underflow terms (it is at least 2^-1022, see difference_margin).
inline constexpr double static_underflow = 0x1p-1000;

// The plane filter (plane_filter.hpp). For a triangle a, b, c and a point p
// the filter computes
//   u = fl(b - a), v = fl(c - a), d = fl(p - a),
//   n_x = fl(fl(u_y v_z) - fl(u_z v_y))  (and cyclically),
//   s = fl(fl(fl(d_x n_x) + fl(d_y n_y)) + fl(d_z n_z)),
// which approximates S = orient3d(A, B, C, P) = det[B - A, C - A, P - A].
//
// Rounding error (Higham, 3.1). Ignoring underflow, each of the six
// monomials D_i U_j V_k of S' = det[b - a, c - a, p - a] (the determinant of
// the approximations) reaches s through at most 8 roundings (d, u, v, their
// product, the difference, the product with d, two sums), so
//   |s - S'| <= gamma_8 sum_i |D_i| (|U_j V_k| + |U_k V_j|).
// With |D_i| <= 2M, |U_j V_k| <= |fl(u_j v_k)| / (1 - gamma_3), and
// Q = fl(fl(Q_x + Q_y) + Q_z), Q_x = fl(|fl(u_y v_z)| + |fl(u_z v_y)|):
//   |s - S'| <= gamma_8 2M Q / ((1 - gamma_3)(1 - u)^2) < 8u (1 + 12u) 2M Q.
// The filter uses fl(fl(9u * 2M) * Q), which is at least 9u (1 - u)^2 2M Q
// and so covers this.
// Underflow adds at most 2^-1075 per product plus its propagation, less than
// (32M + 8) 2^-1075 in all (including the estimate of Q), and is covered by
// the absolute term (M + 1) 2^-1000.
// Input error: S - S' = det[D - D', U, V] + det[D', U - U', V]
//   + det[D', U', V - V'] (primes for the approximations), each entry of the
// differences at most 2e and of the others at most 2M + 2e, so
// |S - S'| <= 36 e (2M + 2e)^2; the filter adds 64 e (2M + 2e)^2.
// Together: |s - S| <= bound, and |s| > bound proves the sign of S.
// Overflow: with M, e <= 2^300 every intermediate stays below 2^1000.

/// The plane filter's rounding factor, 9u (see above).
inline constexpr double plane_rounding = 9.0 * unit_roundoff;
/// The plane filter's input-error factor, 64 (see above).
inline constexpr double plane_input = 64.0;

/// The absolute terms of the plane filter's bound (input error and
/// underflow) for a set with |p_k| <= max_abs and |p_k - P_k| <= max_error,
/// both in [0, filter_range].
inline double plane_filter_slack(double max_abs, double max_error) noexcept {
  const double w = 2.0 * max_abs + 2.0 * max_error;
  return plane_input * max_error * w * w + (max_abs * static_underflow + static_underflow);
}

/// The plane filter's bound on |s - S| for a triangle with the estimate q
/// of Q, in a set with span = 2M and the slack above.
inline double plane_filter_bound(double span, double q, double slack) noexcept {
  return plane_rounding * span * q + slack;
}

// The dot-product scan (the quickhull's initial simplex; DotOrderFilter in
// dot_order_filter.hpp, the contributing-vertex walk's climbs). A bound on
// |P . N - fl(p . n)| for every point P of the set and the direction N with
// approximation n (|n_k - N_k| <= f_k):
//   |P . N - p . N| <= e |N|_1 <= e (|n|_1 + |f|_1),
//   |p . N - p . n| <= M |f|_1,
//   |p . n - fl(p . n)| <= gamma_3 M |n|_1 + 3 2^-1075 (underflow),
// with gamma_3 M |n|_1 <= 4u M fl(|n|_1) (gamma_3 (1 + u)^2 < 4u), doubled
// for the rounding of the bound itself, plus 2^-1000 for the underflow. With
// M, e <= 2^300 and |n|_1 + |f|_1 <= 2^600 nothing overflows.

/// The largest |n|_1 + |f|_1 for which the dot-product bound is finite.
inline constexpr double dot_range = 0x1p600;
/// The dot-product bound's rounding factor, 4u > gamma_3 (1 + u)^2.
inline constexpr double dot_rounding = 4.0 * unit_roundoff;
/// The factor that covers the rounding of the dot-product bound itself.
inline constexpr double dot_inflation = 2.0;

/// The bound above for direction n and a set with |p_k| <= max_abs and
/// |p_k - P_k| <= max_error; infinite outside the ranges.
inline double dot_filter_bound(const ApproxVec3& n, double max_abs, double max_error) noexcept {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double a = std::fabs(n.x.value) + std::fabs(n.y.value) + std::fabs(n.z.value);
  const double f = n.x.error + n.y.error + n.z.error;
  if (!(max_abs <= filter_range) || !(max_error <= filter_range) || !(a + f <= dot_range)) return inf;
  return dot_inflation * (max_error * (a + f) + max_abs * f + dot_rounding * max_abs * a) + static_underflow;
}

// ---- A quotient of two running bounds (the EPA's face distances) -----------
//
// For Approx c and n standing for C >= 0 and N > 0, bounds L <= C / N <= H
// in doubles. Lower: with a = fl(c.value - c.error) > 0 and b =
// fl(n.value + n.error), (R3) gives C >= a (1 - u) and N <= b (1 + u); for
// q = fl(a / b) in [2^-1000, max] (normal; else L = 0, an overflow too) (R1) gives a / b
// >= q / (1 + u), so C / N >= q (1 - u) / (1 + u)^2; and L = fl(q G) <=
// q G (1 + u) is at most that when G <= (1 - u) / (1 + u)^3, about 1 - 4u.
// Upper: with A = fl(c.value + c.error) and B = fl(n.value - n.error) > 0
// (else H is infinite), C <= A (1 + u) and N >= B / (1 + u), and for Q =
// fl(A / B) (R1, R2) A / B <= Q (1 + u) + 2^-1075, so C / N <= (Q +
// 2^-1000) (1 + u)^3. H = fl(fl(Q + 2^-1000) G') >= (Q + 2^-1000) G' /
// (1 + u)^2 by (R4) and (R1), which covers it when G' >= (1 + u)^5. An
// infinity makes H infinite; a NaN compares false, and the caller treats
// it as "no bound".

/// G = 1 - 32u and G' = 1 + 32u: the quotient bounds' rounding factors.
inline constexpr double quotient_shrink = 1.0 - 0x1p-48;
inline constexpr double quotient_inflation = 1.0 + 0x1p-48;
/// Quotients below this give the lower bound 0 (no underflow analysis).
inline constexpr double quotient_floor = 0x1p-1000;

/// The bounds above: low <= C / N <= high.
struct QuotientBounds {
  double low = 0.0;
  double high = std::numeric_limits<double>::infinity();
};

inline QuotientBounds quotient_bounds(Approx c, Approx n) noexcept {
  QuotientBounds out;
  const double a = c.value - c.error;
  const double q = a / (n.value + n.error);
  if (a > 0 && q >= quotient_floor && q <= std::numeric_limits<double>::max()) out.low = q * quotient_shrink;
  const double b = n.value - n.error;
  if (b > 0) out.high = ((c.value + c.error) / b + quotient_floor) * quotient_inflation;
  return out;
}

}  // namespace cvms::filtered
