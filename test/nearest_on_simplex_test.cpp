// SPDX-License-Identifier: MIT
// GJK's exact sub-distance (lib/proximity/nearest_on_simplex.hpp) against a
// plain brute force: for every nonempty subset of the points, the projection
// of the origin onto its affine hull by solving the Gram system in rationals;
// the nearest one with positive weights is the answer. Includes point sets
// where the double-precision guess is likely wrong (huge coordinates with
// tiny differences, lattice ties broken by 1e-25), so that the exact
// fallback runs.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "nearest_on_simplex.hpp"
#include "support/linear_solve.hpp"

namespace cvms::detail {
namespace {

struct Projection {
  Vec3 point;
  Rational norm;
  std::uint32_t mask = 0;
};

// The nearest point of conv(points) to the origin, by brute force over subsets.
Projection brute_force(const std::vector<Vec3>& p) {
  std::optional<Projection> best;
  for (std::uint32_t mask = 1; mask < (1u << p.size()); ++mask) {
    std::vector<Vec3> s;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (mask & (1u << i)) s.push_back(p[i]);
    const std::size_t k = s.size() - 1;
    std::vector<std::vector<Rational>> g(k, std::vector<Rational>(k));
    std::vector<Rational> r(k);
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t j = 0; j < k; ++j) g[i][j] = dot(s[i + 1] - s[0], s[j + 1] - s[0]);
      r[i] = -dot(s[i + 1] - s[0], s[0]);
    }
    const auto mu = test::solve_linear(g, r);
    if (!mu) continue;
    Rational first = 1;
    Vec3 x = s[0];
    bool positive = true;
    for (std::size_t i = 0; i < k; ++i) {
      positive = positive && (*mu)[i] > 0;
      first -= (*mu)[i];
      x += (*mu)[i] * (s[i + 1] - s[0]);
    }
    if (!positive || first <= 0) continue;
    const Rational n = dot(x, x);
    if (!best || n < best->norm) best = Projection{x, n, mask};
  }
  return *best;
}

Rational fraction(long num, long den) {
  Rational q(num, den);
  q.canonicalize();  // gmpxx's two-argument constructor does not
  return q;
}

Rational random_coordinate(std::mt19937_64& rng, int kind) {
  const long v = static_cast<long>(rng() % 2001) - 1000;
  switch (kind) {
    case 0:
      return fraction(v, 7);
    case 1:  // huge with tiny differences: the doubles of the dot products collapse
      return Rational(mpz_class("100000000000000000000")) + fraction(v, 1000);
    case 2:
      return Rational(static_cast<double>(v) / 3.0);
    case 3:  // a small integer moved by about 1e-25: the exact ties of the lattice are broken below double precision
      return Rational(v % 3) + fraction(v, 7) * Rational(mpz_class(1), mpz_class("10000000000000000000000000000"));
    case 4:  // doubles of very different exponents: powers of two from 2^-1074 to 2^0 as denominators (the shift path)
      return Rational(std::ldexp(static_cast<double>(v) / 3.0, -static_cast<int>(rng() % 1070)));
    default:  // dyadic and non-dyadic coordinates mixed in one simplex (the lcm path)
      return rng() % 4 == 0 ? fraction(v, 5) : Rational(static_cast<double>(v) / 64.0);
  }
}

TEST(ProximityNearestOnSimplex, AgreesWithBruteForce) {
  std::mt19937_64 rng(2026);
  int checked = 0;
  for (int trial = 0; trial < 4500; ++trial) {
    const int count = 1 + static_cast<int>(rng() % 4);
    const int kind = static_cast<int>(rng() % 6);
    std::vector<Vec3> pts;
    for (int i = 0; i < count; ++i)
      pts.push_back({random_coordinate(rng, kind), random_coordinate(rng, kind), random_coordinate(rng, kind)});
    if (kind == 1) {  // move the cloud next to the origin, keeping the tiny differences
      const Vec3 shift = pts[0] - Vec3{fraction(static_cast<long>(rng() % 5), 3), Rational(1, 2), Rational(-1, 5)};
      for (Vec3& p : pts) p -= shift;
    }
    const Projection expected = brute_force(pts);
    // The precondition: the nearest point's support holds the newest point,
    // and the points are affinely independent (brute force found the mask).
    if (!(expected.mask & (1u << (count - 1)))) continue;
    bool independent = true;
    {
      std::vector<std::vector<Rational>> g(count - 1, std::vector<Rational>(count - 1));
      std::vector<Rational> r(count - 1);
      for (int i = 0; i + 1 < count; ++i)
        for (int j = 0; j + 1 < count; ++j) g[i][j] = dot(pts[i + 1] - pts[0], pts[j + 1] - pts[0]);
      independent = count == 1 || test::solve_linear(g, r).has_value();
    }
    if (!independent) continue;
    SimplexPoints in{};
    for (int i = 0; i < count; ++i) in[i] = &pts[i];
    const SimplexNearest got = nearest_on_simplex(in, count);
    SCOPED_TRACE("seed 2026, trial " + std::to_string(trial) + ", kind " + std::to_string(kind));
    ASSERT_EQ(got.squared_norm, expected.norm);
    ASSERT_EQ(got.point, expected.point);
    ASSERT_EQ(got.support_mask, expected.mask);
    ASSERT_EQ(weighted_sum(in.data(), got.weight_num.data(), got.weight_den, count), expected.point);
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

}  // namespace
}  // namespace cvms::detail
