// SPDX-License-Identifier: MIT
// Tests of the fixed-width 4×4 determinant sign (lib/predicates/
// fixed_det4.hpp), both by the 2×2 minors and by the last row's cofactors,
// against an independent mpz evaluation (cofactor expansion
// along the first row, 3×3 minors by Sarrus' rule): random entries of every
// width from 1 to 255 bits (seeded), singular matrices (a row a combination
// of the others), the extreme entries ±(2^b − 1) at each limb boundary in
// Hadamard sign patterns (the largest determinants ±1 patterns reach), and
// the refusal of entries of 256 bits and more; and the sign of
// det[a; b; c; p] q_3 − det[a; b; c; q] p_3 (fixed_det4_cross_sign, the dual
// hull's farther-point test) the same way, with ties. Values too, not only
// signs: at every sign pattern of the widest entries (where the parts of the
// sign-and-magnitude sums reach their maxima) the cofactors and the
// determinant from them equal the oracle's; and SignedSum (fixed_int.hpp) at
// the edge of its range, with negative zeros.
#include "fixed_det4.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <string>

#include <gmpxx.h>

namespace cvms {
namespace {

using Rng = std::mt19937_64;
using Matrix = std::array<std::array<mpz_class, 4>, 4>;

mpz_class oracle_det(const Matrix& m) {
  mpz_class det = 0;
  for (int c = 0; c < 4; ++c) {
    int col[3], n = 0;
    for (int k = 0; k < 4; ++k)
      if (k != c) col[n++] = k;
    auto e = [&](int r, int k) -> const mpz_class& { return m[1 + r][col[k]]; };
    const mpz_class minor = e(0, 0) * (e(1, 1) * e(2, 2) - e(1, 2) * e(2, 1)) -
                            e(0, 1) * (e(1, 0) * e(2, 2) - e(1, 2) * e(2, 0)) +
                            e(0, 2) * (e(1, 0) * e(2, 1) - e(1, 1) * e(2, 0));
    det += (c % 2 == 0 ? 1 : -1) * m[0][c] * minor;
  }
  return det;
}

int oracle_sign(const Matrix& m) { return sgn(oracle_det(m)); }

template <int E>
int cofactor_sign(const std::array<std::array<mpz_srcptr, 4>, 4>& p) {
  const detail::Cofactors<E> cof = detail::last_row_cofactors<E>(detail::fixed_row<E>(p[0]), detail::fixed_row<E>(p[1]),
                                                                 detail::fixed_row<E>(p[2]));
  return detail::fixed_det4_sign<E>(cof, detail::fixed_row<E>(p[3]));
}

// The sign by the entry point, checked to agree with the cofactor path
// (last_row_cofactors, then four products) in the same width.
std::optional<int> fixed_sign(const Matrix& m) {
  std::array<std::array<mpz_srcptr, 4>, 4> p;
  int limbs = 1;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      p[r][c] = m[r][c].get_mpz_t();
      limbs = std::max(limbs, detail::signed_limbs(p[r][c]));
    }
  const std::optional<int> s = detail::fixed_det4_sign(p);
  if (!s) return s;
  const int by_cofactors = limbs == 1   ? cofactor_sign<1>(p)
                           : limbs == 2 ? cofactor_sign<2>(p)
                           : limbs == 3 ? cofactor_sign<3>(p)
                                        : cofactor_sign<4>(p);
  EXPECT_EQ(by_cofactors, *s) << "the cofactor path disagrees";
  return s;
}

// A uniform integer of at most `bits` bits, either sign.
mpz_class random_integer(Rng& rng, int bits) {
  mpz_class v = 0;
  for (int k = 0; k < bits; k += 32) v = (v << 32) + mpz_class(static_cast<unsigned long>(rng() & 0xffffffffu));
  mpz_fdiv_r_2exp(v.get_mpz_t(), v.get_mpz_t(), static_cast<mp_bitcnt_t>(bits));
  return rng() % 2 == 0 ? mpz_class(-v) : v;
}

TEST(FixedDet4, RandomMatricesOfEveryWidthMatchMpz) {
  Rng rng(1603);
  int zeros = 0;
  for (int round = 0; round < 6000; ++round) {
    const int bits = 1 + round % 255;
    SCOPED_TRACE("seed 1603 round " + std::to_string(round) + " bits " + std::to_string(bits));
    Matrix m;
    for (auto& row : m)
      for (mpz_class& x : row) x = random_integer(rng, 1 + static_cast<int>(rng() % static_cast<unsigned>(bits)));
    m[0][0] = random_integer(rng, bits);  // one entry of the full width, the rest shorter or equal
    if (round % 3 == 0) {
      // Row 3 = s row 0 + t row 1 (small s, t), clipped to the width: singular
      // when nothing was clipped.
      const long s = static_cast<long>(rng() % 5) - 2, t = static_cast<long>(rng() % 5) - 2;
      bool fits = true;
      for (int c = 0; c < 4; ++c) {
        m[3][c] = s * m[0][c] + t * m[1][c];
        fits = fits && mpz_sizeinbase(m[3][c].get_mpz_t(), 2) <= detail::max_fixed_entry_bits;
      }
      if (!fits) m[3] = m[1];
    }
    const int expected = oracle_sign(m);
    zeros += expected == 0;
    const std::optional<int> got = fixed_sign(m);
    ASSERT_TRUE(got.has_value());
    EXPECT_EQ(*got, expected);
  }
  EXPECT_GE(zeros, 1900);
}

TEST(FixedDet4, ExtremeEntriesAtEveryLimbBoundary) {
  const int hadamard[4][4] = {{1, 1, 1, 1}, {1, -1, 1, -1}, {1, 1, -1, -1}, {1, -1, -1, 1}};
  for (const int bits : {1, 2, 62, 63, 64, 65, 126, 127, 128, 129, 190, 191, 192, 193, 254, 255}) {
    SCOPED_TRACE("bits " + std::to_string(bits));
    mpz_class big = 1;
    big = (big << bits) - 1;
    for (int flip = 0; flip < 16; ++flip) {
      // The Hadamard pattern with rows negated by `flip`, and a swapped
      // pair of rows for odd flips: every sign of the largest determinant.
      Matrix m;
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[r][c] = ((flip >> r) & 1 ? -1 : 1) * hadamard[r][c] * big;
      if (flip % 2 == 1) std::swap(m[1], m[2]);
      ASSERT_EQ(fixed_sign(m), std::optional<int>(oracle_sign(m)));
      // All entries equal: rank one, determinant 0.
      Matrix same;
      for (auto& row : same)
        for (mpz_class& x : row) x = (flip % 2 == 0 ? 1 : -1) * big;
      EXPECT_EQ(fixed_sign(same), std::optional<int>(0));
    }
    // The identity scaled: det = big^4 > 0; one entry −big: det < 0.
    Matrix diag;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) diag[r][c] = r == c ? big : mpz_class(0);
    EXPECT_EQ(fixed_sign(diag), std::optional<int>(1));
    diag[2][2] = -big;
    EXPECT_EQ(fixed_sign(diag), std::optional<int>(-1));
  }
}

