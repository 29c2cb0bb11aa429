// SPDX-License-Identifier: MIT
/// \file
/// Exact 2D and 3D vectors of rationals. No sqrt, no angles, no normalisation:
/// everything stays exact, directions are compared with predicates.
#pragma once

#include <cstddef>
#include <functional>

#include "cvms/rational.hpp"

namespace cvms {

/// An exact 2D vector or point. Plain aggregate: `Vec2{1, Rational(1, 3)}`.
struct Vec2 {
  ///@{
  /// The exact coordinates.
  Rational x, y;
  ///@}

  /// Componentwise sum.
  friend Vec2 operator+(const Vec2& a, const Vec2& b) { return {a.x + b.x, a.y + b.y}; }
  /// Componentwise difference.
  friend Vec2 operator-(const Vec2& a, const Vec2& b) { return {a.x - b.x, a.y - b.y}; }
  /// Negation.
  friend Vec2 operator-(const Vec2& a) { return {-a.x, -a.y}; }
  /// Scaling by s.
  friend Vec2 operator*(const Rational& s, const Vec2& a) { return {s * a.x, s * a.y}; }
  /// Scaling by s.
  friend Vec2 operator*(const Vec2& a, const Rational& s) { return s * a; }
  /// Adds b.
  Vec2& operator+=(const Vec2& b) { x += b.x; y += b.y; return *this; }
  /// Subtracts b.
  Vec2& operator-=(const Vec2& b) { x -= b.x; y -= b.y; return *this; }
  /// Exact equality.
  friend bool operator==(const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }
  /// Exact inequality.
  friend bool operator!=(const Vec2& a, const Vec2& b) { return !(a == b); }
  /// Lexicographic (x, then y); gives a total order for sorting and maps.
  friend bool operator<(const Vec2& a, const Vec2& b) {
    int c = cmp(a.x, b.x);
    return c != 0 ? c < 0 : a.y < b.y;
  }
};

/// The dot product, exact.
inline Rational dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
/// The z component of the 3D cross product: positive when b is counterclockwise of a.
inline Rational cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }

/// An exact 3D vector or point. Plain aggregate: `Vec3{1, 0, Rational(1, 3)}`.
struct Vec3 {
  ///@{
  /// The exact coordinates.
  Rational x, y, z;
  ///@}

  /// Componentwise sum.
  friend Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  /// Componentwise difference.
  friend Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  /// Negation.
  friend Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
  /// Scaling by s.
  friend Vec3 operator*(const Rational& s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
  /// Scaling by s.
  friend Vec3 operator*(const Vec3& a, const Rational& s) { return s * a; }
  /// Adds b.
  Vec3& operator+=(const Vec3& b) { x += b.x; y += b.y; z += b.z; return *this; }
  /// Subtracts b.
  Vec3& operator-=(const Vec3& b) { x -= b.x; y -= b.y; z -= b.z; return *this; }
  /// Coordinate i: x, y, z for 0, 1, 2. \pre 0 <= i <= 2 (anything else gives z).
  const Rational& operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  /// Coordinate i: x, y, z for 0, 1, 2. \pre 0 <= i <= 2 (anything else gives z).
  Rational& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  /// Exact equality.
  friend bool operator==(const Vec3& a, const Vec3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  }
  /// Exact inequality.
  friend bool operator!=(const Vec3& a, const Vec3& b) { return !(a == b); }
  /// Lexicographic (x, y, z); gives a total order for sorting and maps.
  friend bool operator<(const Vec3& a, const Vec3& b) {
    int c = cmp(a.x, b.x);
    if (c != 0) return c < 0;
    c = cmp(a.y, b.y);
    return c != 0 ? c < 0 : a.z < b.z;
  }
};

/// The dot product, exact.
inline Rational dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
/// The cross product, exact (not normalised): orthogonal to a and b, and
/// (a, b, cross(a, b)) is right-handed when a and b are not parallel.
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// True iff every coordinate is 0.
inline bool is_zero(const Vec3& a) { return sgn(a.x) == 0 && sgn(a.y) == 0 && sgn(a.z) == 0; }

/// A 3x3 matrix of rationals, row-major; used for exact rotations and scalings.
struct Mat3 {
  Rational m[3][3];  ///< m[row][column]; zero-initialised
  /// The identity matrix.
  static Mat3 identity();
  /// The matrix-vector product a v.
  friend Vec3 operator*(const Mat3& a, const Vec3& v) {
    return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
            a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
            a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
  }
  /// The matrix product a b (apply b first).
  friend Mat3 operator*(const Mat3& a, const Mat3& b);
  /// The exact determinant (negative: the map reverses orientation).
  [[nodiscard]] Rational determinant() const;
};

/// Hash of an exact value; equal values hash equal (GMP keeps rationals canonical).
/// Deterministic and made of invertible mixing steps, so it is not
/// collision resistant: anyone can make many values with one hash, and a
/// hash container keyed by untrusted values can be driven quadratic. The
/// library never keys untrusted input by it (readers and Mesh::from_soup
/// deduplicate by sorting); sort, or use an ordered container, for such data.
std::size_t hash_value(const Rational& value) noexcept;
/// Hash of an exact 2D vector, for unordered containers (see std::hash<Vec2>).
std::size_t hash_value(const Vec2& v) noexcept;
/// Hash of an exact 3D vector, for unordered containers (see std::hash<Vec3>).
std::size_t hash_value(const Vec3& v) noexcept;

}  // namespace cvms

// Written inside namespace std rather than as `struct std::hash<...>`: the
// same meaning, and doxygen 1.9 handles only this form.
namespace std {
/// Lets Vec2 be a key of std::unordered_map / unordered_set.
template <>
struct hash<cvms::Vec2> {
  /// cvms::hash_value(v).
  std::size_t operator()(const cvms::Vec2& v) const noexcept { return cvms::hash_value(v); }
};
/// Lets Vec3 be a key of std::unordered_map / unordered_set.
template <>
struct hash<cvms::Vec3> {
  /// cvms::hash_value(v).
  std::size_t operator()(const cvms::Vec3& v) const noexcept { return cvms::hash_value(v); }
};
}  // namespace std
