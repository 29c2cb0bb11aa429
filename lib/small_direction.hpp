// SPDX-License-Identifier: MIT
// Primitive integer directions small enough for machine integers. The edge
// facets of A + B have normal +-cross(d_A, d_B) for edge directions d_A, d_B;
// when the inputs are doubles (the common case) the primitive edge
// directions fit in 64 bits and their cross product in 128, so the output
// normals need no GMP arithmetic until the result is stored.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "cvms/approx.hpp"
#include "cvms/vec.hpp"

namespace cvms::detail {

/// A primitive integer vector (coordinates with gcd 1, not all zero) whose
/// coordinates are below 2^62 in magnitude.
struct SmallDirection {
  std::array<std::int64_t, 3> c;  ///< the coordinates

  /// As a Vec3 of integers.
  [[nodiscard]] Vec3 to_vec3() const;
};

/// The primitive direction of to - from, when both points are exactly doubles
/// (approximation error 0 in every coordinate), their exponents are close
/// enough for 128-bit arithmetic and the result fits; nullopt otherwise (the
/// caller then uses the general rational path), and for to == from.
[[nodiscard]] std::optional<SmallDirection> small_primitive_direction(const ApproxVec3& from,
                                                                      const ApproxVec3& to) noexcept;

/// primitive_direction(cross(u, v)), computed in 128-bit integers.
/// \pre u and v are not parallel.
[[nodiscard]] Vec3 primitive_cross(const SmallDirection& u, const SmallDirection& v);

}  // namespace cvms::detail
