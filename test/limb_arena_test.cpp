// SPDX-License-Identifier: MIT
// LimbArena (lib/numeric/limb_arena.hpp): a stored value equals the original
// (compared with independent copies made before storing), reads and copies
// of it behave like any rational, it stays valid while the arena (or one
// that absorbed it) lives, and destroying values and arenas in either order
// frees everything once (ASan and valgrind check the last two). The
// polyhedra that keep their values in arenas: arena_storage_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "limb_arena.hpp"

namespace cvms::detail {
namespace {

Rational random_value(std::mt19937_64& rng) {
  switch (rng() % 6) {
    case 0:
      return 0;
    case 1:
      return rng() % 2 == 0 ? 1 : -1;
    case 2:  // a double of any exponent, subnormals included
      return Rational(std::ldexp(static_cast<double>(rng() >> 11) * (rng() % 2 == 0 ? 1 : -1),
                                 static_cast<int>(rng() % 2000) - 1100));
    case 3: {  // several limbs over several limbs
      mpz_class num, den;
      mpz_ui_pow_ui(num.get_mpz_t(), 3 + rng() % 5, 40 + rng() % 200);
      mpz_ui_pow_ui(den.get_mpz_t(), 7, 1 + rng() % 120);
      Rational q(rng() % 2 == 0 ? num : mpz_class(-num), den);
      q.canonicalize();
      return q;
    }
    case 4: {  // a power-of-two denominator beyond one limb
      Rational q(mpz_class(static_cast<unsigned long>(rng() | 1)));
      mpz_mul_2exp(q.get_den_mpz_t(), q.get_den_mpz_t(), 64 + rng() % 100);
      return q;
    }
    default:
      return Rational(static_cast<long>(rng() % 2000001) - 1000000, 1 + static_cast<long>(rng() % 999));
  }
}

std::vector<Rational> random_values(std::uint64_t seed, std::size_t n) {
  std::mt19937_64 rng(seed);
  std::vector<Rational> values;
  for (std::size_t i = 0; i < n; ++i) {
    values.push_back(random_value(rng));
    values.back().canonicalize();
  }
  return values;
}

TEST(LimbArena, StoredValuesEqualTheOriginalsAndBehaveAsRationals) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const std::vector<Rational> originals = random_values(seed, 3000);
    LimbArena arena;
    std::vector<Rational> stored(originals.size());
    for (std::size_t i = 0; i < originals.size(); ++i) arena.store(stored[i], originals[i]);
    for (std::size_t i = 0; i < originals.size(); ++i) {
      ASSERT_EQ(stored[i], originals[i]) << i;
      ASSERT_EQ(to_string(stored[i]), to_string(originals[i])) << i;
      ASSERT_EQ(sgn(stored[i]), sgn(originals[i]));
      Rational copy = stored[i];  // owns its limbs
      copy += 1;
      ASSERT_EQ(copy, originals[i] + 1);
      ASSERT_EQ(stored[i] * 3 - stored[i], 2 * originals[i]);  // read as an operand, unchanged
    }
    if (LimbArena::holds_limbs()) {
      EXPECT_GT(arena.capacity_bytes(), 0u);
    } else {
      EXPECT_EQ(arena.capacity_bytes(), 0u);
    }
  }
}

// Past 1 MiB the arena's blocks are 2 MiB, on huge pages where the build
// maps large blocks (huge_page_blocks.hpp): more than 5 MiB of limbs, every
// value read back against its original.
TEST(LimbArena, LargeArenasKeepEveryValue) {
  if (!LimbArena::holds_limbs()) GTEST_SKIP() << "values own their limbs with this GMP";
  const mpz_class base = (mpz_class(1) << 1000) + 12345;  // 16 limbs
  constexpr std::size_t count = 45000;                    // 45,000 * 16 * 8 bytes = 5.8 MB
  LimbArena arena;
  std::vector<Rational> stored(count);
  for (std::size_t i = 0; i < count; ++i) arena.store(stored[i], Rational(base + i));
  EXPECT_GE(arena.capacity_bytes(), count * 16 * sizeof(mp_limb_t));
  for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(stored[i], Rational(base + i)) << i;
}

