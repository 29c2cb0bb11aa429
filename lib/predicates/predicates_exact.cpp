// SPDX-License-Identifier: MIT
// Exact rational evaluation of every predicate (the filter's fallback).
#include "predicates_exact.hpp"

#include <initializer_list>

#include "dyadic.hpp"

namespace cvms::exact {

Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c) { return exact::sign_cross2(b - a, c - a); }

// cmp(u.x v.y, u.y v.x) with both sides over the positive denominator
// den(u.x) den(u.y) den(v.x) den(v.y): four integer products a side and no
// canonical rational (the ties of parallel facets' planar sums, issue 14).
Sign sign_cross2(const Vec2& u, const Vec2& v) {
  struct Scratch {
    mpz_class left, right;
  };
  thread_local Scratch s;
  mpz_mul(s.left.get_mpz_t(), u.x.get_num_mpz_t(), v.y.get_num_mpz_t());
  mpz_mul(s.right.get_mpz_t(), u.y.get_num_mpz_t(), v.x.get_num_mpz_t());
  const int left_sign = mpz_sgn(s.left.get_mpz_t()), right_sign = mpz_sgn(s.right.get_mpz_t());
  if (left_sign != right_sign) return sign_of(left_sign - right_sign);  // also when one side is zero
  if (left_sign == 0) return Sign::zero;
  mpz_mul(s.left.get_mpz_t(), s.left.get_mpz_t(), u.y.get_den_mpz_t());
  mpz_mul(s.left.get_mpz_t(), s.left.get_mpz_t(), v.x.get_den_mpz_t());
  mpz_mul(s.right.get_mpz_t(), s.right.get_mpz_t(), u.x.get_den_mpz_t());
  mpz_mul(s.right.get_mpz_t(), s.right.get_mpz_t(), v.y.get_den_mpz_t());
  return sign_of(mpz_cmp(s.left.get_mpz_t(), s.right.get_mpz_t()));
}

Sign sign_dot(const Vec2& u, const Vec2& v) { return sign_of(sgn(dot(u, v))); }

Sign orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return sign_of(sgn(dot(cross(b - a, c - a), d - a)));
}

Sign sign_dot(const Vec3& u, const Vec3& v) { return sign_of(sgn(dot(u, v))); }

namespace {

bool has_integer_coordinates(const Vec3& v) {
  return v.x.get_den() == 1 && v.y.get_den() == 1 && v.z.get_den() == 1;
}

// Fraction-free dot products with an integer vector n: with L a common
// multiple of a point's denominators, L dot(p, n) = sum_i n_i num(p_i) L /
// den(p_i), an integer sum with no canonical rational (no gcd), scaled by L > 0.
struct ScaledDots {
  mpz_class l, sum, term;

  // l = the lcm of the coordinates' denominators of every point.
  void common_denominator(std::initializer_list<const Vec3*> points) {
    l = (*points.begin())->x.get_den();
    for (const Vec3* p : points)
      for (int i = 0; i < 3; ++i)
        if ((*p)[i].get_den() != l) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), (*p)[i].get_den_mpz_t());
  }
  // sum += L dot(p, n), or -= when subtract. \pre n is an integer vector.
  void add_scaled_dot(const Vec3& p, const Vec3& n, bool subtract) {
    for (int i = 0; i < 3; ++i) {
      if (mpz_sgn(n[i].get_num_mpz_t()) == 0 || mpz_sgn(p[i].get_num_mpz_t()) == 0) continue;
      mpz_divexact(term.get_mpz_t(), l.get_mpz_t(), p[i].get_den_mpz_t());
      mpz_mul(term.get_mpz_t(), term.get_mpz_t(), p[i].get_num_mpz_t());
      if (subtract)
        mpz_submul(sum.get_mpz_t(), term.get_mpz_t(), n[i].get_num_mpz_t());
      else
        mpz_addmul(sum.get_mpz_t(), term.get_mpz_t(), n[i].get_num_mpz_t());
    }
  }
};

}  // namespace

// For an integer n (every facet normal is one): with L the lcm of the six
// denominators of v and w, L (v - w) is an integer vector and L > 0, so the
// sign is that of sum_i n_i (num(v_i) L / den(v_i) - num(w_i) L / den(w_i)),
// one integer sum. The rational form canonicalises nine intermediates, and
// their gcds were most of the exact cost when the coordinates are not dyadic
// (decimal input, where A + A makes every contributing-vertex choice an exact
// tie: issue 14).
Sign compare_dot(const Vec3& v, const Vec3& w, const Vec3& n) {
  if (!has_integer_coordinates(n)) return sign_of(sgn(dot(v - w, n)));
  thread_local ScaledDots s;
  s.common_denominator({&v, &w});
  s.sum = 0;
  s.add_scaled_dot(v, n, false);
  s.add_scaled_dot(w, n, true);
  return sign_of(mpz_sgn(s.sum.get_mpz_t()));
}

Sign side_of_plane(const Vec3& p, const Vec3& n, const Rational& offset) {
  return sign_of(cmp(dot(p, n), offset));
}

Sign sign_triple(const Vec3& u, const Vec3& v, const Vec3& w) { return sign_of(sgn(dot(u, cross(v, w)))); }

bool is_parallel(const Vec3& u, const Vec3& v) {
  return u.y * v.z == u.z * v.y && u.z * v.x == u.x * v.z && u.x * v.y == u.y * v.x;
}


// The differences by detail::subtract: no gcd when the points are dyadic.
Sign sign_triple_of_differences(const Vec3& n, const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  return exact::sign_triple(n, detail::subtract(a1, a0), detail::subtract(b1, b0));
}

// a, b orthogonal to n != 0: cross(a, b) is a multiple of n, zero iff a and
// b are parallel, so det[n, a, b] = dot(n, cross(a, b)) is zero iff they are.
Sign sign_triple_in_plane(const Vec3& n, const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  const Vec3 a = detail::subtract(a1, a0), b = detail::subtract(b1, b0);
  if (exact::is_parallel(a, b)) return Sign::zero;
  return exact::sign_triple(n, a, b);
}

Sign sign_dot_of_differences(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  return exact::sign_dot(detail::subtract(a1, a0), detail::subtract(b1, b0));
}

Sign sign_triple_with_difference(const Vec3& u, const Vec3& v, const Vec3& w0, const Vec3& w1) {
  return exact::sign_triple(u, v, detail::subtract(w1, w0));
}

bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
  return exact::is_parallel(detail::subtract(b, a), detail::subtract(c, a));
}

Sign side_of_integer_plane(const Vec3& p, const Vec3& n, const Rational& offset) {
  // With L the lcm of p's denominators and offset = a / b (b > 0):
  // dot(p, n) - offset = (L dot(p, n) b - a L) / (L b).
  thread_local ScaledDots s;
  s.common_denominator({&p});
  s.sum = 0;
  s.add_scaled_dot(p, n, false);
  mpz_mul(s.sum.get_mpz_t(), s.sum.get_mpz_t(), offset.get_den_mpz_t());
  mpz_mul(s.term.get_mpz_t(), s.l.get_mpz_t(), offset.get_num_mpz_t());
  return sign_of(mpz_cmp(s.sum.get_mpz_t(), s.term.get_mpz_t()));
}

}  // namespace cvms::exact
