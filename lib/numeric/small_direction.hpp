// SPDX-License-Identifier: MIT
// Integer directions small enough for machine integers. The edge
// facets of A + B have normal +-cross(d_A, d_B) for edge directions d_A, d_B;
// when the inputs are doubles (the common case) integer edge
// directions usually fit in 64 bits and their cross product in 128, so the output
// normals need no GMP arithmetic until the result is stored.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "approx.hpp"
#include "dyadic_points.hpp"
#include "cvms/vec.hpp"

namespace cvms::detail {

/// A nonzero integer vector whose coordinates are below 2^62 in magnitude
/// (not necessarily primitive: only its direction is used).
struct SmallDirection {
  std::array<std::int64_t, 3> c;  ///< the coordinates

  /// As a Vec3 of integers.
  [[nodiscard]] Vec3 to_vec3() const;
};

/// A positive integer multiple of to - from, when both points are exactly doubles
/// (approximation error 0 in every coordinate), their exponents are close
/// enough for 128-bit arithmetic and the result fits; nullopt otherwise (the
/// caller then uses the general rational path), and for to == from.
[[nodiscard]] std::optional<SmallDirection> small_integer_direction(const ApproxVec3& from,
                                                                    const ApproxVec3& to) noexcept;

/// Positive integer multiples of b - a and c - a (the same multiple of both),
/// when every coordinate of a, b and c is a fraction of one-limb integers
/// (decimals like 0.123456 or -0.9999510991904915) whose common denominator
/// L is below 2^63 and whose scaled numerators are below 2^61 in magnitude:
/// the differences of the points times L. nullopt otherwise (the caller then
/// uses the general rational path), and when b == a or c == a.
[[nodiscard]] std::optional<std::array<SmallDirection, 2>> small_fraction_directions(const Vec3& a, const Vec3& b,
                                                                                     const Vec3& c);
/// The same for one edge: a positive integer multiple of to - from (the
/// difference times the common denominator of the two points), under the
/// same limits; nullopt otherwise and for to == from.
[[nodiscard]] std::optional<SmallDirection> small_fraction_direction(const Vec3& from, const Vec3& to);

class LimbArena;

/// A primitive integer vector in 128-bit coordinates: the cross product of
/// two small directions, before it becomes rationals.
struct SmallNormal {
  __extension__ using Int128 = __int128;
  std::array<Int128, 3> c;  ///< the coordinates, below 2^125 in magnitude

  void negate() noexcept;
  /// ApproxVec3::of of the same vector (the same doubles and bounds),
  /// read off the integers.
  [[nodiscard]] ApproxVec3 approx() const noexcept;
  /// out = this vector, in out's existing storage.
  void assign_to(Vec3& out) const;
  /// out = this vector, numerators kept in arena (LimbArena::store_integer).
  void store(LimbArena& arena, Vec3& out) const;
  /// Packs this vector as point j of out (long numerators' limbs in arena).
  void pack(LimbArena& arena, DyadicPoints& out, std::size_t j) const;
};

/// The primitive integer vector of the direction of (x, y, z), as a
/// SmallNormal: the edge direction of two points of a two-word scaled
/// operand (two_word_scaled.hpp), whose difference is below 2^125.
/// \pre (x, y, z) is nonzero and each below 2^127 in magnitude.
[[nodiscard]] SmallNormal primitive_vector(SmallNormal::Int128 x, SmallNormal::Int128 y, SmallNormal::Int128 z) noexcept;

/// v as a SmallDirection when every coordinate is below 2^62 in magnitude;
/// nullopt otherwise.
[[nodiscard]] std::optional<SmallDirection> as_small_direction(const SmallNormal& v) noexcept;

/// A SmallDirection along the nonzero (x, y, z) (each below 2^127 in
/// magnitude): the vector divided by the powers of 2 and 5 its coordinates
/// share (what a decimal or dyadic common denominator puts in a difference
/// of scaled points, found without a gcd) when that fits, else the
/// primitive vector when it fits; nullopt otherwise.
[[nodiscard]] std::optional<SmallDirection> small_multiple(SmallNormal::Int128 x, SmallNormal::Int128 y,
                                                           SmallNormal::Int128 z) noexcept;

/// primitive_direction(cross(u, v)) in 128-bit integers.
/// \pre u and v are not parallel.
[[nodiscard]] SmallNormal primitive_cross(const SmallDirection& u, const SmallDirection& v) noexcept;

}  // namespace cvms::detail
