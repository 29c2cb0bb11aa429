// SPDX-License-Identifier: MIT
// Approx::of: the bound |value - q| <= error holds, checked exactly, and
// error == 0 exactly when q is a double; Approx::of_quotient's bound holds.
#include "approx.hpp"
#include "error_bounds.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <string>

#include "support/random_numbers.hpp"

namespace cvms {
namespace {

using test::power_of_two;

// The oracle for "q is a double": mpq_set_d is exact, so compare.
bool is_a_double(const Rational& q) {
  if (abs(q) > Rational(DBL_MAX)) return false;
  return Rational(to_double_nearest(q)) == q;
}

// Checks the contract of Approx::of for q; returns "" or a message.
std::string check(const Rational& q) {
  Approx a = Approx::of(q);
  if (std::isnan(a.value) || std::isnan(a.error)) return "NaN for " + to_string(q);
  if (!(a.error >= 0)) return "negative error for " + to_string(q);
  if (!std::isfinite(a.value) || !std::isfinite(a.error)) {
    // Unknown is allowed only beyond the double range.
    if (abs(q) < power_of_two(1024)) return "non-finite for in-range " + to_string(q);
    return "";
  }
  Rational diff = abs(Rational(a.value) - q);
  if (diff > Rational(a.error)) return "bound violated for " + to_string(q);
  if ((a.error == 0) != is_a_double(q)) return "exactness wrong for " + to_string(q);
  // The value is one of the two doubles around q (nearest or truncated): q
  // lies strictly between it and the next double toward q.
  if (a.error != 0) {
    double toward = std::nextafter(a.value, Rational(a.value) < q ? INFINITY : -INFINITY);
    if (std::isfinite(toward) && (Rational(toward) - q) * (Rational(a.value) - q) >= 0)
      return "value not adjacent to " + to_string(q);
  }
  return "";
}

TEST(Approx, ExactDoublesHaveZeroError) {
  for (double d : {0.0, 1.0, -1.0, 0.1, -1e300, 1e-300, 5e-324, -5e-324, DBL_MAX, -DBL_MAX, DBL_MIN,
                   DBL_MIN / 3, 123456789.125, std::ldexp(1.0, -1074), std::ldexp(1.0, 1023)}) {
    Approx a = Approx::of(Rational(d));
    EXPECT_EQ(a.value, d);
    EXPECT_EQ(a.error, 0.0) << d;
  }
}

TEST(Approx, HandPickedBoundaries) {
  std::vector<Rational> cases = {
      Rational(1, 3),
      Rational(-1, 3),
      Rational(1, 10),
      power_of_two(1024) - 1,  // truncates to DBL_MAX
      -(power_of_two(1024) - 1),
      power_of_two(1024),
      power_of_two(5000),
      -power_of_two(1030),  // beyond the range
      power_of_two(-1075),  // truncates to 0
      -power_of_two(-1075),
      power_of_two(-3000),
      power_of_two(-1074) * 3 / 2,                                               // between two subnormals
      power_of_two(-1022) - power_of_two(-1080),                                 // just below DBL_MIN
      power_of_two(-1022) + power_of_two(-1080),                                 // just above DBL_MIN
      power_of_two(53) + 1,                                                      // 54 significant bits
      power_of_two(-1074) * (power_of_two(53) - 1),                              // 53 bits, lowest 2^-1074
      power_of_two(-1075) * (power_of_two(53) - 1),                              // one bit too low
      power_of_two(-1074) * (power_of_two(54) - 1),                              // 54 bits
      Rational(power_of_two(1023) * (power_of_two(53) - 1) / power_of_two(52)),  // DBL_MAX exactly
      // Fractions of integers with at most / just over 53 bits (the division fast path).
      test::fraction(mpz_class(1) << 53, 3) - 1,
      test::fraction((mpz_class(1) << 53) - 1, (mpz_class(1) << 52) + 1),
      test::fraction(-((mpz_class(1) << 53) - 1), (mpz_class(1) << 53) - 3),
      test::fraction((mpz_class(1) << 53) + 1, 3),
      test::fraction(1, (mpz_class(1) << 53) + 1),
      test::fraction(mpz_class("18446744073709551615"), 7),
      test::fraction(1, 7),
      test::fraction(-22, 7),
  };
  for (const Rational& q : cases) EXPECT_EQ(check(q), "") << to_string(q).substr(0, 80);
  EXPECT_EQ(Approx::of(power_of_two(-1075)).value, 0.0);
  EXPECT_GT(Approx::of(power_of_two(-1075)).error, 0.0);
  EXPECT_EQ(Approx::of(power_of_two(1024) - 1).value, DBL_MAX);
  EXPECT_FALSE(std::isfinite(Approx::of(power_of_two(1024)).error));
}

TEST(Approx, RandomRationalsBoundHolds) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    test::Rng rng(seed);
    int inexact = 0;
    for (int i = 0; i < 20000; ++i) {
      Rational q = test::random_rational(rng);
      std::string message = check(q);
      ASSERT_EQ(message, "") << "case " << i;
      if (Approx::of(q).error != 0) ++inexact;
    }
    EXPECT_GT(inexact, 1000);  // the generator does produce non-doubles
  }
}

