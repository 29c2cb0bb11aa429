// SPDX-License-Identifier: MIT
// short_interior_point (short_interior_point.hpp). Rounding moves x0 by at
// most 2^-(k+1) per coordinate, so once 2^-(k+1) |a|_1 is below the LP's
// slack for every row the rounded point is inside; the exact check below
// decides, whatever k, so no bound is needed for correctness: a candidate
// that fails is skipped.
#include "short_interior_point.hpp"

#include <array>

namespace cvms::detail {
namespace {

// x rounded to the nearest multiple of 2^-bits (ties upwards).
Rational rounded(const Rational& x, unsigned bits) {
  mpz_class scaled = x.get_num();
  mpz_mul_2exp(scaled.get_mpz_t(), scaled.get_mpz_t(), bits + 1);
  scaled += x.get_den();
  mpz_class twice_den = x.get_den();
  mpz_mul_2exp(twice_den.get_mpz_t(), twice_den.get_mpz_t(), 1);
  mpz_fdiv_q(scaled.get_mpz_t(), scaled.get_mpz_t(), twice_den.get_mpz_t());
  Rational r(scaled);
  mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), bits);
  return r;
}

bool strictly_inside(const std::vector<LpRow>& rows, const std::vector<Rational>& x) {
  Rational value;
  for (const LpRow& row : rows) {
    value = 0;
    for (std::size_t k = 0; k < x.size(); ++k) value += row.a[k] * x[k];
    if (value >= row.b) return false;
  }
  return true;
}

}  // namespace

std::vector<Rational> short_interior_point(const std::vector<LpRow>& rows, const std::vector<Rational>& x0) {
  for (const unsigned bits : std::array<unsigned, 4>{0, 4, 16, 64}) {
    std::vector<Rational> x;
    x.reserve(x0.size());
    bool changed = false;
    for (const Rational& c : x0) {
      x.push_back(rounded(c, bits));
      changed = changed || x.back() != c;
    }
    if (!changed) return x0;
    if (strictly_inside(rows, x)) return x;
  }
  return x0;
}

}  // namespace cvms::detail
