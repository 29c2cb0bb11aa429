// SPDX-License-Identifier: MIT
// A semi-static filter for orient3d against one fixed triangle: the triangle's
// plane is set up once in double (its normal and one error bound for every
// point of the set), after which testing a point costs six multiplications
// and one comparison, with no error propagation per test. The hull's conflict
// tests decide this way; when the bound cannot prove the sign, the caller
// falls back to the exact predicate. Private to the library.
//
// Setting. The exact points P of a set are approximated by doubles p with
// |p_k - P_k| <= e for every coordinate (e = 0 when the points are doubles),
// and |p_k| <= M. For a triangle a, b, c and a point p the filter computes
//   u = fl(b - a), v = fl(c - a), d = fl(p - a),
//   n_x = fl(fl(u_y v_z) - fl(u_z v_y))  (and cyclically),
//   s = fl(fl(fl(d_x n_x) + fl(d_y n_y)) + fl(d_z n_z)),
// which approximates S = orient3d(A, B, C, P) = det[B - A, C - A, P - A].
//
// Rounding error (u = 2^-53, gamma_k = k u / (1 - k u); Higham, "Accuracy and
// Stability of Numerical Algorithms", 3.1). Ignoring underflow, each of the
// six monomials D_i U_j V_k of S' = det[b - a, c - a, p - a] (the determinant
// of the approximations) reaches s through at most 8 roundings (d, u, v, their
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
// Overflow: with M, e <= 2^300 every intermediate stays below 2^1000; larger
// sets (or non-finite approximations) get an infinite bound, which never
// proves anything (NaN compares false too).
#pragma once

#include <array>
#include <cmath>
#include <limits>

namespace cvms {

/// A point's double approximation.
using Coords = std::array<double, 3>;

/// What the filter needs to know about a point set: twice the largest
/// coordinate magnitude, and the absolute error terms (see above).
struct PlaneFilterScale {
  double span = std::numeric_limits<double>::infinity();   ///< 2M
  double slack = std::numeric_limits<double>::infinity();  ///< input and underflow terms

  /// For approximations with |p_k| <= max_abs and |p_k - P_k| <= max_error.
  static PlaneFilterScale of(double max_abs, double max_error) noexcept {
    constexpr double limit = 0x1p300;
    if (!(max_abs <= limit) || !(max_error <= limit)) return {};
    const double w = 2.0 * max_abs + 2.0 * max_error;
    return {2.0 * max_abs, 64.0 * max_error * w * w + (max_abs * 0x1p-1000 + 0x1p-1000)};
  }
};

/// The plane of one triangle, ready to test many points against it.
struct PlaneFilter {
  Coords a;      ///< the first corner
  Coords n;      ///< fl(cross(b - a, c - a)) as above
  double bound;  ///< |s - S| <= bound for every point of the set

  static PlaneFilter of(const Coords& a, const Coords& b, const Coords& c,
                        const PlaneFilterScale& scale) noexcept {
    const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
    const double yz = uy * vz, zy = uz * vy, zx = uz * vx, xz = ux * vz, xy = ux * vy, yx = uy * vx;
    const double q =
        (std::fabs(yz) + std::fabs(zy)) + (std::fabs(zx) + std::fabs(xz)) + (std::fabs(xy) + std::fabs(yx));
    return {a, {yz - zy, zx - xz, xy - yx}, 9.0 * 0x1p-53 * scale.span * q + scale.slack};
  }

  /// s for point p: approximately orient3d(a, b, c, p).
  [[nodiscard]] double value(const Coords& p) const noexcept {
    return (p[0] - a[0]) * n[0] + (p[1] - a[1]) * n[1] + (p[2] - a[2]) * n[2];
  }
  /// True iff the value proves that the point is strictly above the plane.
  [[nodiscard]] bool above(double s) const noexcept { return s > bound; }
  /// True iff the value proves that the point is strictly below the plane.
  [[nodiscard]] bool below(double s) const noexcept { return s < -bound; }
};

}  // namespace cvms
