// SPDX-License-Identifier: MIT
// Packed dyadic numbers and DyadicPoints (lib/numeric/dyadic_points.hpp)
// against values built with GMP's own arithmetic (the oracle): packing then
// unpacking gives the original, canonical value; the packing's fields are
// the canonical ones (zero is size 0, exponent 0, word 0; a one-limb
// numerator is inline; the exponent is log2 of the denominator), whichever
// overload packed it; non-dyadic values are refused; long numerators stay
// valid in an arena the points keep, after the arena object and across
// moves of the points; two threads with arenas of their own store what one
// thread stores.
#include "dyadic_points.hpp"

#include <gmp.h>
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "cvms/rational.hpp"
#include "cvms/vec.hpp"
#include "dyadic.hpp"
#include "limb_arena.hpp"

namespace cvms::detail {
namespace {

// --- the oracle: values made with GMP alone -------------------------------

/// The integer whose n limbs (least significant first) are `limbs`.
mpz_class from_limbs(const std::vector<std::uint64_t>& limbs) {
  mpz_class z;
  mpz_import(z.get_mpz_t(), limbs.size(), -1, sizeof(std::uint64_t), 0, 0, limbs.data());
  return z;
}

/// A random integer of exactly n limbs (its top limb nonzero).
mpz_class random_integer(std::mt19937_64& rng, std::size_t n) {
  std::vector<std::uint64_t> limbs(n);
  for (std::uint64_t& limb : limbs) limb = rng();
  if (limbs.back() == 0) limbs.back() = 1;
  return from_limbs(limbs);
}

/// sign * magnitude / 2^exponent, canonicalised by GMP.
Rational dyadic(const mpz_class& magnitude, bool negative, unsigned long exponent) {
  mpz_class den;
  mpz_ui_pow_ui(den.get_mpz_t(), 2, exponent);
  Rational q(negative ? mpz_class(-magnitude) : magnitude, den);
  q.canonicalize();
  return q;
}

/// (high 2^64 + low) / 2^exponent with the sign, by mpz arithmetic.
Rational two_limb_value(std::uint64_t low, std::uint64_t high, bool negative, unsigned long exponent) {
  mpz_class magnitude = mpz_class(static_cast<unsigned long>(high));
  magnitude <<= 64;
  magnitude += static_cast<unsigned long>(low);
  return dyadic(magnitude, negative, exponent);
}

FixedDyadic<2> fixed(std::uint64_t low, std::uint64_t high, bool negative, mp_bitcnt_t exponent) {
  FixedDyadic<2> value;
  value.numerator.magnitude = {low, high};
  value.numerator.negative = negative;
  value.exponent = exponent;
  return value;
}

std::string describe(const FixedDyadic<2>& v) {
  return "fixed low " + std::to_string(v.numerator.magnitude[0]) + " high " +
         std::to_string(v.numerator.magnitude[1]) + (v.numerator.negative ? " negative" : " positive") +
         " exponent " + std::to_string(v.exponent);
}

// --- checks -----------------------------------------------------------------

/// q is in lowest terms with a positive denominator (GMP's canonical form).
void expect_canonical(const Rational& q) {
  Rational copy(q);
  copy.canonicalize();
  EXPECT_EQ(copy.get_num(), q.get_num()) << q.get_str();
  EXPECT_EQ(copy.get_den(), q.get_den()) << q.get_str();
  EXPECT_GT(sgn(q.get_den()), 0) << q.get_str();
  mpz_class gcd;
  mpz_gcd(gcd.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  EXPECT_EQ(gcd, 1) << q.get_str();
}

/// got is exactly expected, numerator and denominator alike, and canonical.
void expect_same_rational(const Rational& got, const Rational& expected) {
  EXPECT_EQ(got.get_num(), expected.get_num())
      << "got " << got.get_str() << ", expected " << expected.get_str();
  EXPECT_EQ(got.get_den(), expected.get_den())
      << "got " << got.get_str() << ", expected " << expected.get_str();
  expect_canonical(got);
}

/// The packing's fields are the canonical packing of the canonical `value`.
void expect_packing_of(const PackedDyadic& p, const Rational& value) {
  mpz_srcptr num = value.get_num_mpz_t();
  mpz_srcptr den = value.get_den_mpz_t();
  ASSERT_EQ(mpz_popcount(den), 1U) << "oracle value not dyadic: " << value.get_str();
  if (sgn(value) == 0) {
    EXPECT_EQ(p.size, 0);
    EXPECT_EQ(p.exponent, 0U);
    EXPECT_EQ(p.word, 0U);
    return;
  }
  EXPECT_EQ(p.size < 0, sgn(value) < 0) << "size " << p.size;
  EXPECT_EQ(static_cast<std::size_t>(std::abs(p.size)), mpz_size(num)) << "size " << p.size;
  EXPECT_EQ(p.exponent, mpz_sizeinbase(den, 2) - 1);
  if (mpz_size(num) == 1) {
    EXPECT_EQ(p.word, mpz_getlimbn(num, 0));
  } else if (static_cast<std::size_t>(std::abs(p.size)) == mpz_size(num)) {
    const auto* limbs = reinterpret_cast<const mp_limb_t*>(p.word);
    for (std::size_t i = 0; i < mpz_size(num); ++i)
      EXPECT_EQ(limbs[i], mpz_getlimbn(num, static_cast<mp_size_t>(i))) << "limb " << i;
  }
}

Rational unpacked(const PackedDyadic& p) {
  Rational out;
  unpack_dyadic(p, out);
  return out;
}

/// Packs the canonical dyadic `value`, checks the fields, unpacks it back.
void expect_round_trip(const Rational& value) {
  SCOPED_TRACE("value " + value.get_str());
  LimbArena arena;
  PackedDyadic p;
  ASSERT_TRUE(pack_dyadic(value, arena, p));
  expect_packing_of(p, value);
  expect_same_rational(unpacked(p), value);
}

/// a and b are the same packing: fields, and the limbs of a long numerator.
void expect_same_packing(const PackedDyadic& a, const PackedDyadic& b) {
  ASSERT_EQ(a.size, b.size);
  EXPECT_EQ(a.exponent, b.exponent);
  if (std::abs(a.size) <= 1) {
    EXPECT_EQ(a.word, b.word);
  } else {
    const auto* la = reinterpret_cast<const mp_limb_t*>(a.word);
    const auto* lb = reinterpret_cast<const mp_limb_t*>(b.word);
    for (int i = 0; i < std::abs(a.size); ++i) EXPECT_EQ(la[i], lb[i]) << "limb " << i;
  }
}

/// A random dyadic of any size: zero, doubles, one to six limb numerators
/// over exponents 0 to 300, integers.
Rational random_dyadic(std::mt19937_64& rng) {
  const bool negative = rng() % 2 == 0;
  switch (rng() % 5) {
    case 0:
      return 0;
    case 1:
      return Rational(std::ldexp(static_cast<double>(rng() >> 11) * (negative ? -1 : 1),
                                 static_cast<int>(rng() % 2000) - 1100));
    case 2:
      return dyadic(random_integer(rng, 1 + rng() % 6), negative, 0);
    default:
      return dyadic(random_integer(rng, 1 + rng() % 6), negative, rng() % 301);
  }
}

// --- pack_dyadic(Rational) ---------------------------------------------------

TEST(DyadicPointsPack, SmallValuesRoundTrip) {
  for (const Rational& q : {Rational(0), Rational(1), Rational(-1), Rational(1, 2), Rational(-1, 2)})
    expect_round_trip(q);
}

TEST(DyadicPointsPack, ZeroPacksAsAllZeroFields) {
  LimbArena arena;
  PackedDyadic p;
  p.word = 99;
  p.exponent = 5;
  p.size = -3;
  ASSERT_TRUE(pack_dyadic(Rational(0), arena, p));
  EXPECT_EQ(p.size, 0);
  EXPECT_EQ(p.exponent, 0U);
  EXPECT_EQ(p.word, 0U);
}

TEST(DyadicPointsPack, DoublesRoundTrip) {
  for (double d : {0.1, -0.1, -1e-300, 1e300, 5e-324, -5e-324, 0.7, DBL_MAX, -DBL_MIN, 3.0, -1024.0}) {
    SCOPED_TRACE("double " + std::to_string(d));
    expect_round_trip(Rational(d));
  }
}

TEST(DyadicPointsPack, OneLimbNumeratorIsInline) {
  for (const Rational& q : {Rational(3), Rational(-3, 8), Rational(0.1), Rational(-1e-300)}) {
    SCOPED_TRACE("value " + q.get_str());
    LimbArena arena;
    PackedDyadic p;
    ASSERT_TRUE(pack_dyadic(q, arena, p));
    EXPECT_EQ(std::abs(p.size), 1);
    EXPECT_EQ(p.word, mpz_getlimbn(q.get_num_mpz_t(), 0));
  }
  // The largest one-limb numerator, both signs.
  mpz_class max_limb = (mpz_class(1) << 64) - 1;
  expect_round_trip(dyadic(max_limb, false, 7));
  expect_round_trip(dyadic(max_limb, true, 0));
}

TEST(DyadicPointsPack, IntegersOfOneToSixLimbsRoundTrip) {
  std::mt19937_64 rng(0x5eed01);
  for (std::size_t n = 1; n <= 6; ++n) {
    SCOPED_TRACE("limbs " + std::to_string(n));
    mpz_class power;
    mpz_setbit(power.get_mpz_t(), 64 * (n - 1));  // the least integer of n limbs
    for (bool negative : {false, true}) {
      expect_round_trip(dyadic(power, negative, 0));
      expect_round_trip(dyadic(random_integer(rng, n), negative, 0));
    }
  }
}

TEST(DyadicPointsPack, DyadicsOfOneToSixLimbNumeratorsRoundTrip) {
  const std::uint64_t seed = 0x5eed02;
  std::mt19937_64 rng(seed);
  for (std::size_t n = 1; n <= 6; ++n) {
    for (unsigned long exponent : {0UL, 1UL, 63UL, 64UL, 65UL, 127UL, 128UL, 200UL, 300UL}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + " limbs " + std::to_string(n) + " exponent " +
                   std::to_string(exponent));
      mpz_class odd = random_integer(rng, n) | 1;
      expect_round_trip(dyadic(odd, rng() % 2 == 0, exponent));
    }
  }
}

TEST(DyadicPointsPack, RandomDyadicsRoundTrip) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    for (int i = 0; i < 400; ++i) expect_round_trip(random_dyadic(rng));
  }
}

