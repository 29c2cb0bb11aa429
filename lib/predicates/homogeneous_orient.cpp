// SPDX-License-Identifier: MIT
// Let M be the 4×4 integer matrix with rows (X_i, Y_i, Z_i, w_i) for the
// points p_i = (X_i, Y_i, Z_i)/w_i, i = a, b, c, d. Dividing row i by w_i
// gives rows (p_i, 1), so det M = w_a w_b w_c w_d det[(p_i, 1)]. Subtracting
// the row of a from the others and expanding along the last column,
// det[(p_i, 1)] = −det[b − a; c − a; d − a] = −orient3d(a, b, c, d). The
// weights are positive, hence sign orient3d = −sign det M.
//
// det M by Laplace expansion along the first two rows: with the 2×2 minors
// s_jk of rows a, b and c_jk of rows c, d (columns j < k),
// det M = s01 c23 − s02 c13 + s03 c12 + s12 c03 − s13 c02 + s23 c01:
// 30 integer products, no division. With entries of at most 255 bits it is
// evaluated in fixed-width integers on the stack (fixed_det4.hpp, with the
// overflow proof); longer entries take GMP's mpz below.
#include "homogeneous_orient.hpp"

#include <gmp.h>

#include "filtered_predicates.hpp"
#include "fixed_det4.hpp"

namespace cvms {
namespace {

// Per-thread integer scratch: mpz_t keeps its limbs between calls.
struct Scratch {
  mpz_t top[6], bottom[6];  // the minors of rows (a, b) and (c, d)
  mpz_t det;
  Scratch() {
    for (int i = 0; i < 6; ++i) {
      mpz_init(top[i]);
      mpz_init(bottom[i]);
    }
    mpz_init(det);
  }
  ~Scratch() {
    for (int i = 0; i < 6; ++i) {
      mpz_clear(top[i]);
      mpz_clear(bottom[i]);
    }
    mpz_clear(det);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
};

// The columns, in the order (j, k) = 01, 02, 03, 12, 13, 23.
constexpr int first_column[6] = {0, 0, 0, 1, 1, 2};
constexpr int second_column[6] = {1, 2, 3, 2, 3, 3};

void minors(const HomogeneousPoint& p, const HomogeneousPoint& q, mpz_t out[6]) {
  mpz_srcptr u[4] = {p.x.get_mpz_t(), p.y.get_mpz_t(), p.z.get_mpz_t(), p.w.get_mpz_t()};
  mpz_srcptr v[4] = {q.x.get_mpz_t(), q.y.get_mpz_t(), q.z.get_mpz_t(), q.w.get_mpz_t()};
  for (int m = 0; m < 6; ++m) {
    const int j = first_column[m], k = second_column[m];
    mpz_mul(out[m], u[j], v[k]);
    mpz_submul(out[m], u[k], v[j]);
  }
}

}  // namespace

Sign homogeneous_orient3d(const HomogeneousPoint& a, const HomogeneousPoint& b, const HomogeneousPoint& c,
                          const HomogeneousPoint& d) {
  ++predicate_counters().exact;
  const std::array<std::array<mpz_srcptr, 4>, 4> rows = {
      {{a.x.get_mpz_t(), a.y.get_mpz_t(), a.z.get_mpz_t(), a.w.get_mpz_t()},
       {b.x.get_mpz_t(), b.y.get_mpz_t(), b.z.get_mpz_t(), b.w.get_mpz_t()},
       {c.x.get_mpz_t(), c.y.get_mpz_t(), c.z.get_mpz_t(), c.w.get_mpz_t()},
       {d.x.get_mpz_t(), d.y.get_mpz_t(), d.z.get_mpz_t(), d.w.get_mpz_t()}}};
  if (const std::optional<int> s = detail::fixed_det4_sign(rows)) return sign_of(-*s);
  thread_local Scratch s;
  minors(a, b, s.top);
  minors(c, d, s.bottom);
  // s_jk pairs with the complementary minor c_(5 − m); the signs alternate
  // as + − + + − +.
  mpz_set_ui(s.det, 0);
  for (int m = 0; m < 6; ++m) {
    if (m == 1 || m == 4)
      mpz_submul(s.det, s.top[m], s.bottom[5 - m]);
    else
      mpz_addmul(s.det, s.top[m], s.bottom[5 - m]);
  }
  return sign_of(-mpz_sgn(s.det));
}

namespace {

// det of the rows with minors `top` of (a, b), and c, x: the 2×2 minors of
// (c, x) taken on the fly.
void det_with(const mpz_t top[6], const HomogeneousPoint& c, const HomogeneousPoint& x, mpz_t bottom[6], mpz_t det) {
  minors(c, x, bottom);
  mpz_set_ui(det, 0);
  for (int m = 0; m < 6; ++m) {
    if (m == 1 || m == 4)
      mpz_submul(det, top[m], bottom[5 - m]);
    else
      mpz_addmul(det, top[m], bottom[5 - m]);
  }
}

}  // namespace

Sign homogeneous_compare_orient3d(const HomogeneousPoint& a, const HomogeneousPoint& b, const HomogeneousPoint& c,
                                  const HomogeneousPoint& p, const HomogeneousPoint& q) {
  ++predicate_counters().exact;
  thread_local Scratch s;
  thread_local mpz_class det_p, det_q;
  minors(a, b, s.top);
  det_with(s.top, c, p, s.bottom, det_p.get_mpz_t());
  det_with(s.top, c, q, s.bottom, det_q.get_mpz_t());
  // Δ_p q.w − Δ_q p.w, its sign negated (homogeneous_orient.hpp).
  mpz_mul(s.det, det_p.get_mpz_t(), q.w.get_mpz_t());
  mpz_submul(s.det, det_q.get_mpz_t(), p.w.get_mpz_t());
  return sign_of(-mpz_sgn(s.det));
}

}  // namespace cvms
