// SPDX-License-Identifier: MIT
// Exact parsing, printing and double conversion of rationals, against
// independent constructions (integer arithmetic, exact midpoints between
// consecutive doubles).
#include "cvms/rational.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "cvms/error.hpp"
#include "cvms/io.hpp"
#include "rational_text.hpp"
#include "support/cpu_time.hpp"
#include "support/random_numbers.hpp"

namespace cvms {
namespace {

using test::fraction;
using test::power_of_ten;
using test::power_of_two;

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

TEST(Rational, ParsesEveryForm) {
  struct Case {
    const char* text;
    Rational expected;
  };
  const Case cases[] = {
      {"0", 0},
      {"-0", 0},
      {"+0", 0},
      {"12", 12},
      {"-12", -12},
      {"+12", 12},
      {"00012", 12},
      {"0.1", fraction(1, 10)},
      {"-0.1", fraction(-1, 10)},
      {"+0.1", fraction(1, 10)},
      {".5", fraction(1, 2)},
      {"+.5", fraction(1, 2)},
      {"-.5", fraction(-1, 2)},
      {"5.", 5},
      {"-5.", -5},
      {"1e3", 1000},
      {"1E3", 1000},
      {"1e+3", 1000},
      {"1e-3", fraction(1, 1000)},
      {"-2.5E+7", -25000000},
      {".5e1", 5},
      {"5.e-1", fraction(1, 2)},
      {"0012.500", fraction(25, 2)},
      {"1e0000000000000000000000003", 1000},  // leading zeros of the exponent are fine
      {"0e5", 0},
      {"0.000e-7", 0},
      {"6/4", fraction(3, 2)},
      {"-6/4", fraction(-3, 2)},
      {"+6/4", fraction(3, 2)},
      {"0/7", 0},
      {"-0/7", 0},
      {"007/014", fraction(1, 2)},
      {"123456789012345678901234567890", Rational(mpz_class("123456789012345678901234567890"))},
      {"1/123456789012345678901234567890", fraction(1, mpz_class("123456789012345678901234567890"))},
      {"3.14159265358979323846264338327950288", fraction(mpz_class("314159265358979323846264338327950288"),
                                                         mpz_class("100000000000000000000000000000000000"))},
      {"1e-300", power_of_ten(-300)},
      {"-1.5e300", Rational(-15) * power_of_ten(299)},
      {"4.9406564584124654e-324", Rational(49406564584124654) * power_of_ten(-340)},
  };
  for (const Case& c : cases) {
    std::optional<Rational> r = try_parse_rational(c.text);
    ASSERT_TRUE(r.has_value()) << c.text;
    EXPECT_EQ(*r, c.expected) << c.text;
    EXPECT_EQ(parse_rational(c.text), c.expected) << c.text;
  }
}

TEST(Rational, ExponentLimits) {
  EXPECT_EQ(try_parse_rational("1e5", 5), Rational(100000));
  EXPECT_EQ(try_parse_rational("1e-5", 5), fraction(1, 100000));
  EXPECT_FALSE(try_parse_rational("1e6", 5).has_value());
  EXPECT_FALSE(try_parse_rational("1e-6", 5).has_value());
  EXPECT_FALSE(try_parse_rational("0e6", 5).has_value());  // the limit is on the text, whatever the value
  EXPECT_TRUE(try_parse_rational("1e100000").has_value());
  EXPECT_TRUE(try_parse_rational("1e-100000").has_value());
  EXPECT_FALSE(try_parse_rational("1e100001").has_value());
  EXPECT_FALSE(try_parse_rational("1e-100001").has_value());
  EXPECT_FALSE(try_parse_rational("1e999999999999999999999999999999").has_value());
  // No overflow even when the caller allows everything (UBSan checks this).
  EXPECT_FALSE(try_parse_rational("1e999999999999999999999999999999", LONG_MAX).has_value());
  EXPECT_FALSE(try_parse_rational("0.5e-9223372036854775807", LONG_MAX).has_value());
  EXPECT_FALSE(try_parse_rational("1e9223372036854775808", LONG_MAX).has_value());
  EXPECT_EQ(try_parse_rational("2.5e1", LONG_MAX), Rational(25));
  // A negative limit means no exponent at all.
  EXPECT_EQ(try_parse_rational("1e0", -3), Rational(1));
  EXPECT_FALSE(try_parse_rational("1e1", -3).has_value());
}

TEST(Rational, RejectsJunk) {
  for (const char* bad :
       {"",      "-",    "+",    ".",        "+.",    "-.",    "e",    "e5",  "1e",    "1e+",   "1e-",
        "1.2.3", "1..2", " 1",   "1 ",       "1,5",   "0x10",  "nan",  "NaN", "inf",   "-inf",  "1/0",
        "1/",    "/2",   "1/-2", "1/+2",     "1.5/2", "1/2/3", "--1",  "+-1", "1e5.5", "1e5e5", "1_000",
        "1e 5",  "1/ 2", "- 1",  "Infinity", "1d5",   "1f",    "1.0.", "١"})
    EXPECT_FALSE(try_parse_rational(bad).has_value()) << bad;
  EXPECT_FALSE(try_parse_rational(std::string_view("1\0", 2)).has_value());
  try {
    parse_rational("abc");
    FAIL() << "no exception";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::parse);
    EXPECT_NE(std::string(e.what()).find("abc"), std::string::npos);
  }
  try {
    parse_rational(std::string(200, '7') + "x");
    FAIL() << "no exception";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::parse);
    EXPECT_LT(std::string(e.what()).size(), 150u);  // the echoed text is shortened
  }
}

