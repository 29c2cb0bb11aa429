// SPDX-License-Identifier: MIT
// A semi-static filter for ordering the points of one set by their dot
// product with one fixed direction: the direction's bound is set up once,
// after which a point costs three multiplications and comparing two points
// one subtraction, with no error propagation per point. The contributing-
// vertex walk's climbs decide this way (paper Section 4.2); when the filter
// cannot prove the order, the caller falls back to the running-error
// compare_dot and then to exact arithmetic.
//
// Setting and proof. The exact points P of the set are approximated by
// doubles p with |p_k - P_k| <= e and |p_k| <= M (PlaneFilterExtent), the
// direction N by n with |n_k - N_k| <= f_k. value(p) = fl(fl(fl(p_x n_x) +
// fl(p_y n_y)) + fl(p_z n_z)) is within b = dot_filter_bound(n, M, e) of
// P . N (error_bounds.hpp, "The dot-product scan"; contraction into FMA only
// removes roundings), and b >= 2^-1000. For two points, fl(v - w) > fl(3 b)
// proves P . N > W . N (error_bounds.hpp, "Comparing two filtered values").
// For one point, v > b proves P . N >= v - b > 0 (and v < -b, P . N < 0):
// the arc trace's sides of facets (the points are then the facets' normals
// and the direction an edge's).
// Out of the bound's range (huge coordinates, non-finite approximations) b
// is infinite and nothing is proved (NaN compares false too).
#pragma once

#include <optional>

#include "approx.hpp"
#include "cvms/sign.hpp"
#include "error_bounds.hpp"
#include "plane_filter.hpp"

namespace cvms {

class DotOrderFilter {
 public:
  /// For direction n over a set of the given extent.
  DotOrderFilter(const ApproxVec3& n, const PlaneFilterExtent& extent) noexcept
      : n_{n.x.value, n.y.value, n.z.value},
        bound_(filtered::dot_filter_bound(n, extent.max_abs, extent.max_error)),
        margin_(filtered::difference_margin * bound_) {}

  /// fl(p . n), in the order the bound assumes.
  [[nodiscard]] double value(const ApproxVec3& p) const noexcept {
    return p.x.value * n_[0] + p.y.value * n_[1] + p.z.value * n_[2];
  }

  /// The sign of P . N when v = value(p) proves it.
  [[nodiscard]] std::optional<Sign> sign(double v) const noexcept {
    if (v > bound_) return Sign::positive;
    if (v < -bound_) return Sign::negative;
    return std::nullopt;
  }

  /// The sign of P . N - W . N when the values v = value(p), w = value(q)
  /// prove it.
  [[nodiscard]] std::optional<Sign> compare(double v, double w) const noexcept {
    const double d = v - w;
    if (d > margin_) return Sign::positive;
    if (d < -margin_) return Sign::negative;
    return std::nullopt;
  }

 private:
  Coords n_;
  double bound_;
  double margin_;
};

}  // namespace cvms
