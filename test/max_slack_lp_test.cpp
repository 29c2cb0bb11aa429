// SPDX-License-Identifier: MIT
// Tests of the max-slack LP (lib/halfspaces/max_slack_lp.hpp) against a
// brute-force optimum: for d <= 3 unknowns the optimum of max t subject to
// a_i·u + t <= b_i, t <= 1 is attained at a basic solution, where d + 1 of
// the constraints (with independent rows) are tight, so the largest t over
// the feasible basic solutions is t*. Random systems in 1, 2 and 3 unknowns
// with interior (t* > 0), flat (t* == 0: pairs of opposite rows) and empty
// (t* < 0) intersections; the answer's point must reach t*, and at t* == 0
// every reported tight row must be tight there.
#include "max_slack_lp.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "support/linear_solve.hpp"

namespace cvms {
namespace {

using Rng = std::mt19937_64;
using detail::LpRow;

// max t over the feasible basic solutions of (u, t) with rows plus t <= 1;
// nothing if the normals do not span R^d (then there is no basic solution).
std::optional<Rational> brute_force_slack(const std::vector<LpRow>& rows, std::size_t d) {
  std::vector<LpRow> all = rows;
  all.push_back({std::vector<Rational>(d, Rational(0)), Rational(1)});  // with t: t <= 1
  std::optional<Rational> best;
  const std::size_t m = all.size();
  std::vector<std::size_t> pick(d + 1);
  // Every (d + 1)-subset in increasing order.
  auto visit = [&](auto&& self, std::size_t depth, std::size_t from) -> void {
    if (depth == d + 1) {
      std::vector<std::vector<Rational>> a;
      std::vector<Rational> b;
      for (std::size_t i : pick) {
        std::vector<Rational> row = all[i].a;
        row.push_back(1);
        a.push_back(row);
        b.push_back(all[i].b);
      }
      const std::optional<std::vector<Rational>> x = test::solve_linear(a, b);
      if (!x) return;
      for (const LpRow& r : all) {
        Rational lhs = (*x)[d];
        for (std::size_t k = 0; k < d; ++k) lhs += r.a[k] * (*x)[k];
        if (lhs > r.b) return;
      }
      if (!best || (*x)[d] > *best) best = (*x)[d];
      return;
    }
    for (std::size_t i = from; i < m; ++i) {
      pick[depth] = i;
      self(self, depth + 1, i + 1);
    }
  };
  visit(visit, 0, 0);
  return best;
}

Rational slack_at(const LpRow& r, const std::vector<Rational>& u) {
  Rational s = r.b;
  for (std::size_t k = 0; k < u.size(); ++k) s -= r.a[k] * u[k];
  return s;
}

std::vector<LpRow> random_system(Rng& rng, std::size_t d, int kind) {
  std::vector<LpRow> rows;
  auto coordinate = [&] { return Rational(static_cast<long>(rng() % 9) - 4); };
  const std::size_t count = d + 2 + rng() % 5;
  while (rows.size() < count) {
    LpRow r;
    bool zero = true;
    for (std::size_t k = 0; k < d; ++k) {
      r.a.push_back(coordinate());
      zero = zero && r.a.back() == 0;
    }
    if (zero) continue;
    Rational b(static_cast<long>(rng() % 13) - 4, 1 + static_cast<long>(rng() % 3));
    b.canonicalize();
    r.b = b;
    rows.push_back(r);
    if (kind > 0 && rows.size() == 1) {
      // The opposite row, offset by 0 (a flat set, t* == 0) or by more (empty).
      LpRow o{{}, -b - Rational(kind - 1)};
      for (const Rational& v : r.a) o.a.push_back(-v);
      rows.push_back(o);
    }
  }
  return rows;
}

TEST(MaxSlackLp, MatchesTheBruteForceOptimum) {
  Rng rng(1603);
  int positive = 0, zero = 0, negative = 0;
  for (int round = 0; round < 600; ++round) {
    SCOPED_TRACE("seed 1603 round " + std::to_string(round));
    const std::size_t d = 1 + static_cast<std::size_t>(round % 3);
    const std::vector<LpRow> rows = random_system(rng, d, (round / 3) % 3);
    const std::optional<Rational> expected = brute_force_slack(rows, d);
    if (!expected) continue;
    const detail::MaxSlack lp = detail::max_slack(rows, static_cast<int>(d));
    ASSERT_EQ(lp.slack, *expected);
    ASSERT_EQ(lp.point.size(), d);
    for (const LpRow& r : rows) EXPECT_GE(slack_at(r, lp.point), lp.slack);
    positive += sgn(lp.slack) > 0;
    negative += sgn(lp.slack) < 0;
    if (sgn(lp.slack) != 0) continue;
    ++zero;
    EXPECT_FALSE(lp.tight.empty());
    for (std::size_t i : lp.tight) EXPECT_EQ(slack_at(rows[i], lp.point), 0);
  }
  EXPECT_GE(positive, 50) << zero << " " << negative;
  EXPECT_GE(zero, 50) << positive << " " << negative;
  EXPECT_GE(negative, 50) << positive << " " << zero;
}

// Tangent planes n·u <= n·c + 1 of the unit sphere about c = (3, 0, 0),
// which does not hold the origin (so some right-hand sides are negative),
// with exact rational unit normals (inverse stereographic projection of a
// grid), sorted by their normals: the farthest planes first, neighbours
// next to each other, the order in which a rule that prefers low row
// indices walks over every plane. The same rows in a few shuffled orders
// take about as many pivots: the LP processes rows in an order of its own.
std::vector<LpRow> sorted_tangent_planes(int side) {
  std::vector<std::vector<Rational>> normals;
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      const Rational a = Rational(4 * i - 2 * side, side) + Rational(1, 2 * side + 1);
      const Rational b = Rational(4 * j - 2 * side, side) + Rational(1, 3 * side + 1);
      const Rational s = 1 + a * a + b * b;
      std::vector<Rational> n{2 * a / s, 2 * b / s, (1 - a * a - b * b) / s};
      for (Rational& v : n) v.canonicalize();
      normals.push_back(std::move(n));
    }
  }
  std::sort(normals.begin(), normals.end());
  std::vector<LpRow> rows;
  for (std::vector<Rational>& n : normals) {
    Rational b = 3 * n[0] + 1;
    rows.push_back({std::move(n), std::move(b)});
  }
  return rows;
}

TEST(MaxSlackLp, SortedRowsTakeAboutAsManyPivotsAsShuffledOnes) {
  const std::vector<LpRow> sorted = sorted_tangent_planes(30);  // 900 rows
  const detail::MaxSlack answer = detail::max_slack(sorted, 3);
  ASSERT_GT(sgn(answer.slack), 0);
  std::size_t most_shuffled = 0;
  Rng rng(5);
  for (int k = 0; k < 5; ++k) {
    std::vector<LpRow> shuffled = sorted;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    const detail::MaxSlack s = detail::max_slack(shuffled, 3);
    EXPECT_EQ(s.slack, answer.slack);
    most_shuffled = std::max(most_shuffled, s.pivots);
  }
  // Taken in the given order, Bland's rule walks over the planes (more than
  // a thousand pivots); in a random order it takes about ten. A small
  // allowance on top of twice the shuffled count keeps the test independent
  // of how std::shuffle draws on a given library.
  EXPECT_LE(answer.pivots, 2 * most_shuffled + 10)
      << answer.pivots << " pivots sorted, " << most_shuffled << " shuffled";
  EXPECT_LE(answer.pivots, 100u);
}

}  // namespace
}  // namespace cvms