TEST(Rational, PrintsExactDecimalOrFraction) {
  struct Case {
    Rational value;
    const char* text;
  };
  const Case cases[] = {
      {0, "0"},
      {fraction(1, 10), "0.1"},
      {fraction(-5, 2), "-2.5"},
      {fraction(-1, 2), "-0.5"},
      {fraction(1, 3), "1/3"},
      {fraction(-1, 3), "-1/3"},
      {fraction(1, 6), "1/6"},
      {fraction(22, 7), "22/7"},
      {12, "12"},
      {-12, "-12"},
      {fraction(1, 1000000), "0.000001"},
      {fraction(1, 8), "0.125"},
      {fraction(1, 1024), "0.0009765625"},
      {fraction(3, 20), "0.15"},
      {fraction(7, 5), "1.4"},
      {fraction(123, 100), "1.23"},
      {fraction(-100001, 1000), "-100.001"},
      {Rational(1000000) * 1000000, "1000000000000"},
  };
  for (const Case& c : cases) EXPECT_EQ(to_string(c.value), c.text);
  // The smallest subnormal: 1074 decimal places, no exponent.
  std::string s = to_string(Rational(5e-324));
  EXPECT_EQ(s.size(), 1076u);
  EXPECT_EQ(s.substr(0, 2), "0.");
  EXPECT_EQ(s.substr(2 + 323, 10), "4940656458");
  EXPECT_EQ(parse_rational(s), Rational(5e-324));
}

// Builds the decimal text of m * 10^-places by hand (the oracle for printing).
std::string decimal_text(mpz_class m, unsigned places) {
  bool negative = m < 0;
  if (negative) m = -m;
  std::string digits = m.get_str();
  if (places > 0) {
    if (digits.size() <= places) digits.insert(0, places + 1 - digits.size(), '0');
    digits.insert(digits.size() - places, 1, '.');
  }
  return negative ? "-" + digits : digits;
}

TEST(Rational, DecimalTextRoundTrips) {
  test::Rng rng(3);
  for (int i = 0; i < 5000; ++i) {
    mpz_class m = test::random_integer(rng, 1 + static_cast<unsigned>(rng() % 120));
    unsigned places = static_cast<unsigned>(rng() % 40);
    if (places > 0 && m % 10 == 0) m += (m < 0 ? -1 : 1);  // canonical text has no trailing zero
    if (m == 0) places = 0;
    std::string text = decimal_text(m, places);
    SCOPED_TRACE(text);
    Rational q = parse_rational(text);
    ASSERT_EQ(q, Rational(m) * power_of_ten(-static_cast<long>(places)));
    ASSERT_EQ(to_string(q), text);
    // Other spellings of the same number parse to the same value.
    ASSERT_EQ(parse_rational(text + (places > 0 ? "000e0" : ".000e0")), q) << "trailing zeros";
    ASSERT_EQ(parse_rational(m.get_str() + "e-" + std::to_string(places)), q);
  }
}

TEST(Rational, AnyRationalRoundTripsThroughText) {
  test::Rng rng(4);
  for (int i = 0; i < 5000; ++i) {
    Rational q = test::random_rational(rng);
    std::string text = to_string(q);
    ASSERT_EQ(parse_rational(text), q) << text.substr(0, 100);
    // A finite decimal exactly when the denominator is 2^a 5^b.
    mpz_class den = q.get_den();
    while (den % 2 == 0) den /= 2;
    while (den % 5 == 0) den /= 5;
    ASSERT_EQ(text.find('/') == std::string::npos, den == 1) << text.substr(0, 100);
    if (text.find('.') != std::string::npos) {
      ASSERT_NE(text.back(), '0');  // shortest decimal
      ASSERT_NE(text.back(), '.');
    }
  }
}