// Integers stored from their limbs: 0, 1 and -1 (views of constants), one
// and two limbs of either sign, over values that held fractions before;
// against the same integers made by GMP, as views when the arena holds limbs.
TEST(LimbArena, StoresIntegersFromTheirLimbs) {
  LimbArena arena;
  struct Case {
    std::uint64_t low, high;
    bool negative;
  };
  const Case cases[] = {{0, 0, false}, {0, 0, true}, {1, 0, false},  {1, 0, true}, {2, 0, true},
                        {~0ull, 0, false}, {0, 1, true}, {12345, ~0ull >> 3, false}, {~0ull, ~0ull >> 3, true}};
  std::vector<Rational> stored(std::size(cases), Rational(-7, 3));
  for (std::size_t i = 0; i < std::size(cases); ++i) {
    const Case& c = cases[i];
    arena.store_integer(stored[i], c.low, c.high, c.negative);
    mpz_class expected = (mpz_class(std::to_string(c.high)) << 64) + mpz_class(std::to_string(c.low));
    if (c.negative) expected = -expected;
    EXPECT_EQ(stored[i], Rational(expected)) << i;
    EXPECT_EQ(stored[i].get_den(), 1) << i;
    if (LimbArena::holds_limbs()) {
      EXPECT_EQ(mpq_numref(stored[i].get_mpq_t())->_mp_alloc, 0) << i;
    }
    const Rational copy = stored[i];  // a copy owns its limbs and keeps the value
    EXPECT_EQ(copy, Rational(expected)) << i;
  }
}

// Negating stored values and values that own their limbs: 0, +-1, one and
// several limbs, fractions; twice gives the value back, and a view stays a
// view over the same limbs.
TEST(LimbArena, NegatesStoredAndOwnValuesInPlace) {
  LimbArena arena;
  mpz_class big;
  mpz_ui_pow_ui(big.get_mpz_t(), 3, 200);
  const Rational values[] = {Rational(0), Rational(1), Rational(-1), Rational(7, 3), Rational(-5),
                             Rational(big, 7), Rational(-big)};
  for (const Rational& value : values) {
    Rational stored;
    arena.store(stored, value);
    const mp_limb_t* limbs = mpz_limbs_read(mpq_numref(stored.get_mpq_t()));
    arena.negate_stored(stored);
    EXPECT_EQ(stored, -value) << to_string(value);
    if (LimbArena::holds_limbs()) {
      EXPECT_EQ(mpq_numref(stored.get_mpq_t())->_mp_alloc, 0) << to_string(value);
      if (sgn(value) != 0) {
        EXPECT_EQ(mpz_limbs_read(mpq_numref(stored.get_mpq_t())), limbs) << to_string(value);
      }
    }
    arena.negate_stored(stored);
    EXPECT_EQ(stored, value) << to_string(value);
    Rational own = value;  // owns its limbs
    arena.negate_stored(own);
    EXPECT_EQ(own, -value) << to_string(value);
    if (sgn(value) != 0) {
      EXPECT_NE(mpq_numref(own.get_mpq_t())->_mp_alloc, 0) << to_string(value);
    }
  }
}

TEST(LimbArena, ValuesStayValidInAnArenaThatAbsorbedTheirs) {
  const std::vector<Rational> originals = random_values(99, 5000);
  LimbArena kept;
  std::vector<Rational> stored(originals.size());
  {
    LimbArena first, second;
    for (std::size_t i = 0; i < originals.size(); ++i) (i % 2 == 0 ? first : second).store(stored[i], originals[i]);
    kept.absorb(std::move(first));
    kept.absorb(std::move(second));
    EXPECT_EQ(first.capacity_bytes(), 0u);  // NOLINT(bugprone-use-after-move): absorb empties it
  }
  for (std::size_t i = 0; i < originals.size(); ++i) ASSERT_EQ(stored[i], originals[i]) << i;
  LimbArena moved = std::move(kept);
  for (std::size_t i = 0; i < originals.size(); ++i) ASSERT_EQ(stored[i], originals[i]) << i;
  // The moved-from arena is empty and stores into blocks of its own, which
  // overwrite none of the values above.
  EXPECT_EQ(kept.capacity_bytes(), 0u);  // NOLINT(bugprone-use-after-move)
  std::vector<Rational> more(originals.size());
  for (std::size_t i = 0; i < originals.size(); ++i) kept.store(more[i], -originals[i]);
  for (std::size_t i = 0; i < originals.size(); ++i) {
    ASSERT_EQ(stored[i], originals[i]) << i;
    ASSERT_EQ(more[i], -originals[i]) << i;
  }
}

