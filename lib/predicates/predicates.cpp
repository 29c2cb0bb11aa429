// SPDX-License-Identifier: MIT
// The filtered predicates: each polynomial is evaluated in double with a
// running error bound (filter_polynomials.hpp; filtered_arithmetic.hpp and
// error_bounds.hpp hold the proof); when the bound proves the sign we answer,
// otherwise we evaluate exactly (predicates_exact.cpp). Every call counts one
// filter success or one fallback in this thread's predicate_counters().
//
// Each predicate has one body, the overload on cached approximations
// (Vec2Ref, Vec3Ref; the hot one); the overload on plain vectors makes the
// approximations on the fly and calls it.
#include "filtered_predicates.hpp"

#include <optional>
#include <utility>

#include "filter_polynomials.hpp"
#include "predicates_exact.hpp"

namespace cvms {

PredicateCounters& predicate_counters() noexcept {
  thread_local PredicateCounters counters;
  return counters;
}

namespace {

using filtered::Approx3;

// The filter's answer, counted, when it proves the sign.
std::optional<Sign> sign_if_certain(Approx r) noexcept {
  if (!filtered::certain(r)) return std::nullopt;
  ++predicate_counters().filtered;
  return filtered::sign(r);
}

// Answers from the filter when it proves the sign, else from `exact_sign`.
template <class ExactSign>
Sign decide(Approx r, ExactSign&& exact_sign) {
  if (const std::optional<Sign> s = sign_if_certain(r)) return *s;
  ++predicate_counters().exact;
  return std::forward<ExactSign>(exact_sign)();
}

// The filter's value of poly (filter_polynomials.hpp) on the arguments'
// cached approximations.
template <class Poly, class... Refs>
auto filter(Poly poly, const Refs&... r) noexcept {
  return filtered::filtered_value(poly, r.approx...);
}

// Primitive normals (the facets' planes) are integer vectors: their exact
// side_of_plane needs no rational arithmetic.
bool has_integer_coordinates(const Vec3& v) noexcept {
  return mpz_cmp_ui(v.x.get_den_mpz_t(), 1) == 0 && mpz_cmp_ui(v.y.get_den_mpz_t(), 1) == 0 &&
         mpz_cmp_ui(v.z.get_den_mpz_t(), 1) == 0;
}

Vec2Ref ref(const Vec2& v, const ApproxVec2& a) noexcept { return {v, a}; }
Vec3Ref ref(const Vec3& v, const ApproxVec3& a) noexcept { return {v, a}; }
ApproxVec2 approximate(const Vec2& v) noexcept { return ApproxVec2::of(v); }
ApproxVec3 approximate(const Vec3& v) noexcept { return ApproxVec3::of(v); }

// The plain overloads: predicate(ref(v, approximation of v)...). The
// approximations are temporaries of this full expression, so they outlive
// the call.
template <class Predicate, class... Vecs>
auto on_the_fly(Predicate predicate, const Vecs&... v) {
  return predicate(ref(v, approximate(v))...);
}

}  // namespace

Sign orient2d(Vec2Ref a, Vec2Ref b, Vec2Ref c) {
  return decide(filter(filtered::orient2d_approx, a, b, c),
                [&] { return exact::orient2d(a.exact, b.exact, c.exact); });
}
Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  return on_the_fly([](auto... r) { return orient2d(r...); }, a, b, c);
}

Sign sign_cross2(Vec2Ref u, Vec2Ref v) {
  return decide(filter(filtered::cross2_approx, u, v), [&] { return exact::sign_cross2(u.exact, v.exact); });
}
Sign sign_cross2(const Vec2& u, const Vec2& v) {
  return on_the_fly([](auto... r) { return sign_cross2(r...); }, u, v);
}

Sign sign_dot(Vec2Ref u, Vec2Ref v) {
  return decide(filter(filtered::dot2_approx, u, v), [&] { return exact::sign_dot(u.exact, v.exact); });
}
Sign sign_dot(const Vec2& u, const Vec2& v) {
  return on_the_fly([](auto... r) { return sign_dot(r...); }, u, v);
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
  return on_the_fly([](auto... r) { return ccw_in_between(r...); }, d, d1, d2);
}

Sign orient3d(Vec3Ref a, Vec3Ref b, Vec3Ref c, Vec3Ref d) {
  return decide(filter(filtered::orient3d_approx, a, b, c, d),
                [&] { return exact::orient3d(a.exact, b.exact, c.exact, d.exact); });
}
std::optional<Sign> orient3d_if_certain(Vec3Ref a, Vec3Ref b, Vec3Ref c, Vec3Ref d) noexcept {
  return sign_if_certain(filter(filtered::orient3d_approx, a, b, c, d));
}
Sign orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return on_the_fly([](auto... r) { return orient3d(r...); }, a, b, c, d);
}

Sign sign_dot(Vec3Ref u, Vec3Ref v) {
  return decide(filter(filtered::dot3_approx, u, v), [&] { return exact::sign_dot(u.exact, v.exact); });
}
Sign sign_dot(const Vec3& u, const Vec3& v) {
  return on_the_fly([](auto... r) { return sign_dot(r...); }, u, v);
}