TEST(Rational, DoubleRoundTrip) {
  for (double d : {0.1, -1e300, 5e-324, 1.0 / 3.0, 123456789.125, DBL_MAX, -DBL_MAX, DBL_MIN, -DBL_MIN,
                   DBL_MIN / 3, -5e-324, 0.0}) {
    Rational q = rational_from_double(d);
    EXPECT_EQ(to_double_nearest(q), d);
    EXPECT_TRUE(is_double_exact(q));
    EXPECT_EQ(parse_rational(to_string(q)), q);
  }
  test::Rng rng(5);
  for (int i = 0; i < 20000; ++i) {
    double d = test::random_double_bits(rng);
    Rational q = rational_from_double(d);
    ASSERT_EQ(to_double_nearest(q), d) << d;
    ASSERT_TRUE(is_double_exact(q)) << d;
    if (i % 10 == 0) {
      ASSERT_EQ(parse_rational(to_string(q)), q) << d;
    }
  }
  for (int i = 0; i < 2000; ++i) {
    float f = std::bit_cast<float>(static_cast<std::uint32_t>(rng()));
    if (!std::isfinite(f)) continue;
    Rational q = rational_from_float(f);
    ASSERT_EQ(q, Rational(static_cast<double>(f)));
    ASSERT_EQ(static_cast<float>(to_double_nearest(q)), f);
  }
}

TEST(Rational, NonFiniteDoublesAreRejected) {
  for (double d : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity()}) {
    try {
      (void)rational_from_double(d);
      FAIL() << "no exception for " << d;
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
    }
  }
  EXPECT_THROW((void)rational_from_float(std::numeric_limits<float>::infinity()), Error);
}

bool even(double d) { return (std::bit_cast<std::uint64_t>(d) & 1u) == 0; }

TEST(Rational, NearestDoubleTiesToEven) {
  test::Rng rng(6);
  const double inf = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 20000; ++i) {
    double d = test::random_double_bits(rng);
    double next = std::nextafter(d, inf);
    if (!std::isfinite(next)) continue;
    Rational lo(d), hi(next);
    Rational mid = (lo + hi) / 2;
    Rational nudge = (hi - lo) / (1 << 20);
    SCOPED_TRACE(std::to_string(i) + ": " + std::to_string(d));
    double tie = even(d) ? d : next;
    ASSERT_EQ(to_double_nearest(mid), tie);
    ASSERT_EQ(to_double_nearest(mid + nudge), next);
    ASSERT_EQ(to_double_nearest(mid - nudge), d);
    ASSERT_EQ(to_double_nearest(lo + nudge), d);
    ASSERT_EQ(to_double_nearest(hi - nudge), next);
    ASSERT_FALSE(is_double_exact(mid));
    ASSERT_FALSE(is_double_exact(lo + nudge));
  }
}

TEST(Rational, NearestDoubleAtTheEdges) {
  const double inf = std::numeric_limits<double>::infinity();
  Rational max(DBL_MAX);
  Rational half_ulp = power_of_two(970);  // ulp(DBL_MAX) = 2^971
  EXPECT_EQ(to_double_nearest(max + half_ulp - 1), DBL_MAX);
  EXPECT_EQ(to_double_nearest(max + half_ulp), inf);  // tie: DBL_MAX is odd
  EXPECT_EQ(to_double_nearest(-(max + half_ulp)), -inf);
  EXPECT_EQ(to_double_nearest(-(max + half_ulp - 1)), -DBL_MAX);
  EXPECT_EQ(to_double_nearest(power_of_two(1024)), inf);
  EXPECT_EQ(to_double_nearest(power_of_two(5000)), inf);
  // Below the smallest subnormal 2^-1074.
  EXPECT_EQ(to_double_nearest(power_of_two(-1075)), 0.0);  // tie: 0 is even
  EXPECT_EQ(to_double_nearest(power_of_two(-1075) + power_of_two(-1200)), 5e-324);
  EXPECT_EQ(to_double_nearest(power_of_two(-1076)), 0.0);
  EXPECT_TRUE(std::signbit(to_double_nearest(-power_of_two(-1076))));  // -0, as IEEE rounds
  EXPECT_EQ(to_double_nearest(power_of_two(-5000)), 0.0);
  EXPECT_EQ(to_double_nearest(power_of_two(-1075) * 3), 0x1p-1073);  // tie between 1 and 2 ulps: even
  EXPECT_EQ(to_double_nearest(Rational(1, 3)), 1.0 / 3.0);
  EXPECT_EQ(to_double_nearest(Rational(1, 10)), 0.1);
  EXPECT_EQ(to_double_nearest(parse_rational("2.2250738585072011e-308")), 2.2250738585072011e-308);
  EXPECT_EQ(to_double_nearest(power_of_two(53) + 1), 0x1p53);  // tie: 2^53 is even
  EXPECT_EQ(to_double_nearest(power_of_two(53) + 3), 0x1p53 + 4);
}

