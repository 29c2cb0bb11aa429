// SPDX-License-Identifier: MIT
// The filtered predicates: each polynomial is evaluated in double with a
// running error bound (filtered_arithmetic.hpp holds the proof); when the
// bound proves the sign we answer, otherwise we evaluate exactly
// (predicates_exact.cpp). Every call counts one filter success or one
// fallback in this thread's predicate_counters().
//
// Each polynomial is written once as a template over the leaf type: either
// Approx (cached or on-the-fly approximations with an error) or double (all
// input errors are zero, the common case for inputs that were doubles, where
// the first operations need no error propagation at all).
#include "filtered_predicates.hpp"

#include <utility>

#include "filtered_arithmetic.hpp"
#include "predicates_exact.hpp"

namespace cvms {

PredicateCounters& predicate_counters() noexcept {
  thread_local PredicateCounters counters;
  return counters;
}

namespace {

using filtered::add;
using filtered::mul;
using filtered::sub;

struct Doubles2 {
  double x, y;
};
struct Doubles3 {
  double x, y, z;
};

Doubles2 values(const ApproxVec2& a) noexcept { return {a.x.value, a.y.value}; }
Doubles3 values(const ApproxVec3& a) noexcept { return {a.x.value, a.y.value, a.z.value}; }

// True iff every coordinate of every argument is exactly its double. The
// errors are nonnegative, so a zero sum means all are zero (NaN is not 0).
bool all_exact(const ApproxVec2& a) noexcept { return a.x.error + a.y.error == 0.0; }
bool all_exact(const ApproxVec3& a) noexcept { return a.x.error + a.y.error + a.z.error == 0.0; }
template <class... Vs>
bool all_exact(const Vs&... vs) noexcept {
  return (all_exact(vs) && ...);
}

// Answers from the filter when it proves the sign, else from `exact_sign`.
template <class ExactSign>
Sign decide(Approx r, ExactSign&& exact_sign) {
  PredicateCounters& counters = predicate_counters();
  if (filtered::certain(r)) {
    ++counters.filtered;
    return filtered::sign(r);
  }
  ++counters.exact;
  return std::forward<ExactSign>(exact_sign)();
}

// --- the polynomials, over leaf vectors V (ApproxVecN or DoublesN) ---

template <class V>
Approx cross2_approx(const V& u, const V& v) noexcept {
  return sub(mul(u.x, v.y), mul(u.y, v.x));
}

template <class V>
Approx dot2_approx(const V& u, const V& v) noexcept {
  return add(mul(u.x, v.x), mul(u.y, v.y));
}

template <class V>
Approx orient2d_approx(const V& a, const V& b, const V& c) noexcept {
  Approx bx = sub(b.x, a.x), by = sub(b.y, a.y);
  Approx cx = sub(c.x, a.x), cy = sub(c.y, a.y);
  return sub(mul(bx, cy), mul(by, cx));
}

template <class V>
Approx dot3_approx(const V& u, const V& v) noexcept {
  return add(add(mul(u.x, v.x), mul(u.y, v.y)), mul(u.z, v.z));
}

// dot(u, cross(v, w)) for leaves or already-propagated Approx triples.
template <class U, class V>
Approx triple_approx(const U& ux, const U& uy, const U& uz, const V& v, const V& w) noexcept {
  Approx cx = sub(mul(v.y, w.z), mul(v.z, w.y));
  Approx cy = sub(mul(v.z, w.x), mul(v.x, w.z));
  Approx cz = sub(mul(v.x, w.y), mul(v.y, w.x));
  return add(add(mul(ux, cx), mul(uy, cy)), mul(uz, cz));
}

struct Approx3 {
  Approx x, y, z;
};

template <class V>
Approx3 difference(const V& a, const V& b) noexcept {
  return {sub(a.x, b.x), sub(a.y, b.y), sub(a.z, b.z)};
}

// det[b - a, c - a, d - a] = dot(d - a, cross(b - a, c - a)).
template <class V>
Approx orient3d_approx(const V& a, const V& b, const V& c, const V& d) noexcept {
  Approx3 ba = difference(b, a), ca = difference(c, a), da = difference(d, a);
  return triple_approx(da.x, da.y, da.z, ba, ca);
}

// dot(v - w, n): one subtraction per coordinate instead of two dot products.
template <class V>
Approx compare_dot_approx(const V& v, const V& w, const V& n) noexcept {
  Approx3 d = difference(v, w);
  return add(add(mul(d.x, n.x), mul(d.y, n.y)), mul(d.z, n.z));
}

template <class V>
Approx3 cross3_approx(const V& u, const V& v) noexcept {
  return {sub(mul(u.y, v.z), mul(u.z, v.y)), sub(mul(u.z, v.x), mul(u.x, v.z)),
          sub(mul(u.x, v.y), mul(u.y, v.x))};
}

}  // namespace

Sign orient2d(Vec2Ref a, Vec2Ref b, Vec2Ref c) {
  const ApproxVec2 &pa = a.approx, &pb = b.approx, &pc = c.approx;
  Approx r = all_exact(pa, pb, pc) ? orient2d_approx(values(pa), values(pb), values(pc))
                                   : orient2d_approx(pa, pb, pc);
  return decide(r, [&] { return exact::orient2d(a.exact, b.exact, c.exact); });
}
Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  ApproxVec2 pa = ApproxVec2::of(a), pb = ApproxVec2::of(b), pc = ApproxVec2::of(c);
  return orient2d(Vec2Ref{a, pa}, Vec2Ref{b, pb}, Vec2Ref{c, pc});
}

