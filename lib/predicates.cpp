// SPDX-License-Identifier: MIT
// Exact evaluation of every predicate. (The floating-point filter is layered
// in front of these in predicates_filter.cpp.)
#include "cvms/predicates.hpp"

namespace cvms {

PredicateCounters& predicate_counters() noexcept {
  thread_local PredicateCounters counters;
  return counters;
}

namespace {
Sign count_exact(int s) {
  ++predicate_counters().exact;
  return sign_of(s);
}
}  // namespace

Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c) { return count_exact(sgn(cross(b - a, c - a))); }
Sign orient2d(Vec2Ref a, Vec2Ref b, Vec2Ref c) { return orient2d(a.exact, b.exact, c.exact); }
Sign sign_cross2(const Vec2& u, const Vec2& v) { return count_exact(cmp(u.x * v.y, u.y * v.x)); }
Sign sign_cross2(Vec2Ref u, Vec2Ref v) { return sign_cross2(u.exact, v.exact); }

bool ccw_in_between(const Vec2& d, const Vec2& d1, const Vec2& d2) {
  // Sector from d1 counterclockwise to d2 (exclusive of both boundaries).
  Sign s1 = sign_cross2(d1, d);   // d left of d1
  Sign s2 = sign_cross2(d, d2);   // d2 left of d
  Sign s12 = sign_cross2(d1, d2);
  if (s12 == Sign::positive) return s1 == Sign::positive && s2 == Sign::positive;
  if (s12 == Sign::negative) return !(s1 != Sign::positive && s2 != Sign::positive);
  // d1 and d2 on one line: same direction -> all but that direction;
  // opposite directions -> the half-plane to the left of d1.
  if (sgn(dot(d1, d2)) > 0) return !(s1 == Sign::zero && sgn(dot(d1, d)) > 0);
  return s1 == Sign::positive;
}

Sign orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return count_exact(sgn(dot(cross(b - a, c - a), d - a)));
}
Sign orient3d(Vec3Ref a, Vec3Ref b, Vec3Ref c, Vec3Ref d) { return orient3d(a.exact, b.exact, c.exact, d.exact); }
Sign sign_dot(const Vec3& u, const Vec3& v) { return count_exact(sgn(dot(u, v))); }
Sign sign_dot(Vec3Ref u, Vec3Ref v) { return sign_dot(u.exact, v.exact); }
Sign compare_dot(const Vec3& v, const Vec3& w, const Vec3& n) { return count_exact(cmp(dot(v, n), dot(w, n))); }
Sign compare_dot(Vec3Ref v, Vec3Ref w, Vec3Ref n) { return compare_dot(v.exact, w.exact, n.exact); }
Sign side_of_plane(const Vec3& p, const Vec3& n, const Rational& offset) { return count_exact(cmp(dot(p, n), offset)); }
Sign sign_triple(const Vec3& u, const Vec3& v, const Vec3& w) { return count_exact(sgn(dot(u, cross(v, w)))); }
Sign sign_triple(Vec3Ref u, Vec3Ref v, Vec3Ref w) { return sign_triple(u.exact, v.exact, w.exact); }
bool is_parallel(const Vec3& u, const Vec3& v) {
  ++predicate_counters().exact;
  return u.y * v.z == u.z * v.y && u.z * v.x == u.x * v.z && u.x * v.y == u.y * v.x;
}
bool is_parallel(Vec3Ref u, Vec3Ref v) { return is_parallel(u.exact, v.exact); }

}  // namespace cvms