TEST(Rational, IsDoubleExact) {
  EXPECT_TRUE(is_double_exact(0));
  EXPECT_TRUE(is_double_exact(power_of_two(-1074)));
  EXPECT_TRUE(is_double_exact(-power_of_two(-1074)));
  EXPECT_TRUE(is_double_exact(power_of_two(1023)));
  EXPECT_TRUE(is_double_exact(Rational(DBL_MAX)));
  EXPECT_TRUE(is_double_exact(power_of_two(53) + 2));
  EXPECT_TRUE(is_double_exact(power_of_two(-1074) * (power_of_two(53) - 1)));
  EXPECT_FALSE(is_double_exact(power_of_two(-1075)));
  EXPECT_FALSE(is_double_exact(power_of_two(-1075) * 3));
  EXPECT_FALSE(is_double_exact(power_of_two(1024)));
  EXPECT_FALSE(is_double_exact(Rational(DBL_MAX) + power_of_two(971)));
  EXPECT_FALSE(is_double_exact(power_of_two(53) + 1));
  EXPECT_FALSE(is_double_exact(fraction(1, 3)));
  EXPECT_FALSE(is_double_exact(fraction(1, 10)));
  // Against the definition, on random rationals.
  test::Rng rng(8);
  for (int i = 0; i < 20000; ++i) {
    Rational q = test::random_rational(rng);
    bool expected = abs(q) <= Rational(DBL_MAX) && Rational(q.get_d()) == q;
    ASSERT_EQ(is_double_exact(q), expected) << to_string(q).substr(0, 80);
  }
}

// ---- parsing under size caps (lib/numeric/rational_text.hpp) ----------------

using detail::NumberTextResult;
using detail::NumberTextStatus;
using detail::parse_rational_into;

NumberTextResult capped(std::string_view text, std::uint64_t max_bits, Rational& out) {
  return parse_rational_into(text, {100000, max_bits}, out);
}

// The bit lengths of the numerator and denominator in lowest terms.
std::uint64_t num_bits(const Rational& q) { return mpz_sizeinbase(q.get_num_mpz_t(), 2); }
std::uint64_t den_bits(const Rational& q) { return mpz_sizeinbase(q.get_den_mpz_t(), 2); }

double seconds_since(double start) {
  return test::cpu_seconds() - start;
}

// "1e99999" is 7 bytes and would be a 332,000-bit integer (86,000 of them in
// a 687 KB OFF would take GBs). The cap is read
// off the text: nothing of that size is ever built.
TEST(RationalText, ExponentTokensAreRefusedBeforeTheNumberIsBuilt) {
  Rational out;
  NumberTextResult r = capped("1e99999", 4096, out);
  EXPECT_EQ(r.status, NumberTextStatus::numerator_too_large);
  EXPECT_EQ(r.bits, 332190u);  // floor(99999 log2 10) + 1
  r = capped("-5e-99999", 4096, out);
  EXPECT_EQ(r.status, NumberTextStatus::denominator_too_large);
  EXPECT_GE(r.bits, 332185u);
  EXPECT_LE(r.bits, 332190u);
  EXPECT_EQ(capped("0." + std::string(99999, '0') + "1", 4096, out).status,
            NumberTextStatus::denominator_too_large);
  // A million of them take no time: each is refused from its digit count.
  auto start = test::cpu_seconds();
  for (int i = 0; i < 1000000; ++i)
    ASSERT_NE(capped(i % 2 ? "1e99999" : "7e-99999", 4096, out).status, NumberTextStatus::ok);
  EXPECT_LT(seconds_since(start), 2.0);
}

// p/q with 500,000-digit p and q (each token just under max_number_chars)
// would take minutes to check; the digit count refuses them.
TEST(RationalText, HalfMillionDigitFractionsAreRefusedFromTheirDigitCount) {
  const std::string p(500000, '7');
  const std::string q = "1" + std::string(499999, '3');
  Rational out;
  auto start = test::cpu_seconds();
  NumberTextResult r = capped(p + "/" + q, 4096, out);
  EXPECT_EQ(r.status, NumberTextStatus::numerator_too_large);
  EXPECT_GE(r.bits, 1660961u);  // floor(499999 log2 10) + 1
  EXPECT_EQ(capped("1/" + q, 4096, out).status, NumberTextStatus::denominator_too_large);
  EXPECT_LT(seconds_since(start), 0.5);
}

