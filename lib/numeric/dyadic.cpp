// SPDX-License-Identifier: MIT
// Gcd-free exact arithmetic for dyadic rationals (see the header).
#include "dyadic.hpp"

#include <algorithm>

namespace cvms::detail {
namespace {

// Stores num / 2^k into out, reducing by the common power of two first.
void set_reduced_dyadic(mpq_ptr out, mpz_ptr num, mp_bitcnt_t k) {
  if (mpz_sgn(num) == 0) {
    mpz_set_ui(mpq_denref(out), 1);
    mpz_set_ui(mpq_numref(out), 0);
    return;
  }
  const mp_bitcnt_t common = std::min(mpz_scan1(num, 0), k);  // the lowest set bit is the same for -num
  if (common > 0) mpz_tdiv_q_2exp(num, num, common);          // exact: 2^common divides num
  if (num != mpq_numref(out)) mpz_set(mpq_numref(out), num);
  mpz_set_ui(mpq_denref(out), 0);
  mpz_setbit(mpq_denref(out), k - common);
}

}  // namespace

namespace {

// out = x + y or x - y (canonical): the operand with the smaller power-of-two
// denominator is brought to the larger one. With different denominators the
// finer numerator is odd and the other term even, so the result is already
// canonical and set_reduced_dyadic only writes the denominator.
void add_or_subtract(Rational& out, const Rational& x, const Rational& y, bool subtract) {
  if (!is_dyadic(x) || !is_dyadic(y)) {
    (subtract ? mpq_sub : mpq_add)(out.get_mpq_t(), x.get_mpq_t(), y.get_mpq_t());
    return;
  }
  const mp_bitcnt_t kx = log2_of_power_of_two(x.get_den_mpz_t());
  const mp_bitcnt_t ky = log2_of_power_of_two(y.get_den_mpz_t());
  const mp_bitcnt_t k = std::max(kx, ky);
  mpz_ptr num = mpq_numref(out.get_mpq_t());
  auto combine = subtract ? mpz_sub : mpz_add;
  if (kx >= ky) {
    mpz_mul_2exp(num, y.get_num_mpz_t(), k - ky);
    combine(num, x.get_num_mpz_t(), num);
  } else {
    mpz_mul_2exp(num, x.get_num_mpz_t(), k - kx);
    combine(num, num, y.get_num_mpz_t());
  }
  set_reduced_dyadic(out.get_mpq_t(), num, k);
}

}  // namespace

void add_into(Rational& out, const Rational& x, const Rational& y) { add_or_subtract(out, x, y, false); }

void subtract_into(Rational& out, const Rational& x, const Rational& y) { add_or_subtract(out, x, y, true); }

Vec3 add(const Vec3& x, const Vec3& y) {
  Vec3 sum;
  for (int i = 0; i < 3; ++i) add_into(sum[i], x[i], y[i]);
  return sum;
}

Vec3 subtract(const Vec3& x, const Vec3& y) {
  Vec3 difference;
  for (int i = 0; i < 3; ++i) subtract_into(difference[i], x[i], y[i]);
  return difference;
}

void integer_dot(const Vec3& n, const Vec3& p, DotScratch& scratch, Rational& out) {
  mpz_class& sum = scratch.sum;
  mpz_class& term = scratch.term;
  sum = 0;
  if (is_dyadic(p.x) && is_dyadic(p.y) && is_dyadic(p.z)) {
    mp_bitcnt_t k = 0;
    for (int i = 0; i < 3; ++i) k = std::max(k, log2_of_power_of_two(p[i].get_den_mpz_t()));
    for (int i = 0; i < 3; ++i) {
      if (mpz_sgn(n[i].get_num_mpz_t()) == 0 || mpz_sgn(p[i].get_num_mpz_t()) == 0) continue;
      mpz_mul_2exp(term.get_mpz_t(), p[i].get_num_mpz_t(), k - log2_of_power_of_two(p[i].get_den_mpz_t()));
      mpz_addmul(sum.get_mpz_t(), term.get_mpz_t(), n[i].get_num_mpz_t());
    }
    set_reduced_dyadic(out.get_mpq_t(), sum.get_mpz_t(), k);
    return;
  }
  mpz_class& l = scratch.denominator;
  l = p.x.get_den();
  for (int i = 1; i < 3; ++i)
    if (p[i].get_den() != l) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), p[i].get_den_mpz_t());
  for (int i = 0; i < 3; ++i) {
    if (mpz_sgn(n[i].get_num_mpz_t()) == 0 || mpz_sgn(p[i].get_num_mpz_t()) == 0) continue;
    mpz_divexact(term.get_mpz_t(), l.get_mpz_t(), p[i].get_den_mpz_t());
    term *= p[i].get_num();
    mpz_addmul(sum.get_mpz_t(), term.get_mpz_t(), n[i].get_num_mpz_t());
  }
  mpz_set(mpq_numref(out.get_mpq_t()), sum.get_mpz_t());
  mpz_set(mpq_denref(out.get_mpq_t()), l.get_mpz_t());
  out.canonicalize();
}

}  // namespace cvms::detail
