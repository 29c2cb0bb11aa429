// SPDX-License-Identifier: MIT
// The running error bounds of lib/numeric/filtered_arithmetic.hpp, checked exactly:
// after every operation |value - exact| <= error, including underflow into
// and below the subnormal range and values near overflow.
#include "filtered_arithmetic.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

#include "support/random_numbers.hpp"

namespace cvms {
namespace {

struct Tracked {
  Approx approx;
  Rational exact;
};

// "" when the invariant holds or the approximation is non-finite (unknown).
std::string violation(const Tracked& t, const char* what) {
  if (!std::isfinite(t.approx.value) || !std::isfinite(t.approx.error)) {
    if (filtered::certain(t.approx)) return std::string(what) + ": non-finite but certain";
    return "";
  }
  if (abs(Rational(t.approx.value) - t.exact) > Rational(t.approx.error))
    return std::string(what) + ": bound violated, value " + std::to_string(t.approx.value);
  if (filtered::certain(t.approx) && sgn(t.exact) != (t.approx.value > 0 ? 1 : -1))
    return std::string(what) + ": certain but wrong sign";
  return "";
}

Tracked leaf(test::Rng& rng, int kind) {
  Rational q;
  switch (kind) {
    case 0:
      q = test::random_rational(rng);
      break;
    case 1:
      q = Rational(test::random_magnitude(rng, -600, -480));
      break;  // products underflow
    case 2:
      q = Rational(test::random_magnitude(rng, 480, 520));
      break;  // products overflow
    case 3:
      q = Rational(test::random_magnitude(rng, -1074, -1000));
      break;  // subnormal-ish
    default:
      q = Rational(test::random_uniform(rng, -1, 1));
      break;
  }
  Approx a = Approx::of(q);
  // Sometimes widen the bound (still valid) so the Approx overloads run on doubles too.
  if (rng() % 3 == 0) a.error = a.error * 2 + 0x1p-1070;
  return {a, q};
}

TEST(FilteredArithmetic, RandomExpressionTreesKeepTheBound) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    test::Rng rng(seed);
    for (int round = 0; round < 300; ++round) {
      int kind = static_cast<int>(rng() % 5);
      std::vector<Tracked> pool;
      for (int i = 0; i < 6; ++i) pool.push_back(leaf(rng, kind));
      for (int step = 0; step < 25; ++step) {
        const Tracked& a = pool[rng() % pool.size()];
        const Tracked& b = pool[rng() % pool.size()];
        bool exact_leaves = a.approx.error == 0 && b.approx.error == 0;
        Tracked c;
        const char* what = "";
        switch (rng() % 3) {
          case 0:
            c = {exact_leaves && rng() % 2 ? filtered::add(a.approx.value, b.approx.value)
                                           : filtered::add(a.approx, b.approx),
                 a.exact + b.exact};
            what = "add";
            break;
          case 1:
            c = {exact_leaves && rng() % 2 ? filtered::sub(a.approx.value, b.approx.value)
                                           : filtered::sub(a.approx, b.approx),
                 a.exact - b.exact};
            what = "sub";
            break;
          default:
            if (exact_leaves && rng() % 2) {
              c = {filtered::mul(a.approx.value, b.approx.value), a.exact * b.exact};
            } else if (b.approx.error == 0 && rng() % 2) {
              c = {filtered::mul(a.approx, b.approx.value), a.exact * b.exact};
            } else {
              c = {filtered::mul(a.approx, b.approx), a.exact * b.exact};
            }
            what = "mul";
        }
        ASSERT_EQ(violation(c, what), "") << "round " << round << " step " << step;
        // Keep the exact values from growing without bound.
        if (mpz_sizeinbase(c.exact.get_num_mpz_t(), 2) + mpz_sizeinbase(c.exact.get_den_mpz_t(), 2) < 8000)
          pool.push_back(c);
      }
    }
  }
}

TEST(FilteredArithmetic, UnderflowIsCovered) {
  // 2^-600 * 2^-600 underflows to 0: the bound must still cover 2^-1200.
  Approx a{0x1p-600, 0.0};
  Approx p = filtered::mul(a, a);
  EXPECT_EQ(p.value, 0.0);
  EXPECT_GE(p.error, 0x1p-1074);
  EXPECT_FALSE(filtered::certain(p));
  // A product landing between subnormals is rounded.
  Approx q = filtered::mul(0x1.8p-537, 0x1.8p-538);
  EXPECT_LE(abs(Rational(q.value) - Rational(0x1.8p-537) * Rational(0x1.8p-538)), Rational(q.error));
  EXPECT_FALSE(filtered::certain(q));
}

TEST(FilteredArithmetic, OverflowIsNeverCertain) {
  Approx big{DBL_MAX, 0.0};
  EXPECT_FALSE(filtered::certain(filtered::mul(big, big)));
  EXPECT_FALSE(filtered::certain(filtered::add(big, big)));
  Approx inf_input{INFINITY, INFINITY};
  EXPECT_FALSE(filtered::certain(filtered::mul(inf_input, Approx{0.0, 0.0})));
  EXPECT_FALSE(filtered::certain(filtered::sub(filtered::mul(big, big), filtered::mul(big, big))));
  Approx nan_input{NAN, 0.0};
  EXPECT_FALSE(filtered::certain(filtered::add(nan_input, Approx{1.0, 0.0})));
}

TEST(FilteredArithmetic, ExactCancellationIsNotCertain) {
  // 0.1 + 0.2 - 0.3 with exact inputs 1/10, 2/10, 3/10: the exact value is 0.
  Approx a = Approx::of(Rational(1, 10)), b = Approx::of(Rational(1, 5)), c = Approx::of(Rational(3, 10));
  Approx r = filtered::sub(filtered::add(a, b), c);
  EXPECT_FALSE(filtered::certain(r));
  EXPECT_LE(abs(Rational(r.value)), Rational(r.error));
  // Well-separated values are certain.
  EXPECT_TRUE(filtered::certain(filtered::sub(Approx{1.0, 0.0}, Approx{0.5, 0.0})));
}

}  // namespace
}  // namespace cvms