Sign compare_dot(Vec3Ref v, Vec3Ref w, Vec3Ref n) {
  return decide(filter(filtered::compare_dot_approx, v, w, n),
                [&] { return exact::compare_dot(v.exact, w.exact, n.exact); });
}
std::optional<Sign> compare_dot_if_certain(Vec3Ref v, Vec3Ref w, Vec3Ref n) noexcept {
  return sign_if_certain(filter(filtered::compare_dot_approx, v, w, n));
}
Sign compare_dot(const Vec3& v, const Vec3& w, const Vec3& n) {
  return on_the_fly([](auto... r) { return compare_dot(r...); }, v, w, n);
}

Sign side_of_plane(Vec3Ref p, Vec3Ref n, const Rational& offset, Approx offset_approx) {
  return decide(filtered::sub(filter(filtered::dot3_approx, p, n), offset_approx), [&] {
    return has_integer_coordinates(n.exact) ? exact::side_of_integer_plane(p.exact, n.exact, offset)
                                            : exact::side_of_plane(p.exact, n.exact, offset);
  });
}
std::optional<Sign> side_of_plane_if_certain(const ApproxVec3& p, const ApproxVec3& n, Approx offset) noexcept {
  return sign_if_certain(filtered::sub(filtered::filtered_value(filtered::dot3_approx, p, n), offset));
}
Sign side_of_plane(const Vec3& p, const Vec3& n, const Rational& offset) {
  return on_the_fly([&](Vec3Ref rp, Vec3Ref rn) { return side_of_plane(rp, rn, offset, Approx::of(offset)); },
                    p, n);
}

Sign sign_triple(Vec3Ref u, Vec3Ref v, Vec3Ref w) {
  return decide(filter(filtered::triple_approx, u, v, w),
                [&] { return exact::sign_triple(u.exact, v.exact, w.exact); });
}
Sign sign_triple(const Vec3& u, const Vec3& v, const Vec3& w) {
  return on_the_fly([](auto... r) { return sign_triple(r...); }, u, v, w);
}

bool is_parallel(Vec3Ref u, Vec3Ref v) {
  // The filter can prove a component of cross(u, v) nonzero, never zero: if
  // any component is provably nonzero the vectors are not parallel. (The
  // selection of filtered_value, written out: through it GCC 12 spends 9
  // more instructions a call on inexact inputs.)
  const ApproxVec3 &pu = u.approx, &pv = v.approx;
  const Approx3 c = filtered::all_exact(pu, pv)
                        ? filtered::cross3_approx(filtered::values(pu), filtered::values(pv))
                        : filtered::cross3_approx(pu, pv);
  PredicateCounters& counters = predicate_counters();
  if (filtered::certain(c.x) || filtered::certain(c.y) || filtered::certain(c.z)) {
    ++counters.filtered;
    return false;
  }
  ++counters.exact;
  return exact::is_parallel(u.exact, v.exact);
}
bool is_parallel(const Vec3& u, const Vec3& v) {
  return on_the_fly([](auto... r) { return is_parallel(r...); }, u, v);
}

Sign sign_triple_of_differences(Vec3Ref n, Vec3Ref a0, Vec3Ref a1, Vec3Ref b0, Vec3Ref b1) {
  return decide(filter(filtered::triple_of_differences_approx, n, a0, a1, b0, b1), [&] {
    return exact::sign_triple_of_differences(n.exact, a0.exact, a1.exact, b0.exact, b1.exact);
  });
}

Sign sign_triple_in_plane(Vec3Ref n, Vec3Ref a0, Vec3Ref a1, Vec3Ref b0, Vec3Ref b1) {
  return decide(filter(filtered::triple_of_differences_approx, n, a0, a1, b0, b1), [&] {
    return exact::sign_triple_in_plane(n.exact, a0.exact, a1.exact, b0.exact, b1.exact);
  });
}

Sign sign_dot_of_differences(Vec3Ref a0, Vec3Ref a1, Vec3Ref b0, Vec3Ref b1) {
  return decide(filter(filtered::dot_of_differences_approx, a0, a1, b0, b1),
                [&] { return exact::sign_dot_of_differences(a0.exact, a1.exact, b0.exact, b1.exact); });
}

Sign sign_triple_with_difference(Vec3Ref u, Vec3Ref v, Vec3Ref w0, Vec3Ref w1) {
  return decide(filter(filtered::triple_with_difference_approx, u, v, w0, w1),
                [&] { return exact::sign_triple_with_difference(u.exact, v.exact, w0.exact, w1.exact); });
}

bool collinear(Vec3Ref a, Vec3Ref b, Vec3Ref c) {
  // As is_parallel: the filter can only prove a component nonzero.
  const Approx3 n = filter(filtered::cross_of_differences_approx, a, b, c);
  PredicateCounters& counters = predicate_counters();
  if (filtered::certain(n.x) || filtered::certain(n.y) || filtered::certain(n.z)) {
    ++counters.filtered;
    return false;
  }
  ++counters.exact;
  return exact::collinear(a.exact, b.exact, c.exact);
}

}  // namespace cvms
