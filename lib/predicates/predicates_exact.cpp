// SPDX-License-Identifier: MIT
// Exact rational evaluation of every predicate (the filter's fallback).
#include "predicates_exact.hpp"

#include <initializer_list>

#include "common_denominator.hpp"
#include "dyadic.hpp"

namespace cvms::exact {

Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c) { return exact::sign_cross2(b - a, c - a); }

// cmp(u.x v.y, u.y v.x) with both sides over the positive denominator
// den(u.x) den(u.y) den(v.x) den(v.y): four integer products a side and no
// canonical rational (the ties of parallel facets' planar sums).
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
  mpz_class n_scaled[3];  // n as an integer vector when it is not one

  // l = the lcm of the coordinates' denominators of every point. A
  // denominator that l is a multiple of (an equal one, as for the three
  // coordinates of most sums of points, or a power of two below l) needs
  // no gcd; one that is a multiple of l replaces it.
  void common_denominator(std::initializer_list<const Vec3*> points) {
    l = (*points.begin())->x.get_den();
    for (const Vec3* p : points) {
      for (int i = 0; i < 3; ++i) {
        const mpz_srcptr d = (*p)[i].get_den_mpz_t();
        if (mpz_cmp(d, l.get_mpz_t()) == 0 || mpz_divisible_p(l.get_mpz_t(), d) != 0) continue;
        if (mpz_divisible_p(d, l.get_mpz_t()) != 0)
          mpz_set(l.get_mpz_t(), d);
        else
          mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), d);
      }
    }
  }
  // sum += L dot(p, n), or -= when subtract, for an integer vector n. A
  // coordinate over the denominator L itself is its numerator: no quotient.
  void add_scaled_dot(const Vec3& p, const mpz_class* const n[3], bool subtract) {
    for (int i = 0; i < 3; ++i) {
      if (mpz_sgn(n[i]->get_mpz_t()) == 0 || mpz_sgn(p[i].get_num_mpz_t()) == 0) continue;
      mpz_srcptr scaled = p[i].get_num_mpz_t();
      if (mpz_cmp(p[i].get_den_mpz_t(), l.get_mpz_t()) != 0) {
        mpz_divexact(term.get_mpz_t(), l.get_mpz_t(), p[i].get_den_mpz_t());
        mpz_mul(term.get_mpz_t(), term.get_mpz_t(), p[i].get_num_mpz_t());
        scaled = term.get_mpz_t();
      }
      if (subtract)
        mpz_submul(sum.get_mpz_t(), scaled, n[i]->get_mpz_t());
      else
        mpz_addmul(sum.get_mpz_t(), scaled, n[i]->get_mpz_t());
    }
  }
};

// An integer vector K n for some K > 0, which has the sign of every dot
// product with n: n's numerators when n is an integer vector, else n scaled
// to the lcm of its denominators (into `scratch`).
void positive_integer_multiple(const Vec3& n, mpz_class scratch[3], const mpz_class* out[3]) {
  if (has_integer_coordinates(n)) {
    for (int i = 0; i < 3; ++i) out[i] = &n[i].get_num();
    return;
  }
  const Rational* const values[3] = {&n.x, &n.y, &n.z};
  detail::scale_to_common_denominator(values, 3, scratch);
  for (int i = 0; i < 3; ++i) out[i] = &scratch[i];
}

}  // namespace

// With L the lcm of the six denominators of v and w, L (v - w) is an integer
// vector and L > 0; with K n an integer vector, K > 0 (n itself for a facet
// normal), the sign is that of sum_i K n_i (num(v_i) L / den(v_i) - num(w_i)
// L / den(w_i)), one integer sum. The rational form canonicalises nine
// intermediates, and their gcds were most of the exact cost: when the
// coordinates are not dyadic (decimal input, where A + A makes every
// contributing-vertex choice an exact tie), and in the exact GJK,
// whose optimality test <w, v> >= <v, v> is an exact tie whenever the double
// GJK's guess is right (v there is a rational point, not a normal).
Sign compare_dot(const Vec3& v, const Vec3& w, const Vec3& n) {
  thread_local ScaledDots s;
  const mpz_class* n_int[3];
  positive_integer_multiple(n, s.n_scaled, n_int);
  s.common_denominator({&v, &w});
  s.sum = 0;
  s.add_scaled_dot(v, n_int, false);
  s.add_scaled_dot(w, n_int, true);
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
  const mpz_class* const n_int[3] = {&n.x.get_num(), &n.y.get_num(), &n.z.get_num()};
  s.common_denominator({&p});
  s.sum = 0;
  s.add_scaled_dot(p, n_int, false);
  mpz_mul(s.sum.get_mpz_t(), s.sum.get_mpz_t(), offset.get_den_mpz_t());
  mpz_mul(s.term.get_mpz_t(), s.l.get_mpz_t(), offset.get_num_mpz_t());
  return sign_of(mpz_cmp(s.sum.get_mpz_t(), s.term.get_mpz_t()));
}

}  // namespace cvms::exact