TEST(DyadicPointsPack, HugeExponentsRoundTrip) {
  expect_round_trip(dyadic(mpz_class(1), false, 5000));
  expect_round_trip(dyadic(mpz_class(3), true, 100000));
}

TEST(DyadicPointsPack, UnpackOverwritesAnyPreviousValue) {
  const Rational value = dyadic(mpz_class(5), true, 3);
  LimbArena arena;
  PackedDyadic p;
  ASSERT_TRUE(pack_dyadic(value, arena, p));
  mpz_class big;
  mpz_ui_pow_ui(big.get_mpz_t(), 3, 400);
  Rational out(big, big + 2);  // several limbs over several limbs
  out.canonicalize();
  unpack_dyadic(p, out);
  expect_same_rational(out, value);
}

TEST(DyadicPointsPack, RefusesNonDyadicValues) {
  mpz_class two_64 = mpz_class(1) << 64;
  const std::vector<Rational> values = {Rational(1, 3),
                                        Rational(-5, 6),
                                        Rational(1, 10),
                                        Rational(7, 12),
                                        Rational(mpz_class(1), 3 * two_64),  // a low zero limb, top limb 3
                                        Rational(mpz_class(1), (two_64 << 64) + two_64),  // limbs {0, 1, 1}
                                        Rational(mpz_class(-1), two_64 + 1)};
  for (const Rational& q : values) {
    SCOPED_TRACE("value " + q.get_str());
    LimbArena arena;
    PackedDyadic p;
    EXPECT_FALSE(pack_dyadic(q, arena, p));
  }
}

