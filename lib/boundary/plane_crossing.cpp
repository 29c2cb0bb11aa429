// SPDX-License-Identifier: MIT
// See plane_crossing.hpp.
#include "plane_crossing.hpp"

namespace cvms::detail {
namespace {

// A point over the common denominator of its coordinates.
struct ScaledPoint {
  mpz_class numerators[3];
  mpz_class denominator;

  // p = numerators / denominator, denominator the lcm of p's denominators:
  // no gcd when one of them is a multiple of the others, as when they are
  // equal (most sums of points) or powers of two.
  void set(const Vec3& p) {
    mpz_ptr l = denominator.get_mpz_t();
    mpz_set(l, p.x.get_den_mpz_t());
    for (int k = 1; k < 3; ++k) {
      const mpz_srcptr d = p[k].get_den_mpz_t();
      if (mpz_cmp(d, l) == 0 || mpz_divisible_p(l, d) != 0) continue;
      if (mpz_divisible_p(d, l) != 0)
        mpz_set(l, d);
      else
        mpz_lcm(l, l, d);
    }
    for (int k = 0; k < 3; ++k) {
      if (mpz_cmp(p[k].get_den_mpz_t(), denominator.get_mpz_t()) == 0) {
        mpz_set(numerators[k].get_mpz_t(), p[k].get_num_mpz_t());
        continue;
      }
      mpz_divexact(numerators[k].get_mpz_t(), denominator.get_mpz_t(), p[k].get_den_mpz_t());
      mpz_mul(numerators[k].get_mpz_t(), numerators[k].get_mpz_t(), p[k].get_num_mpz_t());
    }
  }
};

// Integers reused on each thread, so that they keep their limbs from one
// call to the next instead of allocating.
struct CrossingScratch {
  ScaledPoint a, b;
  mpz_class sa, sb, term;
};

// s = o_d dot(n, P) - o_n d for the point P / d.
void scaled_plane_value(mpz_class& s, mpz_class& term, const ScaledPoint& p, const Vec3& n,
                        const Rational& offset) {
  mpz_mul(s.get_mpz_t(), n.x.get_num_mpz_t(), p.numerators[0].get_mpz_t());
  mpz_addmul(s.get_mpz_t(), n.y.get_num_mpz_t(), p.numerators[1].get_mpz_t());
  mpz_addmul(s.get_mpz_t(), n.z.get_num_mpz_t(), p.numerators[2].get_mpz_t());
  mpz_mul(s.get_mpz_t(), s.get_mpz_t(), offset.get_den_mpz_t());
  mpz_mul(term.get_mpz_t(), offset.get_num_mpz_t(), p.denominator.get_mpz_t());
  mpz_sub(s.get_mpz_t(), s.get_mpz_t(), term.get_mpz_t());
}

}  // namespace

void plane_crossing(const Vec3& a, const Vec3& b, const Vec3& n, const Rational& offset, Vec3& out) {
  thread_local CrossingScratch s;
  s.a.set(a);
  s.b.set(b);
  scaled_plane_value(s.sa, s.term, s.a, n, offset);
  scaled_plane_value(s.sb, s.term, s.b, n, offset);
  // The denominator S_A d_b - S_B d_a, nonzero as S_A and S_B have opposite
  // signs; mpq_canonicalize makes it positive.
  mpz_mul(s.term.get_mpz_t(), s.sa.get_mpz_t(), s.b.denominator.get_mpz_t());
  mpz_submul(s.term.get_mpz_t(), s.sb.get_mpz_t(), s.a.denominator.get_mpz_t());
  for (int k = 0; k < 3; ++k) {
    mpq_ptr x = out[k].get_mpq_t();
    mpz_mul(mpq_numref(x), s.sa.get_mpz_t(), s.b.numerators[k].get_mpz_t());
    mpz_submul(mpq_numref(x), s.sb.get_mpz_t(), s.a.numerators[k].get_mpz_t());
    mpz_set(mpq_denref(x), s.term.get_mpz_t());
    mpq_canonicalize(x);
  }
}

}  // namespace cvms::detail