Sign sign_cross2(Vec2Ref u, Vec2Ref v) {
  const ApproxVec2 &pu = u.approx, &pv = v.approx;
  Approx r = all_exact(pu, pv) ? cross2_approx(values(pu), values(pv)) : cross2_approx(pu, pv);
  return decide(r, [&] { return exact::sign_cross2(u.exact, v.exact); });
}
Sign sign_cross2(const Vec2& u, const Vec2& v) {
  ApproxVec2 pu = ApproxVec2::of(u), pv = ApproxVec2::of(v);
  return sign_cross2(Vec2Ref{u, pu}, Vec2Ref{v, pv});
}

Sign sign_dot(Vec2Ref u, Vec2Ref v) {
  const ApproxVec2 &pu = u.approx, &pv = v.approx;
  Approx r = all_exact(pu, pv) ? dot2_approx(values(pu), values(pv)) : dot2_approx(pu, pv);
  return decide(r, [&] { return exact::sign_dot(u.exact, v.exact); });
}
Sign sign_dot(const Vec2& u, const Vec2& v) {
  ApproxVec2 pu = ApproxVec2::of(u), pv = ApproxVec2::of(v);
  return sign_dot(Vec2Ref{u, pu}, Vec2Ref{v, pv});
}

bool ccw_in_between(Vec2Ref d, Vec2Ref d1, Vec2Ref d2) {
  // The sector from d1 counterclockwise to d2, both boundaries excluded.
  Sign s12 = sign_cross2(d1, d2);
  if (s12 == Sign::positive) {
    // Sector narrower than a half-turn: strictly left of d1 and right of d2.
    return sign_cross2(d1, d) == Sign::positive && sign_cross2(d, d2) == Sign::positive;
  }
  if (s12 == Sign::negative) {
    // Wider than a half-turn: everything outside the closed sector from d2
    // to d1, which is narrower than a half-turn.
    return sign_cross2(d1, d) == Sign::positive || sign_cross2(d, d2) == Sign::positive;
  }
  Sign s1 = sign_cross2(d1, d);
  // d1 and d2 on one line. Same direction: all but that direction;
  // opposite directions: the open half-plane to the left of d1.
  if (sign_dot(d1, d2) == Sign::positive) return !(s1 == Sign::zero && sign_dot(d1, d) == Sign::positive);
  return s1 == Sign::positive;
}
bool ccw_in_between(const Vec2& d, const Vec2& d1, const Vec2& d2) {
  ApproxVec2 p = ApproxVec2::of(d), p1 = ApproxVec2::of(d1), p2 = ApproxVec2::of(d2);
  return ccw_in_between(Vec2Ref{d, p}, Vec2Ref{d1, p1}, Vec2Ref{d2, p2});
}

Sign orient3d(Vec3Ref a, Vec3Ref b, Vec3Ref c, Vec3Ref d) {
  const ApproxVec3 &pa = a.approx, &pb = b.approx, &pc = c.approx, &pd = d.approx;
  Approx r = all_exact(pa, pb, pc, pd) ? orient3d_approx(values(pa), values(pb), values(pc), values(pd))
                                       : orient3d_approx(pa, pb, pc, pd);
  return decide(r, [&] { return exact::orient3d(a.exact, b.exact, c.exact, d.exact); });
}
Sign orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  ApproxVec3 pa = ApproxVec3::of(a), pb = ApproxVec3::of(b), pc = ApproxVec3::of(c), pd = ApproxVec3::of(d);
  return orient3d(Vec3Ref{a, pa}, Vec3Ref{b, pb}, Vec3Ref{c, pc}, Vec3Ref{d, pd});
}

