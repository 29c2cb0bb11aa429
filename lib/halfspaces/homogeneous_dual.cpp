// SPDX-License-Identifier: MIT
// Building the homogeneous dual points of homogeneous_dual.hpp: each row is
// multiplied by the lcm of its denominators and divided by the gcd of its
// numerators (a positive factor either way), and x0 is written over the lcm
// D of its denominators, so s_i = b_i D − a_i·X = D (b_i − a_i·x0) > 0
// exactly when x0 is strictly inside.
#include "homogeneous_dual.hpp"

#include <array>

#include "common_denominator.hpp"

namespace cvms::detail {
namespace {

// content = gcd of the normal n_0, n_1, n_2 (the first pair often decides:
// a gcd of 1 ends it).
void normal_content(const std::array<mpz_class, 4>& n, mpz_class& content) {
  mpz_gcd(content.get_mpz_t(), n[0].get_mpz_t(), n[1].get_mpz_t());
  if (content != 1) mpz_gcd(content.get_mpz_t(), content.get_mpz_t(), n[2].get_mpz_t());
}

// The dual of rows whose entries row(i) gives as (a_x, a_y, a_z, b). Each
// row is worked out in the same few integers, whose limbs are reused from
// row to row, and stored in the dual's arena: no heap block per row (on
// Sphere5's 5,120 rows the integers of their own were about 40 % of the
// intersection's heap blocks, and the allocator's time grows with them).
template <class Entries>
HomogeneousDual dual_of(std::size_t count, const Entries& row, const std::vector<Rational>& x0) {
  mpz_class d;
  const Rational zero;
  std::array<mpz_class, 4> xd;
  const std::array<const Rational*, 4> origin{&x0[0], &x0[1], &x0[2], &zero};
  scale_to_common_denominator(origin.data(), origin.size(), xd.data(), d);
  HomogeneousDual dual;
  dual.points.reserve(count);
  dual.offsets.reserve(count);
  dual.normal_contents.reserve(count);
  std::array<mpz_class, 4> n;  // n_k = L q_k, L the lcm of the row's denominators
  mpz_class scale, content, g, w;
  for (std::size_t i = 0; i < count; ++i) {
    const std::array<const Rational*, 4> q = row(i);
    scale_to_common_denominator(q.data(), q.size(), n.data(), scale);
    normal_content(n, content);
    // The row's gcd divides its normal's: with a primitive normal (the
    // usual case) the row is primitive and nothing is divided.
    if (content != 1) {
      mpz_gcd(g.get_mpz_t(), content.get_mpz_t(), n[3].get_mpz_t());
      if (g != 1) {
        for (mpz_class& v : n) mpz_divexact(v.get_mpz_t(), v.get_mpz_t(), g.get_mpz_t());
        mpz_divexact(content.get_mpz_t(), content.get_mpz_t(), g.get_mpz_t());
      }
    }
    mpz_mul(w.get_mpz_t(), n[3].get_mpz_t(), d.get_mpz_t());
    mpz_submul(w.get_mpz_t(), n[0].get_mpz_t(), xd[0].get_mpz_t());
    mpz_submul(w.get_mpz_t(), n[1].get_mpz_t(), xd[1].get_mpz_t());
    mpz_submul(w.get_mpz_t(), n[2].get_mpz_t(), xd[2].get_mpz_t());
    HomogeneousPoint& p = dual.points.emplace_back();
    dual.limbs.store(p.x, n[0].get_mpz_t());
    dual.limbs.store(p.y, n[1].get_mpz_t());
    dual.limbs.store(p.z, n[2].get_mpz_t());
    dual.limbs.store(p.w, w.get_mpz_t());
    dual.limbs.store(dual.offsets.emplace_back(), n[3].get_mpz_t());
    dual.limbs.store(dual.normal_contents.emplace_back(), content.get_mpz_t());
  }
  dual.origin = {xd[0], xd[1], xd[2], d};
  return dual;
}

}  // namespace

HomogeneousDual homogeneous_dual(const std::vector<LpRow>& rows, const std::vector<Rational>& x0) {
  return dual_of(
      rows.size(),
      [&](std::size_t i) -> std::array<const Rational*, 4> {
        const LpRow& r = rows[i];
        return {&r.a[0], &r.a[1], &r.a[2], &r.b};
      },
      x0);
}

HomogeneousDual homogeneous_dual(std::span<const HalfspaceRow> rows, const std::vector<Rational>& x0) {
  return dual_of(
      rows.size(),
      [&](std::size_t i) -> std::array<const Rational*, 4> {
        const HalfspaceRow& r = rows[i];
        return {&r.normal.x, &r.normal.y, &r.normal.z, &r.offset};
      },
      x0);
}

}  // namespace cvms::detail
