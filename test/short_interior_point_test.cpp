// SPDX-License-Identifier: MIT
// Tests of short_interior_point (lib/halfspaces/short_interior_point.hpp):
// the point it picks is strictly inside every row (checked here by
// substitution), has a power-of-two denominator of at most 2^64 or is the
// given point, and comes back unchanged when no rounding is inside (a thin
// slab the rounding steps over).
#include "short_interior_point.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace cvms {
namespace {

using Rng = std::mt19937_64;

Rational fraction(long n, long d) {
  Rational q(n, d);
  q.canonicalize();
  return q;
}

bool power_of_two(const mpz_class& d) { return mpz_popcount(d.get_mpz_t()) == 1; }

bool strictly_inside(const std::vector<detail::LpRow>& rows, const std::vector<Rational>& x) {
  for (const detail::LpRow& r : rows)
    if (!(r.a[0] * x[0] + r.a[1] * x[1] + r.a[2] * x[2] < r.b)) return false;
  return true;
}

TEST(ShortInteriorPoint, RandomSystemsGiveAShortStrictInteriorPoint) {
  Rng rng(1616);
  int shortened = 0;
  for (int round = 0; round < 300; ++round) {
    SCOPED_TRACE("seed 1616 round " + std::to_string(round));
    // x0 with long odd denominators, rows around it with slack from 1/10^6 to 20.
    const std::vector<Rational> x0 = {fraction(static_cast<long>(rng() % 2000001) - 1000000, 999983),
                                      fraction(static_cast<long>(rng() % 2001) - 1000, 7919),
                                      fraction(static_cast<long>(rng() % 201) - 100, 104729)};
    std::vector<detail::LpRow> rows;
    for (int i = 0; i < 20; ++i) {
      std::vector<Rational> a = {Rational(static_cast<long>(rng() % 41) - 20), Rational(static_cast<long>(rng() % 41) - 20),
                                 Rational(static_cast<long>(rng() % 41) - 20)};
      const Rational slack = round % 3 == 0 ? fraction(1, 1000000) : fraction(1 + static_cast<long>(rng() % 20), 1);
      const Rational b = a[0] * x0[0] + a[1] * x0[1] + a[2] * x0[2] + slack;
      rows.push_back({std::move(a), b});
    }
    const std::vector<Rational> x = detail::short_interior_point(rows, x0);
    ASSERT_EQ(x.size(), 3u);
    EXPECT_TRUE(strictly_inside(rows, x));
    if (x == x0) continue;
    ++shortened;
    for (const Rational& c : x) {
      EXPECT_TRUE(power_of_two(c.get_den()));
      EXPECT_LE(mpz_sizeinbase(c.get_den().get_mpz_t(), 2), 65u);
    }
  }
  EXPECT_GE(shortened, 250);
}

TEST(ShortInteriorPoint, NoRoundingInsideKeepsThePoint) {
  // The slab 1/3 − 2^-70 < x < 1/3 + 2^-70 holds no multiple of 2^-64.
  Rational eps(1);
  mpq_div_2exp(eps.get_mpq_t(), eps.get_mpq_t(), 70);
  const Rational third = fraction(1, 3);
  const std::vector<detail::LpRow> rows = {{{Rational(1), Rational(0), Rational(0)}, third + eps},
                                           {{Rational(-1), Rational(0), Rational(0)}, -(third - eps)},
                                           {{Rational(0), Rational(1), Rational(0)}, Rational(1)}};
  const std::vector<Rational> x0 = {third, Rational(0), Rational(0)};
  EXPECT_EQ(detail::short_interior_point(rows, x0), x0);
}

TEST(ShortInteriorPoint, AnIntegerPointStaysAsItIs) {
  const std::vector<detail::LpRow> rows = {{{Rational(1), Rational(0), Rational(0)}, Rational(5)}};
  const std::vector<Rational> x0 = {Rational(2), Rational(-3), Rational(0)};
  EXPECT_EQ(detail::short_interior_point(rows, x0), x0);
}

}  // namespace
}  // namespace cvms