// --- pack_dyadic(FixedDyadic<2>) ----------------------------------------------

/// Packs v, checks the fields against `expected` (made by the oracle) and unpacks.
void expect_fixed_packs_as(const FixedDyadic<2>& v, const Rational& expected) {
  SCOPED_TRACE(describe(v) + ", expected " + expected.get_str());
  LimbArena arena;
  PackedDyadic p;
  pack_dyadic(v, arena, p);
  expect_packing_of(p, expected);
  expect_same_rational(unpacked(p), expected);
}

TEST(DyadicPointsFixed, UnreducedInputsPackReduced) {
  expect_fixed_packs_as(fixed(12, 0, false, 3), Rational(3, 2));
  expect_fixed_packs_as(fixed(0, 1, false, 64), Rational(1));
  expect_fixed_packs_as(fixed(0, 1, true, 65), Rational(-1, 2));
  expect_fixed_packs_as(fixed(0, std::uint64_t{1} << 63, true, 127), Rational(-1));
  expect_fixed_packs_as(fixed(8, 0, false, 2), Rational(2));
  expect_fixed_packs_as(fixed(0, 6, false, 2), two_limb_value(0, 3, false, 1));  // still two limbs
}

TEST(DyadicPointsFixed, NegativeZeroPacksAsZero) {
  LimbArena arena;
  PackedDyadic p;
  p.word = 1;
  p.size = 2;
  p.exponent = 9;
  pack_dyadic(fixed(0, 0, true, 7), arena, p);
  EXPECT_EQ(p.size, 0);
  EXPECT_EQ(p.exponent, 0U);
  EXPECT_EQ(p.word, 0U);
  expect_same_rational(unpacked(p), Rational(0));
}