// Honest input never meets the readers' default: every double, written
// shortest or exactly, has at most 1024 bits above and 1075 below.
TEST(RationalText, DoublesWrittenExactlyOrShortestPassTheReadCap) {
  const std::uint64_t cap = ReadLimits{}.max_number_bits;
  auto check = [&](double d) {
    char shortest[64];
    auto end = std::to_chars(shortest, shortest + sizeof shortest, d).ptr;
    for (const std::string& text : {std::string(shortest, end), to_string(rational_from_double(d))}) {
      Rational out;
      ASSERT_EQ(capped(text, cap, out).status, NumberTextStatus::ok) << text.substr(0, 60);
      ASSERT_EQ(out, *try_parse_rational(text)) << text.substr(0, 60);
      ASSERT_LE(num_bits(out), 2000u) << text.substr(0, 60);
      ASSERT_LE(den_bits(out), 1200u) << text.substr(0, 60);
    }
  };
  for (double d : {5e-324, -5e-324, DBL_MIN, DBL_MAX, -DBL_MAX, 1e-300, 1e300, -1.5e300, 1e308, 1e-308,
                   4.9406564584124654e-324, 2.2250738585072009e-308, 0.1, 1.0 / 3.0})
    check(d);
  Rational tiny;
  ASSERT_EQ(capped(to_string(power_of_two(-1074)), cap, tiny).status, NumberTextStatus::ok);
  EXPECT_EQ(tiny, power_of_two(-1074));  // 751 digits, 5^1074 / 10^1074 reduced
  EXPECT_EQ(den_bits(tiny), 1075u);
  test::Rng rng(18);
  for (int i = 0; i < 5000; ++i) check(test::random_double_bits(rng));
}

// The caps are on the value in lowest terms, exactly at the bit: the
// decimal's powers of 2 and 5 cancel before the denominator is sized.
TEST(RationalText, CapsAreOnTheValueInLowestTerms) {
  struct Case {
    const char* text;
    NumberTextStatus status;
  };
  const Case cases[] = {
      {"1023", NumberTextStatus::ok},  // 10 bits
      {"-1023", NumberTextStatus::ok},
      {"1024", NumberTextStatus::numerator_too_large},
      {"102.4e1", NumberTextStatus::numerator_too_large},
      {"0.001", NumberTextStatus::ok},  // 1/1000: 10 bits
      {"0.0001", NumberTextStatus::denominator_too_large},
      {"625e-4", NumberTextStatus::ok},      // 1/16
      {"0.0625", NumberTextStatus::ok},      // 1/16
      {"512e-3", NumberTextStatus::ok},      // 64/125
      {"0.5e-2", NumberTextStatus::ok},      // 1/200
      {"1000000e-6", NumberTextStatus::ok},  // 1
      {"1000000.000e-6", NumberTextStatus::ok},
      {"0.000000e-90000", NumberTextStatus::ok},  // 0
      {"1/1023", NumberTextStatus::ok},
      {"02/001023", NumberTextStatus::ok},  // leading zeros do not count
      {"1/1024", NumberTextStatus::denominator_too_large},
      {"2048/2", NumberTextStatus::numerator_too_large},  // p/q as written
      {"1/0", NumberTextStatus::not_a_number},
      {"1e100001", NumberTextStatus::exponent_too_large},  // the exponent first
      {"1.5", NumberTextStatus::ok},
      {"x", NumberTextStatus::not_a_number},
  };
  for (const Case& c : cases) {
    Rational out;
    EXPECT_EQ(capped(c.text, 10, out).status, c.status) << c.text;
    if (c.status == NumberTextStatus::ok) {
      EXPECT_EQ(out, *try_parse_rational(c.text)) << c.text;
    }
  }
}

// Parses text under cap and checks it against the exact value: refused
// exactly when a part is beyond the cap, else that value in lowest terms.
void expect_capped_parse(const std::string& text, const Rational& expected, std::uint64_t cap,
                         NumberTextResult& r) {
  Rational out = 12345;  // not zero: the parser must set both parts
  r = capped(text, cap, out);
  const bool fits = num_bits(expected) <= cap && den_bits(expected) <= cap;
  ASSERT_EQ(r.status == NumberTextStatus::ok, fits) << "cap " << cap;
  if (fits) {
    ASSERT_EQ(out, expected);
    ASSERT_EQ(gcd(out.get_num(), out.get_den()), 1);
    ASSERT_GT(out.get_den(), 0);
  }
}

// Against an independent construction: the value is that of the uncapped
// parser, in lowest terms, and it is refused exactly when a part exceeds the cap.
TEST(RationalText, AgreesWithTheExactSizesOnRandomDecimals) {
  test::Rng rng(1818);
  for (int i = 0; i < 20000; ++i) {
    mpz_class m = test::random_integer(rng, 1 + static_cast<unsigned>(rng() % 300));
    if (rng() % 4 == 0) m *= mpz_class(10) * static_cast<unsigned long>(rng() % 1000 + 1);
    const long places = static_cast<long>(rng() % 60);
    const long exponent = static_cast<long>(rng() % 1601) - 800;
    std::string digits = mpz_class(abs(m)).get_str();
    if (static_cast<long>(digits.size()) <= places)
      digits.insert(0, static_cast<std::size_t>(places) + 1 - digits.size(), '0');
    digits.insert(digits.size() - static_cast<std::size_t>(places), 1, '.');
    const std::string text = (m < 0 ? "-" : "") + digits + "e" + std::to_string(exponent);
    SCOPED_TRACE(text);
    Rational expected = Rational(m) * power_of_ten(exponent - places);
    const std::uint64_t cap = 1 + rng() % 3000;
    NumberTextResult r;
    ASSERT_NO_FATAL_FAILURE(expect_capped_parse(text, expected, cap, r));
    if (r.status != NumberTextStatus::ok) {
      const bool numerator = r.status == NumberTextStatus::numerator_too_large;
      ASSERT_TRUE(numerator || r.status == NumberTextStatus::denominator_too_large);
      // The reported size is a true lower bound of the part refused.
      ASSERT_LE(r.bits, numerator ? num_bits(expected) : den_bits(expected));
      ASSERT_GT(numerator ? num_bits(expected) : den_bits(expected), cap);
    }
  }
}