TEST(LimbArena, ValuesMayDieAfterTheirArena) {
  // Destroying a stored value never touches the arena's limbs, so this
  // order is fine too (the polyhedra destroy their values first anyway).
  std::vector<Rational> stored(100);
  {
    LimbArena arena;
    const std::vector<Rational> originals = random_values(7, stored.size());
    for (std::size_t i = 0; i < stored.size(); ++i) arena.store(stored[i], originals[i]);
  }
  stored.clear();
  SUCCEED();
}

TEST(LimbArena, StoresVectorsAndReusesScratch) {
  LimbArena arena;
  const Vec3 a{Rational(1, 3), Rational(-5, 1), Rational(0.125)};
  Vec3 scratch = a;
  Vec3 out;
  arena.store(out, scratch);
  scratch.x = 7;  // the stored copy does not follow its source
  EXPECT_EQ(out, a);
  arena.store(out, scratch);  // storing again into a stored value is allowed
  EXPECT_EQ(out, (Vec3{7, -5, Rational(0.125)}));
}

// A fraction stored from its two integers equals the rational GMP makes of
// them; a denominator of more than one limb lives in the arena too (a view,
// owning nothing), a one-limb one in the value's own limb. Every value is
// stored into the same `out` objects twice, so that a view denominator is
// also overwritten by a one-limb one and the other way round.
TEST(LimbArena, StoresFractionsFromTheirIntegers) {
  const std::vector<Rational> originals = random_values(31, 4000);
  LimbArena arena;
  std::vector<Rational> stored(originals.size());
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t i = 0; i < originals.size(); ++i) {
      const Rational& q = originals[(i + static_cast<std::size_t>(pass) * 7) % originals.size()];
      arena.store(stored[i], q.get_num_mpz_t(), q.get_den_mpz_t());
    }
    for (std::size_t i = 0; i < originals.size(); ++i) {
      const Rational& q = originals[(i + static_cast<std::size_t>(pass) * 7) % originals.size()];
      ASSERT_EQ(stored[i], q) << pass << " " << i;
      ASSERT_EQ(to_string(stored[i] + 1), to_string(q + 1)) << pass << " " << i;
      if (!LimbArena::holds_limbs()) continue;
      const bool long_denominator = mpz_size(q.get_den_mpz_t()) > 1;
      ASSERT_EQ(mpq_denref(stored[i].get_mpq_t())->_mp_alloc == 0, long_denominator) << pass << " " << i;
    }
  }
}

// The edges of store(numerator, denominator): a one-limb numerator over a
// long power of two, a negative numerator over a denominator just past one
// limb, -1 and 0 over 1; into a value whose own denominator owns several
// limbs, and into one whose denominator is already a view.
TEST(LimbArena, StoresFractionsIntoEveryKindOfValue) {
  const mpz_class two_200 = mpz_class(1) << 200, past_one_limb = (mpz_class(1) << 64) + 1;
  const mpz_class one = 1, minus_one = -1, zero = 0;
  const std::pair<const mpz_class*, const mpz_class*> fractions[] = {{&one, &two_200},
                                                                     {&minus_one, &past_one_limb},
                                                                     {&minus_one, &one},
                                                                     {&zero, &one},
                                                                     {&two_200, &past_one_limb}};
  LimbArena arena;
  for (const auto& [num, den] : fractions) {
    const Rational expected(*num, *den);
    Rational owning(mpz_class(5), (mpz_class(1) << 300) + 7);  // its denominator owns five limbs
    ASSERT_GE(mpq_denref(owning.get_mpq_t())->_mp_alloc, 2);
    arena.store(owning, num->get_mpz_t(), den->get_mpz_t());
    EXPECT_EQ(owning, expected) << to_string(expected);
    Rational viewed;
    arena.store(viewed, mpz_class(3).get_mpz_t(), two_200.get_mpz_t());  // a view denominator first
    arena.store(viewed, num->get_mpz_t(), den->get_mpz_t());
    EXPECT_EQ(viewed, expected) << to_string(expected);
    EXPECT_EQ(to_string(viewed * 2), to_string(expected * 2));
  }
}