TEST(DyadicPointsFixed, OddTwoLimbNumeratorsStayTwoLimbs) {
  for (mp_bitcnt_t exponent : {0UL, 1UL, 64UL, 100UL, 127UL}) {
    for (bool negative : {false, true}) {
      const FixedDyadic<2> v = fixed(1, 1, negative, exponent);
      LimbArena arena;
      PackedDyadic p;
      pack_dyadic(v, arena, p);
      SCOPED_TRACE(describe(v));
      EXPECT_EQ(p.size, negative ? -2 : 2);
      EXPECT_EQ(p.exponent, exponent);
      expect_same_rational(unpacked(p), two_limb_value(1, 1, negative, exponent));
    }
  }
}

/// A random two-limb numerator, with zero limbs and trailing zero bits often.
FixedDyadic<2> random_fixed(std::mt19937_64& rng) {
  std::uint64_t low = rng(), high = rng();
  switch (rng() % 4) {
    case 0:
      high = 0;
      break;
    case 1:
      low = 0;
      break;
    case 2:
      low &= ~std::uint64_t{0} << (rng() % 64);
      break;  // trailing zero bits
    default:
      break;
  }
  if (rng() % 16 == 0) low = high = 0;
  return fixed(low, high, rng() % 2 == 0, rng() % 128);
}

TEST(DyadicPointsFixed, RandomTwoLimbValuesMatchMpzArithmetic) {
  const std::uint64_t seed = 0x5eed03;
  std::mt19937_64 rng(seed);
  SCOPED_TRACE("seed " + std::to_string(seed));
  for (int i = 0; i < 3000; ++i) {
    const FixedDyadic<2> v = random_fixed(rng);
    expect_fixed_packs_as(v, two_limb_value(v.numerator.magnitude[0], v.numerator.magnitude[1],
                                            v.numerator.negative, v.exponent));
  }
}

// --- equal values, equal packings ---------------------------------------------------

TEST(DyadicPointsFixed, EqualValuesPackEquallyWhicheverOverload) {
  const std::uint64_t seed = 0x5eed04;
  std::mt19937_64 rng(seed);
  SCOPED_TRACE("seed " + std::to_string(seed));
  LimbArena arena;
  for (int i = 0; i < 3000; ++i) {
    const FixedDyadic<2> v = random_fixed(rng);
    const Rational q =
        two_limb_value(v.numerator.magnitude[0], v.numerator.magnitude[1], v.numerator.negative, v.exponent);
    SCOPED_TRACE(describe(v) + " = " + q.get_str());
    PackedDyadic from_fixed, from_rational;
    pack_dyadic(v, arena, from_fixed);
    ASSERT_TRUE(pack_dyadic(q, arena, from_rational));
    expect_same_packing(from_fixed, from_rational);
  }
}

