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

// The integers (n_k) and the positive factor L with n_k = L q_k, L the lcm
// of the denominators (scale_to_common_denominator: an entry whose
// denominator is L, every entry of an integer row, is its numerator).
std::array<mpz_class, 4> over_common_denominator(const std::array<const Rational*, 4>& q, mpz_class& lcm) {
  std::array<mpz_class, 4> n;
  lcm = scale_to_common_denominator(q.data(), q.size(), n.data());
  return n;
}

// content = gcd of the normal n_0, n_1, n_2 (the first pair often decides:
// a gcd of 1 ends it).
void normal_content(const std::array<mpz_class, 4>& n, mpz_class& content) {
  mpz_gcd(content.get_mpz_t(), n[0].get_mpz_t(), n[1].get_mpz_t());
  if (content != 1) mpz_gcd(content.get_mpz_t(), content.get_mpz_t(), n[2].get_mpz_t());
}

// The dual of rows whose entries row(i) gives as (a_x, a_y, a_z, b).
template <class Entries>
HomogeneousDual dual_of(std::size_t count, const Entries& row, const std::vector<Rational>& x0) {
  mpz_class d;
  const Rational zero;
  const std::array<mpz_class, 4> xd = over_common_denominator({&x0[0], &x0[1], &x0[2], &zero}, d);
  HomogeneousDual dual;
  dual.points.reserve(count);
  dual.offsets.reserve(count);
  dual.normal_contents.reserve(count);
  mpz_class scale, g;
  for (std::size_t i = 0; i < count; ++i) {
    std::array<mpz_class, 4> n = over_common_denominator(row(i), scale);
    mpz_class& content = dual.normal_contents.emplace_back();
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
    HomogeneousPoint& p = dual.points.emplace_back();
    p.w = n[3] * d;
    mpz_submul(p.w.get_mpz_t(), n[0].get_mpz_t(), xd[0].get_mpz_t());
    mpz_submul(p.w.get_mpz_t(), n[1].get_mpz_t(), xd[1].get_mpz_t());
    mpz_submul(p.w.get_mpz_t(), n[2].get_mpz_t(), xd[2].get_mpz_t());
    p.x = std::move(n[0]);
    p.y = std::move(n[1]);
    p.z = std::move(n[2]);
    dual.offsets.push_back(std::move(n[3]));
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