// An integer of at most `limbs` limbs in one of the shapes the tests need:
// 0 random limbs, 1 2^j or 2^j - 1, 2 an odd top limb alone, 3 a top limb
// with its highest bit set and one stray bit far below it, 4 a top limb of
// random length alone, 5 below 1000.
mpz_class integer_of_shape(test::Rng& rng, int limbs, int shape) {
  const auto top_shift = static_cast<unsigned>(64 * (limbs - 1));
  switch (shape) {
    case 0: {
      mpz_class x = 0;
      for (int l = 0; l < limbs; ++l) x = (x << 64) + mpz_class(std::to_string(rng()));
      return x;
    }
    case 1: {
      mpz_class x = mpz_class(1) << static_cast<unsigned>(rng() % (64 * limbs));
      if (rng() % 2 == 0) x -= 1;
      return x;
    }
    case 2:
      return mpz_class(std::to_string(rng() | 1)) << top_shift;
    case 3:
      return (mpz_class(std::to_string(rng() | (std::uint64_t{1} << 63))) << top_shift) +
             (mpz_class(1) << static_cast<unsigned>(rng() % (top_shift + 1)));
    case 4:
      return mpz_class(std::to_string(rng() >> (rng() % 64))) << top_shift;
    default:
      return mpz_class(std::to_string(rng() % 1000));
  }
}

// Numerators of one to six limbs over one-limb powers of two (the normals
// and plane offsets Approx::of reads from the top limbs): the contract, and
// the very double GMP's truncation gives. Shapes: random limbs, 2^j and
// 2^j - 1, a top limb alone, and one stray bit far below it.
TEST(Approx, DyadicsOfEverySizeTruncateLikeGmp) {
  test::Rng rng(2611);
  for (int i = 0; i < 40000; ++i) {
    const int limbs = 1 + static_cast<int>(rng() % 6);
    mpz_class num = integer_of_shape(rng, limbs, static_cast<int>(rng() % 4));
    if (num == 0) continue;
    if (rng() % 2 == 0) num = -num;
    Rational q(num, mpz_class(1) << static_cast<unsigned>(rng() % 64));
    q.canonicalize();
    SCOPED_TRACE("case " + std::to_string(i));
    ASSERT_EQ(check(q), "");
    if (abs(q) < power_of_two(1024)) {
      // The double and the bound of the general path: GMP's truncation, and
      // the truncation bound unless q is a double. The bound's formula is the
      // implementation's own; check(q) above is what proves it exactly.
      const double truncated = mpq_get_d(q.get_mpq_t());
      ASSERT_EQ(Approx::of(q).value, truncated) << to_string(q);
      ASSERT_EQ(Approx::of(q).error, is_a_double(q) ? 0.0 : filtered::truncation_error(truncated)) << to_string(q);
    }
  }
}