Sign sign_dot(Vec3Ref u, Vec3Ref v) {
  const ApproxVec3 &pu = u.approx, &pv = v.approx;
  Approx r = all_exact(pu, pv) ? dot3_approx(values(pu), values(pv)) : dot3_approx(pu, pv);
  return decide(r, [&] { return exact::sign_dot(u.exact, v.exact); });
}
Sign sign_dot(const Vec3& u, const Vec3& v) {
  ApproxVec3 pu = ApproxVec3::of(u), pv = ApproxVec3::of(v);
  return sign_dot(Vec3Ref{u, pu}, Vec3Ref{v, pv});
}

Sign compare_dot(Vec3Ref v, Vec3Ref w, Vec3Ref n) {
  const ApproxVec3 &pv = v.approx, &pw = w.approx, &pn = n.approx;
  Approx r = all_exact(pv, pw, pn) ? compare_dot_approx(values(pv), values(pw), values(pn))
                                   : compare_dot_approx(pv, pw, pn);
  return decide(r, [&] { return exact::compare_dot(v.exact, w.exact, n.exact); });
}
Sign compare_dot(const Vec3& v, const Vec3& w, const Vec3& n) {
  ApproxVec3 pv = ApproxVec3::of(v), pw = ApproxVec3::of(w), pn = ApproxVec3::of(n);
  return compare_dot(Vec3Ref{v, pv}, Vec3Ref{w, pw}, Vec3Ref{n, pn});
}

Sign side_of_plane(Vec3Ref p, Vec3Ref n, const Rational& offset, Approx offset_approx) {
  const ApproxVec3 &pp = p.approx, &pn = n.approx;
  Approx dot_pn = all_exact(pp, pn) ? dot3_approx(values(pp), values(pn)) : dot3_approx(pp, pn);
  Approx r = sub(dot_pn, offset_approx);
  return decide(r, [&] { return exact::side_of_plane(p.exact, n.exact, offset); });
}
Sign side_of_plane(const Vec3& p, const Vec3& n, const Rational& offset) {
  ApproxVec3 pp = ApproxVec3::of(p), pn = ApproxVec3::of(n);
  return side_of_plane(Vec3Ref{p, pp}, Vec3Ref{n, pn}, offset, Approx::of(offset));
}

Sign sign_triple(Vec3Ref u, Vec3Ref v, Vec3Ref w) {
  const ApproxVec3 &pu = u.approx, &pv = v.approx, &pw = w.approx;
  Approx r;
  if (all_exact(pu, pv, pw)) {
    Doubles3 du = values(pu);
    r = triple_approx(du.x, du.y, du.z, values(pv), values(pw));
  } else {
    r = triple_approx(pu.x, pu.y, pu.z, pv, pw);
  }
  return decide(r, [&] { return exact::sign_triple(u.exact, v.exact, w.exact); });
}
Sign sign_triple(const Vec3& u, const Vec3& v, const Vec3& w) {
  ApproxVec3 pu = ApproxVec3::of(u), pv = ApproxVec3::of(v), pw = ApproxVec3::of(w);
  return sign_triple(Vec3Ref{u, pu}, Vec3Ref{v, pv}, Vec3Ref{w, pw});
}

bool is_parallel(Vec3Ref u, Vec3Ref v) {
  // The filter can prove a component of cross(u, v) nonzero, never zero: if
  // any component is provably nonzero the vectors are not parallel.
  const ApproxVec3 &pu = u.approx, &pv = v.approx;
  Approx3 c = all_exact(pu, pv) ? cross3_approx(values(pu), values(pv)) : cross3_approx(pu, pv);
  PredicateCounters& counters = predicate_counters();
  if (filtered::certain(c.x) || filtered::certain(c.y) || filtered::certain(c.z)) {
    ++counters.filtered;
    return false;
  }
  ++counters.exact;
  return exact::is_parallel(u.exact, v.exact);
}
bool is_parallel(const Vec3& u, const Vec3& v) {
  ApproxVec3 pu = ApproxVec3::of(u), pv = ApproxVec3::of(v);
  return is_parallel(Vec3Ref{u, pu}, Vec3Ref{v, pv});
}

}  // namespace cvms