TEST(DyadicPointsFixed, DifferentRepresentationsPackEqually) {
  // 3/2 as 3/2^1, 6/2^2, 3 2^64 / 2^65; and 2^64 + 1 over 2^3 as itself and times 2^5.
  LimbArena arena;
  const std::vector<std::vector<FixedDyadic<2>>> groups = {
      {fixed(3, 0, false, 1), fixed(6, 0, false, 2), fixed(0, 3, false, 65)},
      {fixed(1, 1, true, 3), fixed(32, 32, true, 8)}};
  for (const auto& group : groups) {
    PackedDyadic first;
    pack_dyadic(group.front(), arena, first);
    for (const FixedDyadic<2>& v : group) {
      SCOPED_TRACE(describe(v));
      PackedDyadic p;
      pack_dyadic(v, arena, p);
      expect_same_packing(p, first);
    }
  }
}

// --- DyadicPoints ------------------------------------------------------------

const Vec3 origin{0, 0, 0};

/// n random points, every coordinate dyadic; a third have a long (three to
/// six limb) numerator somewhere.
std::vector<Vec3> random_points(std::uint64_t seed, std::size_t n) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> points(n);
  for (Vec3& p : points) {
    for (int axis = 0; axis < 3; ++axis) p[axis] = random_dyadic(rng);
    if (rng() % 3 == 0)
      p[static_cast<int>(rng() % 3)] =
          dyadic(random_integer(rng, 3 + rng() % 4) | 1, rng() % 2 == 0, rng() % 301);
  }
  return points;
}

/// Packs points[begin, end) into `points` through `arena`; false if one failed.
bool pack_range(const std::vector<Vec3>& values, std::size_t begin, std::size_t end, LimbArena& arena,
                DyadicPoints& points) {
  bool ok = true;
  for (std::size_t j = begin; j < end; ++j)
    for (int axis = 0; axis < 3; ++axis)
      ok = pack_dyadic(values[j][axis], arena, points.coordinate(j, axis)) && ok;
  return ok;
}

/// Every point of `points` is exactly the same numbers as `expected`.
void expect_points(const DyadicPoints& points, const std::vector<Vec3>& expected) {
  ASSERT_EQ(points.size(), expected.size());
  const std::vector<Vec3> vectors = points.to_vectors();
  ASSERT_EQ(vectors.size(), expected.size());
  for (std::size_t j = 0; j < expected.size(); ++j) {
    SCOPED_TRACE("point " + std::to_string(j));
    const Vec3 p = points.point(j);
    for (int axis = 0; axis < 3; ++axis) {
      SCOPED_TRACE("axis " + std::to_string(axis));
      expect_same_rational(p[axis], expected[j][axis]);
      expect_same_rational(vectors[j][axis], expected[j][axis]);
    }
  }
}

/// Fills fresh heap blocks of the sizes an arena uses with junk limbs, so
/// that limbs read from freed blocks would likely be wrong.
void scribble_over_freed_blocks() {
  std::vector<LimbArena> arenas(4);
  const std::vector<mp_limb_t> junk(4096, ~mp_limb_t{0});
  for (LimbArena& arena : arenas)
    for (int i = 0; i < 8; ++i) (void)arena.copy_limbs(junk.data(), 500);
}

TEST(DyadicPoints, DefaultIsEmpty) {
  const DyadicPoints points;
  EXPECT_EQ(points.size(), 0U);
  EXPECT_TRUE(points.to_vectors().empty());
}