// Found by the parse_number fuzz harness (test/fuzz/regressions/parse_number/
// both_parts_over_the_cap): with both parts of p/q beyond the cap, the
// denominator's digit-count estimate shows it first and is named, a true
// lower bound; a numerator over the cap alone is always named.
TEST(RationalText, FractionWithBothPartsOverTheCapNamesEither) {
  Rational out;
  NumberTextResult r = capped("99999999999999999991/218446744073709551616", 64, out);
  EXPECT_EQ(r.status, NumberTextStatus::denominator_too_large);
  EXPECT_GT(r.bits, 64u);
  EXPECT_LE(r.bits, 68u);  // 218446744073709551616 has 68 bits
  r = capped("99999999999999999991/3", 64, out);
  EXPECT_EQ(r.status, NumberTextStatus::numerator_too_large);
  EXPECT_EQ(r.bits, 67u);
}

// The fast path (short decimals and exact expansions of doubles, built from
// machine words) against the independent construction M x 10^e, on the shapes
// it takes and the edges around it: 18/19/20 digits, leading and trailing
// zeros, a bare '.', signs, "-0", scales near its limit of 350 and caps at
// the exact size of the value.
std::string with_point(const std::string& digits, std::size_t places) {
  std::string s = digits;
  if (s.size() <= places) s.insert(0, places + 1 - s.size(), '0');
  s.insert(s.size() - places, 1, '.');
  return s;
}

TEST(RationalText, FastPathAgreesWithTheConstructionOnItsShapes) {
  test::Rng rng(1414);
  const int digit_counts[] = {1, 2, 6, 9, 17, 18, 19, 20, 21, 37, 38, 39, 40, 55, 100, 299, 300, 301, 320};
  for (int i = 0; i < 40000; ++i) {
    const int count = digit_counts[rng() % std::size(digit_counts)];
    std::string digits;
    for (int d = 0; d < count; ++d) digits += static_cast<char>('0' + rng() % 10);
    if (rng() % 3 == 0) digits.append(rng() % 5, '0');           // trailing zeros
    if (rng() % 4 == 0) digits.insert(0, rng() % 4, '0');        // leading zeros
    const std::size_t places = rng() % (digits.size() + 3);
    const long exponent = rng() % 3 == 0 ? 0 : static_cast<long>(rng() % 761) - 380;
    const bool point = rng() % 5 != 0;
    std::string text = point ? with_point(digits, places) : digits;
    if (text.size() > 2 && text.front() == '0' && text[1] == '.' && rng() % 2 == 0) text.erase(0, 1);  // ".5"
    if (rng() % 7 == 0 && text.find('.') == std::string::npos) text += '.';                        // "1."
    const long scale = exponent - (point ? static_cast<long>(places) : 0);
    if (exponent != 0 || rng() % 2 == 0) {
      text += rng() % 2 ? 'e' : 'E';
      text += std::to_string(exponent);
    }
    const bool negative = rng() % 2 == 0;
    // Characters, not literals, inserted and appended here: GCC 12 warns
    // falsely on string inserts of literals in a Release build (-Wrestrict,
    // GCC bug 105329).
    if (negative) text.insert(text.begin(), '-');
    else if (rng() % 4 == 0) text.insert(text.begin(), '+');
    SCOPED_TRACE(text);
    Rational expected = Rational(mpz_class(digits, 10)) * power_of_ten(scale);
    if (negative) expected = -expected;
    const std::uint64_t exact = std::max(num_bits(expected), den_bits(expected));
    const std::uint64_t caps[] = {detail::gmp_max_bits, 4096, exact, exact > 1 ? exact - 1 : 1, exact + 1};
    NumberTextResult r;
    ASSERT_NO_FATAL_FAILURE(expect_capped_parse(text, expected, caps[rng() % std::size(caps)], r));
  }
}