// det[a; b; c; p] · q_3 − det[a; b; c; q] · p_3 by the oracle's expansion.
int oracle_cross_sign(const Matrix& abc, const std::array<mpz_class, 4>& p, const std::array<mpz_class, 4>& q) {
  auto det = [&](const std::array<mpz_class, 4>& last) {
    Matrix m = abc;
    m[3] = last;
    return oracle_det(m);
  };
  return sgn(mpz_class(det(p) * q[3] - det(q) * p[3]));
}

template <int E>
detail::FixedRow<E> fixed_row_of(const std::array<mpz_class, 4>& r) {
  return detail::fixed_row<E>({r[0].get_mpz_t(), r[1].get_mpz_t(), r[2].get_mpz_t(), r[3].get_mpz_t()});
}

template <int E>
int cross_sign(const Matrix& abc, const std::array<mpz_class, 4>& p, const std::array<mpz_class, 4>& q) {
  const detail::Cofactors<E> cof =
      detail::last_row_cofactors<E>(fixed_row_of<E>(abc[0]), fixed_row_of<E>(abc[1]), fixed_row_of<E>(abc[2]));
  return detail::fixed_det4_cross_sign<E>(cof, fixed_row_of<E>(p), fixed_row_of<E>(q));
}

int cross_sign_in(int limbs, const Matrix& abc, const std::array<mpz_class, 4>& p, const std::array<mpz_class, 4>& q) {
  return limbs == 1   ? cross_sign<1>(abc, p, q)
         : limbs == 2 ? cross_sign<2>(abc, p, q)
         : limbs == 3 ? cross_sign<3>(abc, p, q)
                      : cross_sign<4>(abc, p, q);
}

