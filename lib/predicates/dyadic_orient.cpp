// SPDX-License-Identifier: MIT
// With every coordinate x = n / 2^k (n, k from the reduced rational) and E
// the largest k, the integers X = n 2^(E - k) are the coordinates scaled by
// 2^E > 0, which scales the determinant by 2^(3E) and keeps its sign.
#include "dyadic_orient.hpp"

#include <gmp.h>

#include "power_of_two.hpp"

namespace cvms {
namespace {

// Per-thread integer scratch: mpz_t keeps its limbs between calls.
struct Scratch {
  mpz_t v[12];  // the scaled coordinates, then the differences
  mpz_t t, det;
  Scratch() {
    for (mpz_t& x : v) mpz_init(x);
    mpz_init(t);
    mpz_init(det);
  }
  ~Scratch() {
    for (mpz_t& x : v) mpz_clear(x);
    mpz_clear(t);
    mpz_clear(det);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
};

}  // namespace

std::optional<Sign> dyadic_orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Rational* q[12] = {&a.x, &a.y, &a.z, &b.x, &b.y, &b.z, &c.x, &c.y, &c.z, &d.x, &d.y, &d.z};
  mp_bitcnt_t shift[12];
  mp_bitcnt_t top = 0;
  for (int i = 0; i < 12; ++i) {
    mpz_srcptr den = q[i]->get_den_mpz_t();
    if (!detail::is_power_of_two(den)) return std::nullopt;
    shift[i] = detail::log2_of_power_of_two(den);
    if (shift[i] > top) top = shift[i];
  }
  thread_local Scratch s;
  for (int i = 0; i < 12; ++i) mpz_mul_2exp(s.v[i], q[i]->get_num_mpz_t(), top - shift[i]);
  // b - a, c - a, d - a in v[3..11].
  for (int i = 3; i < 12; ++i) mpz_sub(s.v[i], s.v[i], s.v[i % 3]);
  mpz_t* u = s.v + 3;  // b - a
  mpz_t* v = s.v + 6;  // c - a
  mpz_t* w = s.v + 9;  // d - a
  // det = w . (u x v)
  mpz_set_ui(s.det, 0);
  for (int k = 0; k < 3; ++k) {
    const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    mpz_mul(s.t, u[k1], v[k2]);
    mpz_submul(s.t, u[k2], v[k1]);
    mpz_addmul(s.det, w[k], s.t);
  }
  return sign_of(mpz_sgn(s.det));
}

}  // namespace cvms