// One-limb fractions whose denominator is not a power of two (decimals of
// up to 19 significant digits, like the shortest round-trip decimals of
// doubles): the very double GMP's truncation gives, and the truncation
// bound. Numerators and denominators of every bit length, their extremes
// (1, 2^64 - 1) and powers of ten.
TEST(Approx, OneLimbFractionsTruncateLikeGmp) {
  constexpr unsigned seed = 2613;
  test::Rng rng(seed);
  const auto word = [&rng] {
    const int bits = 1 + static_cast<int>(rng() % 64);
    switch (rng() % 4) {
      case 0:
        return std::uint64_t{1} << (bits - 1);
      case 1:
        return bits == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
      case 2: {
        std::uint64_t ten = 1;
        for (int k = rng() % 20; k > 0; --k) ten *= 10;
        return ten;
      }
      default:
        return (rng() | std::uint64_t{1} << 63) >> (64 - bits);
    }
  };
  for (int i = 0; i < 200000; ++i) {
    Rational q(mpz_class(static_cast<unsigned long>(word())), mpz_class(static_cast<unsigned long>(word())));
    q.canonicalize();
    if (rng() % 2 == 0) q = -q;
    if (q == 0) continue;
    SCOPED_TRACE("case " + std::to_string(i) + ", seed " + std::to_string(seed) + ": " + to_string(q));
    ASSERT_EQ(check(q), "");
    const double truncated = mpq_get_d(q.get_mpq_t());
    const bool one_limb = mpz_size(q.get_num_mpz_t()) == 1 && mpz_size(q.get_den_mpz_t()) == 1;
    const bool small =
        mpz_sizeinbase(q.get_num_mpz_t(), 2) <= 53 && mpz_sizeinbase(q.get_den_mpz_t(), 2) <= 53;
    if (one_limb && !small && !is_a_double(q)) {
      ASSERT_EQ(Approx::of(q).value, truncated);
      ASSERT_EQ(Approx::of(q).error, filtered::truncation_error(truncated));
    }
  }
}

// Approx::of_quotient for integers n / d, unreduced: the bound holds
// exactly (the oracle is the exact rational), and it is never looser than
// the documented |value| 2^-51. Sizes of 1 to 6 limbs, tops with and without
// their highest bit, powers of two and their neighbours (the rounding of
// the tops' conversions), common factors, and exponents on both sides of the
// fast path's range (|s_n - s_d| = 900).
mpz_class random_integer(test::Rng& rng) {
  const int limbs = 1 + static_cast<int>(rng() % 6);
  constexpr int shapes[4] = {0, 1, 4, 5};
  return integer_of_shape(rng, limbs, shapes[rng() % 4]);
}

std::string check_quotient(const mpz_class& n, const mpz_class& d) {
  const Approx a = Approx::of_quotient(n.get_mpz_t(), d.get_mpz_t());
  const std::string which = n.get_str() + " / " + d.get_str();
  if (std::isnan(a.value) || std::isnan(a.error) || !(a.error >= 0)) return "no bound for " + which;
  Rational q(n, d);
  q.canonicalize();
  if (!std::isfinite(a.value) || !std::isfinite(a.error))
    return abs(q) < power_of_two(1024) ? "non-finite for in-range " + which : "";
  if (abs(Rational(a.value) - q) > Rational(a.error)) return "bound violated for " + which;
  if (a.error > std::fabs(a.value) * 0x1p-51 && a.error > filtered::truncation_error(a.value))
    return "bound looser than documented for " + which;
  return "";
}