// A rational whose denominator limb was given back (what the threaded
// output build does for its planes) holds every kind of value stored into
// it, a power-of-two denominator as a view (no heap block of its own), any
// other as GMP allocates it; reads, copies and storing again behave as for
// any value, and destroying it frees once (ASan, valgrind).
TEST(LimbArena, GivenBackDenominatorsHoldEveryValue) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const std::vector<Rational> originals = random_values(seed, 2000);
    LimbArena arena;
    std::vector<Rational> stored;
    stored.reserve(originals.size());
    for (std::size_t i = 0; i < originals.size(); ++i) {
      Rational& fresh = stored.emplace_back();
      LimbArena::give_back_denominator(fresh);
      ASSERT_EQ(fresh, 0);
      if (i % 4 == 1) arena.store(fresh, Rational(1, 3));  // a denominator GMP allocates first
      if (i % 4 == 2) arena.store_integer(fresh, 7, 0, true);
      if (i % 4 == 3) {
        arena.store(fresh, mpq_numref(originals[i].get_mpq_t()), mpq_denref(originals[i].get_mpq_t()));
      } else {
        arena.store(fresh, originals[i]);
      }
    }
    for (std::size_t i = 0; i < originals.size(); ++i) {
      ASSERT_EQ(stored[i], originals[i]) << i;
      ASSERT_EQ(to_string(stored[i]), to_string(originals[i])) << i;
      Rational copy = stored[i];
      copy -= 1;
      ASSERT_EQ(copy, originals[i] - 1) << i;
      const mpz_srcptr den = mpq_denref(stored[i].get_mpq_t());
      const bool power_of_two_below_2_64 = mpz_size(den) == 1 && mpz_popcount(den) == 1;
      if (LimbArena::holds_limbs() && power_of_two_below_2_64 && i % 4 != 1) {
        // A view of the constant table: every 2^k is the same limb.
        ASSERT_EQ(den->_mp_alloc, 0) << i;
        Rational same_power;
        LimbArena::give_back_denominator(same_power);
        arena.store(same_power, Rational(mpz_class(1), mpz_class(den)));
        ASSERT_EQ(mpq_denref(same_power.get_mpq_t())->_mp_d, den->_mp_d) << i;
      }
    }
    // Dyadic values stored again, over whatever each denominator is now.
    for (std::size_t i = 0; i < stored.size(); ++i) {
      const std::uint64_t magnitude = 2 * i + 1;
      arena.store_dyadic(stored[i], &magnitude, 1, i % 2 == 0, i % 70);
      ASSERT_EQ(stored[i],
                Rational(mpz_class(i % 2 == 0 ? -static_cast<long>(magnitude) : static_cast<long>(magnitude)),
                         mpz_class(1) << static_cast<unsigned>(i % 70)))
          << i;
    }
  }
}

// Integers stored as views: equal to the originals, unaffected by later
// changes of their source, and copies of them own their limbs.
TEST(LimbArena, StoresIntegers) {
  std::mt19937_64 rng(77);
  LimbArena arena;
  std::vector<mpz_class> originals, stored(3000);
  mpz_class source;
  for (std::size_t i = 0; i < stored.size(); ++i) {
    source = mpz_class(static_cast<unsigned long>(rng())) << static_cast<unsigned>(rng() % 700);
    if (i % 3 == 0) source = -source;
    if (i % 11 == 0) source = i % 2 == 0 ? 0 : 1;
    originals.push_back(source);
    arena.store(stored[i], source.get_mpz_t());
  }
  source = 12345;
  arena.store(stored[0], source.get_mpz_t());  // storing again into a stored integer
  originals[0] = 12345;
  for (std::size_t i = 0; i < stored.size(); ++i) {
    ASSERT_EQ(stored[i], originals[i]) << i;
    mpz_class copy = stored[i];
    copy += 1;
    ASSERT_EQ(copy, originals[i] + 1) << i;
    if (LimbArena::holds_limbs()) {
      ASSERT_EQ(stored[i].get_mpz_t()->_mp_alloc, 0) << i;
    }
  }
}

}  // namespace
}  // namespace cvms::detail