// Every digit count up to 40, the point at every place (and none), with
// leading and trailing zeros: the fast path reads its digits in runs split
// by the point, eight at a time into chunks of 19, so the point before,
// inside and after each eight-digit step and chunk boundary is covered, not
// left to chance.
TEST(RationalText, EveryDigitCountAndPointPlace) {
  test::Rng rng(4040);
  for (std::size_t count = 1; count <= 40; ++count)
    for (std::size_t places = 0; places <= count + 1; ++places)
      for (int zeros = 0; zeros < 4; ++zeros) {
        std::string digits;
        for (std::size_t d = 0; d < count; ++d) digits += static_cast<char>('0' + rng() % 10);
        digits.front() = static_cast<char>('1' + rng() % 9);  // the count is the significant digits'
        digits.back() = static_cast<char>('1' + rng() % 9);
        if ((zeros & 1) != 0) digits.append(2, '0');
        std::string text = with_point(digits, places);
        if ((zeros & 2) != 0) text.insert(text.begin(), 2, '0');
        if (places == count + 1 && (zeros & 1) == 0) text = digits;  // no point at all
        SCOPED_TRACE(text);
        const long scale = text == digits ? 0 : -static_cast<long>(places);
        const Rational expected = Rational(mpz_class(digits, 10)) * power_of_ten(scale);
        const std::optional<Rational> parsed = try_parse_rational(text);
        ASSERT_TRUE(parsed.has_value());
        ASSERT_EQ(*parsed, expected);
      }
}

// The parser reads digits eight at a time where it can: every byte that is
// not part of a number's syntax, at every place of the first or second
// eight-character window of a 24-digit number, makes the text no number;
// a point there gives the value the digits and the point's place say.
TEST(RationalText, EveryByteInsideAnEightDigitWindow) {
  const std::string digits = "123456789012345678901234";
  for (int byte = 0; byte < 256; ++byte) {
    const char c = static_cast<char>(byte);
    if ((c >= '0' && c <= '9') || c == 'e' || c == 'E' || c == '/' || c == '+' || c == '-') continue;
    for (std::size_t at = 0; at < 16; ++at) {
      std::string text = digits;
      text.insert(at + 1, 1, c);  // after at least one digit
      SCOPED_TRACE("byte " + std::to_string(byte) + " after digit " + std::to_string(at));
      const std::optional<Rational> parsed = try_parse_rational(text);
      if (c != '.') {
        EXPECT_FALSE(parsed.has_value());
        continue;
      }
      ASSERT_TRUE(parsed.has_value());
      const long places = static_cast<long>(digits.size() - at - 1);
      EXPECT_EQ(*parsed, Rational(mpz_class(digits, 10)) * power_of_ten(-places));
    }
  }
}

// The fast path cancels the fives of 10^places against the digits by exact
// division: digits m 5^j, for every j up to 140 (the limb-sized steps, the
// binary descent and their mix), with m prime to 5 or not, one limb or
// several, and the point anywhere around j; against GMP's own reduction.
TEST(RationalText, FastPathCancelsEveryPowerOfFive) {
  const mpz_class factors[] = {1,
                               3,
                               7,
                               2,
                               1024,
                               25 * 3,
                               mpz_class("18446744073709551617"),  // 2^64 + 1
                               mpz_class("340282366920938463463374607431768211507"),
                               mpz_class("98765432109876543210987654321")};
  for (const mpz_class& m : factors)
    for (unsigned j = 0; j <= 140; ++j) {
      mpz_class five_j;
      mpz_ui_pow_ui(five_j.get_mpz_t(), 5, j);
      const std::string digits = mpz_class(m * five_j).get_str();
      for (const long places : {0L, static_cast<long>(j) - 1, static_cast<long>(j), static_cast<long>(j) + 1,
                                static_cast<long>(j) + 30}) {
        if (places < 0) continue;
        const std::string text = with_point(digits, static_cast<std::size_t>(places));
        SCOPED_TRACE(text);
        const Rational expected = Rational(mpz_class(digits, 10)) * power_of_ten(-places);
        const std::optional<Rational> parsed = try_parse_rational(text);
        ASSERT_TRUE(parsed.has_value());
        ASSERT_EQ(*parsed, expected);
        ASSERT_EQ(parsed->get_den(), expected.get_den());  // in lowest terms
      }
    }
}

TEST(RationalText, FastPathReadsExactExpansionsOfDoubles) {
  test::Rng rng(1415);
  for (int i = 0; i < 20000; ++i) {
    const double d = i % 2 == 0 ? test::random_magnitude(rng, -60, 60) : test::random_double_bits(rng);
    const Rational exact(d);
    const std::string text = to_string(exact);
    SCOPED_TRACE(text.substr(0, 80));
    Rational out = 7;
    ASSERT_EQ(capped(text, detail::gmp_max_bits, out).status, NumberTextStatus::ok);
    ASSERT_EQ(out, exact);
    ASSERT_EQ(out.get_den(), exact.get_den());
  }
  for (const char* zero : {"0", "-0", "+0", "0.000", "-.0", "0e-300", "000.000e5"}) {
    Rational out = 3;
    ASSERT_EQ(capped(zero, 64, out).status, NumberTextStatus::ok) << zero;
    EXPECT_EQ(out, 0) << zero;
  }
}