int limbs_of(const Matrix& abc, const std::array<mpz_class, 4>& p, const std::array<mpz_class, 4>& q) {
  int limbs = 1;
  for (const auto* r : {&abc[0], &abc[1], &abc[2], &p, &q})
    for (const mpz_class& x : *r) limbs = std::max(limbs, detail::signed_limbs(x.get_mpz_t()));
  return limbs;
}

TEST(FixedDet4, CrossSignMatchesMpz) {
  // fixed_det4_cross_sign, the farther-point comparison of the dual hull
  // (homogeneous_orient.hpp), on random rows of every width, with ties:
  // q = k p (both products equal k det(p) p_3) when that fits the width.
  Rng rng(1605);
  int ties = 0;
  for (int round = 0; round < 6000; ++round) {
    const int bits = 1 + round % 255;
    SCOPED_TRACE("seed 1605 round " + std::to_string(round) + " bits " + std::to_string(bits));
    Matrix abc;
    std::array<mpz_class, 4> p, q;
    for (auto* r : {&abc[0], &abc[1], &abc[2], &p, &q})
      for (mpz_class& x : *r) x = random_integer(rng, 1 + static_cast<int>(rng() % static_cast<unsigned>(bits)));
    abc[0][0] = random_integer(rng, bits);
    if (round % 3 == 0) {
      const long k = static_cast<long>(rng() % 5) - 2;
      bool fits = true;
      for (int c = 0; c < 4; ++c) {
        q[c] = k * p[c];
        fits = fits && mpz_sizeinbase(q[c].get_mpz_t(), 2) <= detail::max_fixed_entry_bits;
      }
      if (!fits) q = p;
    }
    const int expected = oracle_cross_sign(abc, p, q);
    ties += expected == 0;
    EXPECT_EQ(cross_sign_in(limbs_of(abc, p, q), abc, p, q), expected);
    EXPECT_EQ(cross_sign_in(limbs_of(abc, p, q), abc, q, p), -expected);
  }
  EXPECT_GE(ties, 1900);
}

TEST(FixedDet4, CrossSignOfExtremeEntries) {
  // Entries ±(2^b − 1) in Hadamard patterns for a, b, c, p (the largest
  // determinants) and q = p with its weight changed: the largest products
  // the bound allows, of both signs.
  const int hadamard[4][4] = {{1, 1, 1, 1}, {1, -1, 1, -1}, {1, 1, -1, -1}, {1, -1, -1, 1}};
  for (const int bits : {1, 2, 63, 64, 127, 128, 191, 192, 254, 255}) {
    SCOPED_TRACE("bits " + std::to_string(bits));
    mpz_class big = 1;
    big = (big << bits) - 1;
    for (int flip = 0; flip < 32; ++flip) {
      Matrix abc;
      std::array<mpz_class, 4> p, q;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) abc[r][c] = ((flip >> r) & 1 ? -1 : 1) * hadamard[r][c] * big;
      for (int c = 0; c < 4; ++c) {
        p[c] = ((flip >> 3) & 1 ? -1 : 1) * hadamard[3][c] * big;
        q[c] = (c == 3) != ((flip >> 4) & 1) ? -p[c] : p[c];
      }
      const int limbs = limbs_of(abc, p, q);
      EXPECT_EQ(cross_sign_in(limbs, abc, p, q), oracle_cross_sign(abc, p, q));
      EXPECT_EQ(cross_sign_in(limbs, abc, p, p), 0);
    }
  }
}

