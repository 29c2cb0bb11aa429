// SPDX-License-Identifier: MIT
// scale_to_common_denominator (lib/numeric/common_denominator.hpp) against
// its definition: L is the lcm of the denominators (computed here by the
// textbook gcd formula) and out[i] / L == values[i], exactly, for dyadic
// values (the shift path), non-dyadic ones and mixtures (the lcm path).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "common_denominator.hpp"

namespace cvms::detail {
namespace {

mpz_class lcm_by_gcd(const std::vector<Rational>& values) {
  mpz_class l = 1;
  for (const Rational& v : values) {
    const mpz_class g = gcd(l, v.get_den());
    l = l / g * v.get_den();
  }
  return l;
}

Rational random_value(std::mt19937_64& rng, int kind) {
  const long v = static_cast<long>(rng() % 20001) - 10000;
  switch (kind) {
    case 0:  // doubles of any exponent, subnormals included: powers of two
      return Rational(std::ldexp(static_cast<double>(v) / 3.0, 60 - static_cast<int>(rng() % 1130)));
    case 1: {  // small odd denominators
      Rational q(v, 1 + static_cast<long>(rng() % 999));
      q.canonicalize();
      return q;
    }
    default:  // one in four non-dyadic among doubles
      return rng() % 4 == 0 ? random_value(rng, 1) : random_value(rng, 0);
  }
}

// Odd trials write into integers kept from trial to trial (the overload
// that reuses their limbs, as the half-space dual does row after row), with
// leftovers of every kind of value before them.
TEST(CommonDenominator, IsTheLcmAndScalesExactly) {
  std::mt19937_64 rng(1492);
  std::vector<mpz_class> reused_out(12);
  mpz_class reused_lcm;
  for (int trial = 0; trial < 3000; ++trial) {
    const int kind = static_cast<int>(rng() % 3);
    const std::size_t count = 1 + rng() % 12;
    std::vector<Rational> values;
    for (std::size_t i = 0; i < count; ++i) values.push_back(random_value(rng, kind));
    std::vector<const Rational*> ptrs;
    for (const Rational& v : values) ptrs.push_back(&v);
    std::vector<mpz_class> fresh_out(count);
    const bool reuse = trial % 2 == 1;
    std::vector<mpz_class>& out = reuse ? reused_out : fresh_out;
    if (reuse) {
      scale_to_common_denominator(ptrs.data(), count, out.data(), reused_lcm);
    } else {
      reused_lcm = scale_to_common_denominator(ptrs.data(), count, out.data());
    }
    const mpz_class l = reused_lcm;
    SCOPED_TRACE("seed 1492, trial " + std::to_string(trial) + ", kind " + std::to_string(kind));
    ASSERT_EQ(l, lcm_by_gcd(values));
    for (std::size_t i = 0; i < count; ++i) {
      Rational back(out[i], l);
      back.canonicalize();  // the two-argument constructor does not
      ASSERT_EQ(back, values[i]) << "value " << i;
    }
  }
}

TEST(CommonDenominator, ZeroAndIntegersNeedNoScale) {
  const Rational zero = 0;
  const Rational seven = -7;
  const Rational* values[2] = {&zero, &seven};
  mpz_class out[2];
  EXPECT_EQ(scale_to_common_denominator(values, 2, out), 1);
  EXPECT_EQ(out[0], 0);
  EXPECT_EQ(out[1], -7);
}

}  // namespace
}  // namespace cvms::detail
