// SPDX-License-Identifier: MIT
// Double approximations of exact values with a proven error bound, kept next
// to the exact values so that predicates can decide in floating point first.
#pragma once

#include "cvms/vec.hpp"

namespace cvms {

/// A double `value` and a bound `error` with |value - exact| <= error.
/// error == 0 means value is the exact number. A non-finite value or error
/// means "unknown": predicates then go straight to exact arithmetic.
struct Approx {
  double value = 0.0;
  double error = 0.0;

  /// The nearest-or-truncated double of q and a bound that covers both the
  /// rounding and underflow; exact (error 0) when q is a double.
  static Approx of(const Rational& q) noexcept;
};

struct ApproxVec2 {
  Approx x, y;
  static ApproxVec2 of(const Vec2& v) noexcept { return {Approx::of(v.x), Approx::of(v.y)}; }
};

struct ApproxVec3 {
  Approx x, y, z;
  static ApproxVec3 of(const Vec3& v) noexcept {
    return {Approx::of(v.x), Approx::of(v.y), Approx::of(v.z)};
  }
};

/// An exact vector together with its cached approximation. Cheap to pass by
/// value: it only refers to storage owned elsewhere (typically a polyhedron).
struct Vec2Ref {
  const Vec2& exact;
  const ApproxVec2& approx;
};
struct Vec3Ref {
  const Vec3& exact;
  const ApproxVec3& approx;
};

}  // namespace cvms
