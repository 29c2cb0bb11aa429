// SPDX-License-Identifier: MIT
// Sums of one-word fractions in machine words against GMP's mpq_add (the
// oracle): decimal denominators up to 10^19, random 64-bit ones, small and
// equal ones, numerators up to 2^64 - 1 of either sign, sums that cancel.
#include "word_fraction.hpp"

#include <gtest/gtest.h>

#include <random>

#include "limb_arena.hpp"

namespace cvms::detail {
namespace {

Rational oracle_sum(const Rational& x, const Rational& y) {
  Rational s;
  mpq_add(s.get_mpq_t(), x.get_mpq_t(), y.get_mpq_t());
  return s;
}

Rational as_rational(const WordFraction& f) {
  const bool negative = f.numerator < 0;
  const WordFraction::Uint128 m =
      negative ? -static_cast<WordFraction::Uint128>(f.numerator) : static_cast<WordFraction::Uint128>(f.numerator);
  const auto integer = [](WordFraction::Uint128 v) -> mpz_class {
    return (mpz_class(static_cast<unsigned long>(v >> 64)) << 64) + mpz_class(static_cast<unsigned long>(v));
  };
  Rational q;
  q.get_num() = negative ? mpz_class(-integer(m)) : integer(m);
  q.get_den() = integer(f.denominator);
  return q;  // not canonicalised: lowest terms are part of what is checked
}

TEST(WordFraction, SumsMatchMpqAdd) {
  const std::uint64_t seed = 5201;
  std::mt19937_64 rng(seed);
  const auto denominator = [&]() -> std::uint64_t {
    switch (rng() % 5) {
      case 0: {
        std::uint64_t d = 1;
        for (int k = static_cast<int>(rng() % 20); k > 0; --k) d *= 10;  // 10^0 .. 10^19
        return d;
      }
      case 1:
        return rng() | 1;  // a random odd 64-bit one
      case 2:
        return 1 + rng() % 12;
      case 3:
        return std::uint64_t{1} << (rng() % 64);
      default:
        return 999983;
    }
  };
  const auto numerator = [&]() -> mpz_class {
    const int bits = 1 + static_cast<int>(rng() % 64);
    const std::uint64_t m = bits == 64 ? rng() : rng() & ((std::uint64_t{1} << bits) - 1);
    const mpz_class v(static_cast<unsigned long>(m));
    return rng() % 2 ? mpz_class(-v) : v;
  };
  int fast = 0;
  for (int i = 0; i < 20000; ++i) {
    Rational x(numerator(), mpz_class(static_cast<unsigned long>(denominator())));
    x.canonicalize();
    Rational y = i % 17 == 0 ? Rational(-x) : Rational(numerator(), mpz_class(static_cast<unsigned long>(denominator())));
    y.canonicalize();
    const Rational expected = oracle_sum(x, y);
    const std::optional<WordFraction> sum = word_fraction_sum(x, y);
    if (!sum) continue;  // a fallback is always allowed; a wrong answer never
    ++fast;
    ASSERT_EQ(as_rational(*sum).get_num(), expected.get_num()) << "seed " << seed << " i " << i << ": " << x << " + " << y;
    ASSERT_EQ(as_rational(*sum).get_den(), expected.get_den()) << "seed " << seed << " i " << i << ": " << x << " + " << y;
    LimbArena arena;
    Rational stored;
    store_word_fraction(arena, stored, *sum);
    ASSERT_EQ(stored, expected) << "seed " << seed << " i " << i;
  }
  EXPECT_GT(fast, 15000) << "one-word fractions should mostly take the word path";
}

TEST(WordFraction, DeclinesWhatWordsCannotHold) {
  const Rational two_limbs(mpz_class(1) << 64, mpz_class(3));
  EXPECT_FALSE(word_fraction_sum(two_limbs, Rational(1, 3)));
  const Rational long_den(mpz_class(1), mpz_class(1) << 64);
  EXPECT_FALSE(word_fraction_sum(Rational(1, 3), long_den));
  // Coprime denominators near 2^64 and numerators near 2^64: cross products beyond 2^126.
  const mpz_class big("18446744073709551557");  // the largest prime below 2^64
  const Rational x(big - 2, big), y(big - 4, big - 2);
  EXPECT_FALSE(word_fraction_sum(x, y));
  EXPECT_TRUE(word_fraction_sum(Rational(0), Rational(0)));
  EXPECT_EQ(as_rational(*word_fraction_sum(Rational(1, 10), Rational(-1, 10))), Rational(0));
}

}  // namespace
}  // namespace cvms::detail
