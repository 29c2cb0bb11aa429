// SPDX-License-Identifier: MIT
/// \file
/// Double approximations of exact values with a proven error bound, kept next
/// to the exact values so that predicates can decide in floating point first.
#pragma once

#include "cvms/vec.hpp"

namespace cvms {

/// A double `value` and a bound `error` with |value - exact| <= error.
/// error == 0 means value is the exact number. A non-finite value or error
/// means "unknown": predicates then go straight to exact arithmetic.
struct Approx {
  double value = 0.0;  ///< the approximation
  double error = 0.0;  ///< a bound on |value - exact|, >= 0

  /// The nearest-or-truncated double of q and a bound that covers both the
  /// rounding and underflow; exact (error 0) when q is a double.
  static Approx of(const Rational& q) noexcept;
  /// A double within error of n / d for integers n and d > 0, from their
  /// top bits: no division of the integers, no gcd (the fraction need not
  /// be reduced). The bound is |value| 2^-51, twice that of `of`; when the
  /// integers' lengths differ by about 900 bits or more, the value is
  /// mpq_get_d's truncation of n / d instead, with `of`'s bound.
  static Approx of_quotient(mpz_srcptr n, mpz_srcptr d) noexcept;
};

/// True only if the exact values a and b approximate differ: |a.value -
/// b.value| > 2 (a.error + b.error) as computed. The computed difference is
/// within a factor 1 + u of the true one, and the computed error sum at least
/// (1 - u) times the true one (exact when subnormal), so the approximations
/// differ by more than 2 (1 - u) / (1 + u) (a.error + b.error) >= a.error +
/// b.error, and the exact values by more than zero. Infinite or NaN values or errors make the
/// comparison false: undecided, never wrong.
inline bool provably_different(const Approx& a, const Approx& b) noexcept {
  const double difference = a.value - b.value;
  return (difference < 0 ? -difference : difference) > 2.0 * (a.error + b.error);
}

/// Approximations of the two coordinates of a Vec2.
struct ApproxVec2 {
  ///@{
  /// The approximations of the coordinates.
  Approx x, y;
  ///@}
  /// Approximates each coordinate with Approx::of.
  static ApproxVec2 of(const Vec2& v) noexcept { return {Approx::of(v.x), Approx::of(v.y)}; }
};

/// Approximations of the three coordinates of a Vec3.
struct ApproxVec3 {
  ///@{
  /// The approximations of the coordinates.
  Approx x, y, z;
  ///@}
  /// Approximates each coordinate with Approx::of.
  static ApproxVec3 of(const Vec3& v) noexcept {
    return {Approx::of(v.x), Approx::of(v.y), Approx::of(v.z)};
  }
};

/// True only if the exact vectors a and b approximate differ: some
/// coordinate is provably different (the scalar test above).
inline bool provably_different(const ApproxVec3& a, const ApproxVec3& b) noexcept {
  return provably_different(a.x, b.x) || provably_different(a.y, b.y) || provably_different(a.z, b.z);
}

/// An exact vector together with its cached approximation. Cheap to pass by
/// value: it only refers to storage owned elsewhere (typically a polyhedron).
/// \pre approx approximates exact (ApproxVec2::of(exact) or a tighter bound);
///   both outlive the reference.
struct Vec2Ref {
  const Vec2& exact;          ///< the exact vector
  const ApproxVec2& approx;   ///< its approximation
};
/// The 3D counterpart of Vec2Ref (see ConvexPolyhedron::vertex_ref()).
/// \pre approx approximates exact; both outlive the reference.
struct Vec3Ref {
  const Vec3& exact;          ///< the exact vector
  const ApproxVec3& approx;   ///< its approximation
};

}  // namespace cvms
