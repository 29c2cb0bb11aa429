// SPDX-License-Identifier: MIT
// Exact 2D and 3D vectors of rationals. No sqrt, no angles, no normalisation:
// everything stays exact, directions are compared with predicates.
#pragma once

#include <cstddef>
#include <functional>

#include "cvms/rational.hpp"

namespace cvms {

struct Vec2 {
  Rational x, y;

  friend Vec2 operator+(const Vec2& a, const Vec2& b) { return {a.x + b.x, a.y + b.y}; }
  friend Vec2 operator-(const Vec2& a, const Vec2& b) { return {a.x - b.x, a.y - b.y}; }
  friend Vec2 operator-(const Vec2& a) { return {-a.x, -a.y}; }
  friend Vec2 operator*(const Rational& s, const Vec2& a) { return {s * a.x, s * a.y}; }
  friend Vec2 operator*(const Vec2& a, const Rational& s) { return s * a; }
  Vec2& operator+=(const Vec2& b) { x += b.x; y += b.y; return *this; }
  Vec2& operator-=(const Vec2& b) { x -= b.x; y -= b.y; return *this; }
  friend bool operator==(const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }
  friend bool operator!=(const Vec2& a, const Vec2& b) { return !(a == b); }
  /// Lexicographic (x, then y); gives a total order for sorting and maps.
  friend bool operator<(const Vec2& a, const Vec2& b) {
    int c = cmp(a.x, b.x);
    return c != 0 ? c < 0 : a.y < b.y;
  }
};

inline Rational dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
/// The z component of the 3D cross product: positive when b is counterclockwise of a.
inline Rational cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }

struct Vec3 {
  Rational x, y, z;

  friend Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
  friend Vec3 operator*(const Rational& s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
  friend Vec3 operator*(const Vec3& a, const Rational& s) { return s * a; }
  Vec3& operator+=(const Vec3& b) { x += b.x; y += b.y; z += b.z; return *this; }
  Vec3& operator-=(const Vec3& b) { x -= b.x; y -= b.y; z -= b.z; return *this; }
  const Rational& operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  Rational& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  friend bool operator==(const Vec3& a, const Vec3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  }
  friend bool operator!=(const Vec3& a, const Vec3& b) { return !(a == b); }
  /// Lexicographic (x, y, z); gives a total order for sorting and maps.
  friend bool operator<(const Vec3& a, const Vec3& b) {
    int c = cmp(a.x, b.x);
    if (c != 0) return c < 0;
    c = cmp(a.y, b.y);
    return c != 0 ? c < 0 : a.z < b.z;
  }
};

inline Rational dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline bool is_zero(const Vec3& a) { return sgn(a.x) == 0 && sgn(a.y) == 0 && sgn(a.z) == 0; }

/// A 3x3 matrix of rationals, row-major; used for exact rotations and scalings.
struct Mat3 {
  Rational m[3][3];
  static Mat3 identity();
  friend Vec3 operator*(const Mat3& a, const Vec3& v) {
    return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
            a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
            a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
  }
  friend Mat3 operator*(const Mat3& a, const Mat3& b);
  [[nodiscard]] Rational determinant() const;
};

/// Hash of an exact value; equal values hash equal (GMP keeps rationals canonical).
std::size_t hash_value(const Rational& value) noexcept;
std::size_t hash_value(const Vec2& v) noexcept;
std::size_t hash_value(const Vec3& v) noexcept;

}  // namespace cvms

template <>
struct std::hash<cvms::Vec2> {
  std::size_t operator()(const cvms::Vec2& v) const noexcept { return cvms::hash_value(v); }
};
template <>
struct std::hash<cvms::Vec3> {
  std::size_t operator()(const cvms::Vec3& v) const noexcept { return cvms::hash_value(v); }
};