TEST(DyadicPoints, NewPointsAreAtTheOrigin) {
  const DyadicPoints points(37);
  ASSERT_EQ(points.size(), 37U);
  for (std::size_t j = 0; j < points.size(); ++j) {
    SCOPED_TRACE("point " + std::to_string(j));
    EXPECT_EQ(points.point(j), origin);
    for (int axis = 0; axis < 3; ++axis) EXPECT_EQ(points.coordinate(j, axis).size, 0);
  }
  expect_points(points, std::vector<Vec3>(37, origin));
}

TEST(DyadicPoints, StoredThroughOwnArenaReadBackExactly) {
  const std::uint64_t seed = 0x5eed05;
  SCOPED_TRACE("seed " + std::to_string(seed));
  const std::vector<Vec3> values = random_points(seed, 300);
  DyadicPoints points(values.size());
  ASSERT_TRUE(pack_range(values, 0, values.size(), points.limbs(), points));
  expect_points(points, values);
}

TEST(DyadicPoints, KeptArenaOutlivesItsObject) {
  const std::uint64_t seed = 0x5eed06;
  SCOPED_TRACE("seed " + std::to_string(seed));
  const std::vector<Vec3> values = random_points(seed, 500);
  DyadicPoints points(values.size());
  {
    LimbArena arena;
    ASSERT_TRUE(pack_range(values, 0, values.size(), arena, points));
    points.keep_limbs(std::move(arena));
  }
  scribble_over_freed_blocks();
  expect_points(points, values);
}

TEST(DyadicPoints, OwnArenaKeepsWritingAfterKeepingAnother) {
  const std::uint64_t seed = 0x5eed07;
  SCOPED_TRACE("seed " + std::to_string(seed));
  const std::vector<Vec3> values = random_points(seed, 600);
  DyadicPoints points(values.size());
  ASSERT_TRUE(pack_range(values, 0, 200, points.limbs(), points));
  {
    LimbArena arena;
    ASSERT_TRUE(pack_range(values, 200, 400, arena, points));
    points.keep_limbs(std::move(arena));
  }
  ASSERT_TRUE(pack_range(values, 400, values.size(), points.limbs(), points));
  scribble_over_freed_blocks();
  expect_points(points, values);
}

TEST(DyadicPoints, MovedPointsKeepTheirLimbs) {
  const std::uint64_t seed = 0x5eed08;
  SCOPED_TRACE("seed " + std::to_string(seed));
  const std::vector<Vec3> values = random_points(seed, 400);
  DyadicPoints moved_to;
  {
    DyadicPoints points(values.size());
    ASSERT_TRUE(pack_range(values, 0, 200, points.limbs(), points));
    {
      LimbArena arena;
      ASSERT_TRUE(pack_range(values, 200, values.size(), arena, points));
      points.keep_limbs(std::move(arena));
    }
    DyadicPoints constructed(std::move(points));
    moved_to = std::move(constructed);
  }
  scribble_over_freed_blocks();
  expect_points(moved_to, values);
}

TEST(DyadicPoints, TwoThreadsWithOwnArenasStoreWhatOneThreadStores) {
  const std::uint64_t seed = 0x5eed09;
  SCOPED_TRACE("seed " + std::to_string(seed));
  constexpr std::size_t n = 2000;
  const std::vector<Vec3> values = random_points(seed, n);
  DyadicPoints one(n);
  ASSERT_TRUE(pack_range(values, 0, n, one.limbs(), one));

  DyadicPoints two(n);
  {
    LimbArena first, second;
    bool first_ok = false, second_ok = false;
    std::thread a([&] { first_ok = pack_range(values, 0, n / 2, first, two); });
    std::thread b([&] { second_ok = pack_range(values, n / 2, n, second, two); });
    a.join();
    b.join();
    ASSERT_TRUE(first_ok);
    ASSERT_TRUE(second_ok);
    two.keep_limbs(std::move(first));
    two.keep_limbs(std::move(second));
  }
  scribble_over_freed_blocks();
  const std::vector<Vec3> from_one = one.to_vectors(), from_two = two.to_vectors();
  ASSERT_EQ(from_two.size(), n);
  for (std::size_t j = 0; j < n; ++j) EXPECT_EQ(from_two[j], from_one[j]) << "point " << j;
  expect_points(two, values);
}

}  // namespace
}  // namespace cvms::detail