TEST(Approx, QuotientsOfIntegersFromTheirTopBits) {
  test::Rng rng(2612);
  for (int i = 0; i < 60000; ++i) {
    mpz_class n = random_integer(rng), d = random_integer(rng);
    if (d == 0) continue;
    const mpz_class common = random_integer(rng) % 100000;
    if (common > 0) {
      n *= common;
      d *= common;
    }
    if (rng() % 2 == 0) n = -n;
    SCOPED_TRACE("case " + std::to_string(i) + ", seed 2612");
    ASSERT_EQ(check_quotient(n, d), "");
  }
  // The edges of the fast path (|s_n - s_d| = 900, s = bit length - 64, so
  // s = 839 against 7, whose s is -61), beyond them (mpq_get_d on the
  // unreduced fraction: numerator and denominator share a factor) and
  // beyond the double range.
  const mpz_class seven = 7, shared = 12345;
  for (const mpz_class& top : {mpz_class(1), mpz_class(3), mpz_class((mpz_class(1) << 64) - 1)}) {
    const int top_bits = static_cast<int>(mpz_sizeinbase(top.get_mpz_t(), 2));
    for (const int s : {838, 839, 840, 899, 900, 901, 1000, 1100, 1200}) {
      const mpz_class big = top << static_cast<unsigned>(s + 64 - top_bits);
      for (const mpz_class& n : {mpz_class(big), mpz_class(-big)}) {
        ASSERT_EQ(check_quotient(n, seven), "") << s;
        ASSERT_EQ(check_quotient(seven * (n < 0 ? -1 : 1), big), "") << s;
        ASSERT_EQ(check_quotient(n * shared, seven * shared), "") << s;
        ASSERT_EQ(check_quotient(seven * shared, big * shared), "") << s;
      }
    }
  }
  // Tails just below 2^s under tops that round up to 2^64 when converted:
  // the largest e_n and e_d of the proof, in both places.
  for (const unsigned s : {1u, 11u, 63u, 64u, 65u, 200u}) {
    const mpz_class ones = (mpz_class(1) << (64 + s)) - 1;
    for (const unsigned t : {0u, 1u, 64u, 130u}) {
      const mpz_class low = (mpz_class(1) << (63 + t)) + 1;
      ASSERT_EQ(check_quotient(ones, low), "") << s << " " << t;
      ASSERT_EQ(check_quotient(low, ones), "") << s << " " << t;
      ASSERT_EQ(check_quotient(-ones, ones + 2), "") << s << " " << t;
    }
  }
  EXPECT_EQ(Approx::of_quotient(mpz_class(0).get_mpz_t(), mpz_class(5).get_mpz_t()).value, 0.0);
  EXPECT_EQ(Approx::of_quotient(mpz_class(0).get_mpz_t(), mpz_class(5).get_mpz_t()).error, 0.0);
}

TEST(Approx, RandomDoubleNeighbours) {
  // Values just off a double (by a fraction of its ulp), all exponents.
  test::Rng rng(7);
  for (int i = 0; i < 20000; ++i) {
    double d = test::random_double_bits(rng);
    double next = std::nextafter(d, std::numeric_limits<double>::infinity());
    if (!std::isfinite(next)) continue;
    Rational lo(d), hi(next);
    Rational t = test::fraction(static_cast<long>(rng() % 1000) + 1, 1001);
    ASSERT_EQ(check(lo + (hi - lo) * t), "") << d;
  }
}

TEST(Approx, VectorsApproximateEachCoordinate) {
  Vec3 v{Rational(1, 3), Rational(2), Rational(-1, 10)};
  ApproxVec3 a = ApproxVec3::of(v);
  EXPECT_EQ(a.y.error, 0.0);
  EXPECT_GT(a.x.error, 0.0);
  EXPECT_LE(abs(Rational(a.z.value) - v.z), Rational(a.z.error));
  ApproxVec2 b = ApproxVec2::of(Vec2{Rational(5), Rational(1, 3)});
  EXPECT_EQ(b.x.value, 5.0);
  EXPECT_GT(b.y.error, 0.0);
}

}  // namespace
}  // namespace cvms
