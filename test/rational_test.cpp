// SPDX-License-Identifier: MIT
#include "cvms/rational.hpp"

#include <gtest/gtest.h>

#include "cvms/error.hpp"

namespace cvms {
namespace {

TEST(Rational, DecimalIsExact) {
  EXPECT_EQ(parse_rational("0.1"), Rational(1, 10));
  EXPECT_EQ(parse_rational("-2.5E+7"), Rational(-25000000));
  EXPECT_EQ(parse_rational(".5"), Rational(1, 2));
  EXPECT_EQ(parse_rational("5."), Rational(5));
  EXPECT_EQ(parse_rational("6/4"), Rational(3, 2));
  Rational tiny = parse_rational("1e-300");
  mpz_class den;
  mpz_ui_pow_ui(den.get_mpz_t(), 10, 300);
  EXPECT_EQ(tiny, Rational(mpz_class(1), den));
}

TEST(Rational, RejectsJunk) {
  for (const char* bad : {"", "-", ".", "e5", "1e", "1/0", "nan", "inf", "1.2.3", "1 ", "0x10", "1e999999999"})
    EXPECT_FALSE(try_parse_rational(bad).has_value()) << bad;
  EXPECT_THROW(parse_rational("abc"), Error);
}

TEST(Rational, PrintsExactDecimalOrFraction) {
  EXPECT_EQ(to_string(Rational(1, 10)), "0.1");
  EXPECT_EQ(to_string(Rational(-5, 2)), "-2.5");
  EXPECT_EQ(to_string(Rational(1, 3)), "1/3");
  EXPECT_EQ(to_string(Rational(12)), "12");
  EXPECT_EQ(to_string(Rational(1, 1000000)), "0.000001");
}

TEST(Rational, DoubleRoundTrip) {
  for (double d : {0.1, -1e300, 5e-324, 1.0 / 3.0, 123456789.125}) {
    Rational q = rational_from_double(d);
    EXPECT_EQ(to_double_nearest(q), d);
    EXPECT_EQ(parse_rational(to_string(q)), q);
  }
}

}  // namespace
}  // namespace cvms