// The oracle's last-row cofactor k: det = sum_k m[3][k] cof_k.
mpz_class oracle_cofactor(const Matrix& m, int k) {
  Matrix with_unit = m;
  for (int c = 0; c < 4; ++c) with_unit[3][c] = c == k ? 1 : 0;
  return oracle_det(with_unit);
}

template <int E>
mpz_class value_of(const detail::FixedInt<E>& x) {
  mpz_class v;
  detail::assign_to(v.get_mpz_t(), x);
  return v;
}

// Every sign pattern of the widest entries ±(2^(64E − 1) − 1): the parts of
// the signed sums are convex in each entry, so their maxima are among these
// (the Hadamard patterns reach the determinant's bound, 16 M^4, with no bit
// to spare). Values, not only signs: the cofactors and the determinant
// from them against the oracle.
template <int E>
void expect_exact_at_every_sign_pattern() {
  SCOPED_TRACE("E = " + std::to_string(E));
  const mpz_class big = (mpz_class(1) << (64 * E - 1)) - 1;
  for (unsigned pattern = 0; pattern < (1u << 16); ++pattern) {
    Matrix m;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) m[r][c] = (pattern >> (4 * r + c)) & 1 ? mpz_class(-big) : big;
    const mpz_class det = oracle_det(m);
    const detail::Cofactors<E> cof =
        detail::last_row_cofactors<E>(fixed_row_of<E>(m[0]), fixed_row_of<E>(m[1]), fixed_row_of<E>(m[2]));
    for (int k = 0; k < 4; ++k) ASSERT_EQ(value_of(cof[static_cast<std::size_t>(k)]), oracle_cofactor(m, k)) << pattern;
    ASSERT_EQ(value_of(detail::fixed_det4<E>(cof, fixed_row_of<E>(m[3]))), det) << pattern;
    ASSERT_EQ(detail::fixed_det4_sign<E>(cof, fixed_row_of<E>(m[3])), sgn(det)) << pattern;
    ASSERT_EQ(detail::fixed_det4_sign<E>(fixed_row_of<E>(m[0]), fixed_row_of<E>(m[1]), fixed_row_of<E>(m[2]),
                                         fixed_row_of<E>(m[3])),
              sgn(det))
        << pattern;
  }
}

TEST(FixedDet4, ExactValuesAtEverySignPatternOfTheWidestEntries) {
  expect_exact_at_every_sign_pattern<1>();
  expect_exact_at_every_sign_pattern<4>();
}

TEST(FixedDet4, CrossSignWithBothProductsInOnePart) {
  // The rows below put both products of the cross sign in one part of its
  // sum (24 M^5 for M = 2^(64E − 1) − 1, above one product's bound); then
  // random sign patterns of the widest entries, both ways round.
  const int worst[5][4] = {{-1, -1, -1, -1}, {-1, -1, 1, 1}, {-1, 1, -1, 1}, {-1, 1, 1, -1}, {-1, 1, 1, 1}};
  for (int bits : {63, 127, 191, 255}) {
    SCOPED_TRACE("bits " + std::to_string(bits));
    const mpz_class big = (mpz_class(1) << bits) - 1;
    Rng rng(static_cast<std::uint64_t>(bits));
    for (int round = 0; round < 2000; ++round) {
      Matrix abc;
      std::array<mpz_class, 4> p, q;
      std::array<mpz_class, 4>* rows[5] = {&abc[0], &abc[1], &abc[2], &p, &q};
      for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 4; ++c)
          (*rows[r])[static_cast<std::size_t>(c)] = round == 0 ? worst[r][c] * big : (rng() % 2 ? -big : big);
      const int expected = oracle_cross_sign(abc, p, q);
      const int limbs = limbs_of(abc, p, q);
      ASSERT_EQ(cross_sign_in(limbs, abc, p, q), expected) << "seed " << bits << " round " << round;
      ASSERT_EQ(cross_sign_in(limbs, abc, q, p), -expected) << "seed " << bits << " round " << round;
    }
  }
}

