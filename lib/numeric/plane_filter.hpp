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
// s = fl(fl(p - a) . n), n = fl(cross(fl(b - a), fl(c - a))), an
// approximation of S = orient3d(A, B, C, P). The bound |s - S| <= bound and
// its proof (rounding, underflow, input error, overflow) are in
// error_bounds.hpp, "The plane filter"; sets beyond its range (M or e above
// 2^300, or non-finite approximations) get an infinite bound, which never
// proves anything (NaN compares false too).
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "approx.hpp"
#include "cvms/sign.hpp"
#include "error_bounds.hpp"

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
    if (!(max_abs <= filtered::filter_range) || !(max_error <= filtered::filter_range)) return {};
    return {2.0 * max_abs, filtered::plane_filter_slack(max_abs, max_error)};
  }
};

/// The largest coordinate magnitude and error bound over the points of a set,
/// gathered one point at a time. A NaN (never produced, but cheap to exclude)
/// would compare false: it is folded into an infinite maximum, which
/// disables the filter.
struct PlaneFilterExtent {
  static constexpr double infinity = std::numeric_limits<double>::infinity();
  double max_abs = 0;
  double max_error = 0;

  void add_value(double x) noexcept {
    max_abs = std::fabs(x) <= max_abs ? max_abs : (std::isnan(x) ? infinity : std::fabs(x));
  }
  void add_error(double e) noexcept {
    max_error = e <= max_error ? max_error : (std::isnan(e) ? infinity : e);
  }
  void add(const Approx& c) noexcept {
    add_value(c.value);
    add_error(c.error);
  }
  void add(const ApproxVec3& p) noexcept {
    add(p.x);
    add(p.y);
    add(p.z);
  }
  void add(const Coords& p) noexcept {
    for (double x : p) add_value(x);
  }
  [[nodiscard]] PlaneFilterScale scale() const noexcept { return PlaneFilterScale::of(max_abs, max_error); }
};

/// The doubles of an approximation (its error bounds are the set's business).
inline Coords coords_of(const ApproxVec3& p) noexcept { return {p.x.value, p.y.value, p.z.value}; }

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
    return {a, {yz - zy, zx - xz, xy - yx}, filtered::plane_filter_bound(scale.span, q, scale.slack)};
  }

  /// s for point p: approximately orient3d(a, b, c, p).
  [[nodiscard]] double value(const Coords& p) const noexcept {
    return (p[0] - a[0]) * n[0] + (p[1] - a[1]) * n[1] + (p[2] - a[2]) * n[2];
  }
  /// True iff the value proves that the point is strictly above the plane.
  [[nodiscard]] bool above(double s) const noexcept { return s > bound; }
  /// True iff the value proves that the point is strictly below the plane.
  [[nodiscard]] bool below(double s) const noexcept { return s < -bound; }
  /// The sign of orient3d that the value s proves, if it proves one.
  [[nodiscard]] std::optional<Sign> sign_if_certain(double s) const noexcept {
    if (above(s)) return Sign::positive;
    if (below(s)) return Sign::negative;
    return std::nullopt;
  }
};

/// The sign of V - W for doubles v, w each within `bound` (at least
/// 2^-1022, as every semi-static bound is) of exact values V, W, when their
/// computed difference proves it: beyond 3 bounds, 2 for the values and 1 for
/// the rounding (error_bounds.hpp, "Comparing two filtered values").
inline std::optional<Sign> difference_sign_if_certain(double v, double w, double bound) noexcept {
  const double difference = v - w, margin = filtered::difference_margin * bound;
  if (difference > margin) return Sign::positive;
  if (-difference > margin) return Sign::negative;
  return std::nullopt;
}

}  // namespace cvms
