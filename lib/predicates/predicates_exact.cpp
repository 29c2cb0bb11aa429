// SPDX-License-Identifier: MIT
// Exact rational evaluation of every predicate (the filter's fallback).
#include "predicates_exact.hpp"

namespace cvms::exact {

Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c) { return exact::sign_cross2(b - a, c - a); }

Sign sign_cross2(const Vec2& u, const Vec2& v) { return sign_of(cmp(u.x * v.y, u.y * v.x)); }

Sign sign_dot(const Vec2& u, const Vec2& v) { return sign_of(sgn(dot(u, v))); }

Sign orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return sign_of(sgn(dot(cross(b - a, c - a), d - a)));
}

Sign sign_dot(const Vec3& u, const Vec3& v) { return sign_of(sgn(dot(u, v))); }

Sign compare_dot(const Vec3& v, const Vec3& w, const Vec3& n) { return sign_of(sgn(dot(v - w, n))); }

Sign side_of_plane(const Vec3& p, const Vec3& n, const Rational& offset) {
  return sign_of(cmp(dot(p, n), offset));
}

Sign sign_triple(const Vec3& u, const Vec3& v, const Vec3& w) { return sign_of(sgn(dot(u, cross(v, w)))); }

bool is_parallel(const Vec3& u, const Vec3& v) {
  return u.y * v.z == u.z * v.y && u.z * v.x == u.x * v.z && u.x * v.y == u.y * v.x;
}

}  // namespace cvms::exact