// The fast printer against the general route, byte for byte: integers,
// dyadics (sums of doubles), decimals, p/q, huge and tiny, negative, zero.
TEST(RationalText, FastPrinterMatchesTheGeneralText) {
  test::Rng rng(1416);
  auto check = [](const Rational& q) {
    std::string fast = "prefix ";
    detail::append_exact_text(fast, q);
    ASSERT_EQ(fast, "prefix " + detail::exact_text_general(q)) << q.get_str().substr(0, 80);
    ASSERT_EQ(to_string(q), detail::exact_text_general(q));
  };
  for (const Rational& q : {Rational(0), Rational(1), Rational(-1), Rational(1, 2), Rational(-1, 1024),
                            Rational(1, 3), Rational(7, 10), Rational(-1, 100000), Rational(5), Rational(1, 5)})
    check(q);
  // Around the stack buffer's limits: places near 800, digits near 770.
  mpz_class five_27;
  mpz_ui_pow_ui(five_27.get_mpz_t(), 5, 27);
  for (long k = 760; k <= 840; ++k) {
    check(Rational(1) / power_of_two(k));
    check(Rational(-3) / (power_of_two(k) * Rational(five_27)));
    check(Rational(test::random_integer(rng, 2400)) / power_of_two(k));
    check(Rational(test::random_integer(rng, 64)) / (power_of_two(k) * Rational(five_27 * 5)));  // 5^28: p/q route
  }
  for (int i = 0; i < 30000; ++i) {
    Rational q;
    switch (i % 6) {
      case 0: q = Rational(test::random_double_bits(rng)); break;             // every exponent
      case 1: q = Rational(test::random_magnitude(rng, -80, 80)) +
                  Rational(test::random_magnitude(rng, -80, 80)); break;       // a sum of doubles
      case 2: q = Rational(test::random_integer(rng, 1 + static_cast<unsigned>(rng() % 3000))); break;
      case 3: q = Rational(test::random_integer(rng, 1 + static_cast<unsigned>(rng() % 200))) *
                  power_of_ten(static_cast<long>(rng() % 120) - 60) *
                  power_of_two(static_cast<long>(rng() % 200) - 100); break;  // decimals, 2^a 5^b
      case 4: q = test::random_rational(rng); break;
      default: q = Rational(test::random_integer(rng, 1 + static_cast<unsigned>(rng() % 64))) /
                   power_of_two(static_cast<long>(rng() % 2200)); break;       // up to the stack's size and beyond
    }
    q.canonicalize();
    check(q);
  }
}

// Decimals whose scaled integer is one or two machine words, at the bounds
// of those words (2^64, 10^19, 2^128): hand-checked texts, then random
// numerators of 1 to 128 bits over powers of ten against the general route.
TEST(RationalText, DecimalsOfOneOrTwoWordsPrintExactly) {
  const mpz_class two_64 = mpz_class(1) << 64;
  const mpz_class two_128 = mpz_class(1) << 128;
  const mpz_class ten_19("10000000000000000000");
  const struct {
    mpz_class numerator;
    long places;
    const char* text;
  } cases[] = {
      {two_64 - 1, 5, "184467440737095.51615"},
      {two_64, 19, "1.8446744073709551616"},
      {two_128 - 1, 38, "3.40282366920938463463374607431768211455"},
      {two_128 - 1, 0, "340282366920938463463374607431768211455"},
      {-ten_19, 3, "-10000000000000000"},
      {ten_19 - 1, 19, "0.9999999999999999999"},
      {ten_19 * ten_19, 40, "0.01"},
      {ten_19 * ten_19 + 1, 45, "0.000000100000000000000000000000000000000000001"},
      {mpz_class(-7), 20, "-0.00000000000000000007"},
  };
  for (const auto& c : cases) {
    const Rational q = Rational(c.numerator) * power_of_ten(-c.places);
    std::string text;
    detail::append_exact_text(text, q);
    EXPECT_EQ(text, c.text) << c.numerator.get_str() << " / 10^" << c.places;
  }
  const std::uint64_t seed = 5219;
  test::Rng rng(seed);
  for (int i = 0; i < 20000; ++i) {
    const auto bits = 1 + static_cast<unsigned>(rng() % 128);
    const long places = static_cast<long>(rng() % 45);
    Rational q = Rational(test::random_integer(rng, bits)) * power_of_ten(-places);
    q.canonicalize();
    std::string text;
    detail::append_exact_text(text, q);
    ASSERT_EQ(text, detail::exact_text_general(q)) << "seed " << seed << ", case " << i;
  }
}

}  // namespace
}  // namespace cvms