// A signed sum at the edge of its range: parts of 2^(64L) − 1 reached with
// a carry through every limb, P == N (a zero, not negative), P − N = ±(2^(64L)
// − 2); a negative zero as operand and as value; the widest product.
template <int L>
void expect_signed_sum_edges() {
  SCOPED_TRACE("L = " + std::to_string(L));
  detail::FixedInt<L> half, below_half, one;
  half.magnitude[L - 1] = std::uint64_t{1} << 63;  // 2^(64L − 1)
  for (std::uint64_t& w : below_half.magnitude) w = ~std::uint64_t{0};
  below_half.magnitude[L - 1] >>= 1;  // 2^(64L − 1) − 1
  one.magnitude[0] = 1;
  const mpz_class top = (mpz_class(1) << (64 * L)) - 1;

  detail::SignedSum<L> equal;
  equal.add(half);
  equal.add(below_half);
  EXPECT_EQ(value_of(equal.value()), top);
  detail::FixedInt<L> minus_half = half;
  minus_half.negative = true;
  equal.add(minus_half);
  equal.subtract(below_half);
  EXPECT_EQ(equal.sign(), 0);
  EXPECT_TRUE(equal.value().zero());
  EXPECT_FALSE(equal.value().negative);

  detail::SignedSum<L> negative;
  negative.subtract(half);
  negative.subtract(below_half);
  negative.add(one);
  EXPECT_EQ(negative.sign(), -1);
  EXPECT_EQ(value_of(negative.value()), -(top - 1));
  mpz_class negated;
  detail::assign_to(negated.get_mpz_t(), negative.value(), true);
  EXPECT_EQ(negated, top - 1);

  detail::FixedInt<L> negative_zero;
  negative_zero.negative = true;
  EXPECT_EQ(negative_zero.sign(), 0);
  EXPECT_EQ(value_of(negative_zero), 0);
  EXPECT_EQ(multiply(negative_zero, half).sign(), 0);

  detail::FixedInt<L> all;
  for (std::uint64_t& w : all.magnitude) w = ~std::uint64_t{0};
  all.negative = true;
  EXPECT_EQ(value_of(multiply(all, all)), top * top);
  detail::FixedInt<L> positive_all = all;
  positive_all.negative = false;
  EXPECT_EQ(value_of(multiply(all, positive_all)), -(top * top));
}

TEST(FixedInt, SignedSumAtTheEdgeOfItsRange) {
  expect_signed_sum_edges<1>();
  expect_signed_sum_edges<2>();
  expect_signed_sum_edges<3>();
  expect_signed_sum_edges<5>();
}

TEST(FixedDet4, LongEntriesAreLeftToMpz) {
  Matrix m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[r][c] = r == c ? 1 : 0;
  m[3][1] = mpz_class(1) << 255;  // 256 bits
  EXPECT_FALSE(fixed_sign(m).has_value());
  m[3][1] = -(mpz_class(1) << 255);
  EXPECT_FALSE(fixed_sign(m).has_value());
  m[3][1] = (mpz_class(1) << 255) - 1;
  EXPECT_EQ(fixed_sign(m), std::optional<int>(1));
}

}  // namespace
}  // namespace cvms
