// SPDX-License-Identifier: MIT
// Exact decimal/fraction parsing and printing. Decimal text is parsed by
// building the integer of all its digits and scaling by a power of ten, so
// "0.1" is exactly 1/10 (never the double nearest to it).
#include "cvms/rational.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "cvms/error.hpp"
#include "exact_double.hpp"

namespace cvms {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Parses an unsigned digit run into `out`; returns false if empty.
bool parse_digits(std::string_view digits, mpz_class& out) {
  if (digits.empty()) return false;
  for (char c : digits)
    if (!is_digit(c)) return false;
  // mpz_set_str needs a NUL-terminated string.
  std::string s(digits);
  return out.set_str(s, 10) == 0;
}

std::optional<Rational> parse_fraction(std::string_view text, std::size_t slash) {
  std::string_view num = text.substr(0, slash);
  std::string_view den = text.substr(slash + 1);
  bool negative = false;
  if (!num.empty() && (num[0] == '+' || num[0] == '-')) {
    negative = num[0] == '-';
    num.remove_prefix(1);
  }
  mpz_class p, q;
  if (!parse_digits(num, p) || !parse_digits(den, q) || q == 0) return std::nullopt;
  Rational r(negative ? mpz_class(-p) : p, q);
  r.canonicalize();
  return r;
}

}  // namespace

std::optional<Rational> try_parse_rational(std::string_view text, long max_exponent) {
  if (text.empty()) return std::nullopt;
  if (auto slash = text.find('/'); slash != std::string_view::npos) return parse_fraction(text, slash);

  std::size_t i = 0;
  bool negative = false;
  if (text[i] == '+' || text[i] == '-') {
    negative = text[i] == '-';
    ++i;
  }
  std::string digits;
  std::size_t int_start = i;
  while (i < text.size() && is_digit(text[i])) ++i;
  digits.append(text.substr(int_start, i - int_start));
  bool has_int = i > int_start;
  long frac_len = 0;
  bool has_frac = false;
  if (i < text.size() && text[i] == '.') {
    ++i;
    std::size_t frac_start = i;
    while (i < text.size() && is_digit(text[i])) ++i;
    frac_len = static_cast<long>(i - frac_start);
    has_frac = frac_len > 0;
    digits.append(text.substr(frac_start, i - frac_start));
  }
  if (!has_int && !has_frac) return std::nullopt;
  // The exponent is accumulated saturating at max_exponent + 1, so that no
  // digit string (and no max_exponent up to LONG_MAX) can overflow it.
  if (max_exponent < 0) max_exponent = 0;
  long exponent = 0;
  bool exponent_too_big = false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    bool exp_negative = false;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
      exp_negative = text[i] == '-';
      ++i;
    }
    std::size_t exp_start = i;
    while (i < text.size() && is_digit(text[i])) {
      long digit = text[i] - '0';
      if (exponent > max_exponent / 10 || exponent * 10 > max_exponent - digit)
        exponent_too_big = true;
      else
        exponent = exponent * 10 + digit;
      ++i;
    }
    if (i == exp_start) return std::nullopt;
    if (exp_negative) exponent = -exponent;
  }
  if (i != text.size()) return std::nullopt;
  if (exponent_too_big) return std::nullopt;

  mpz_class mantissa;
  if (!parse_digits(digits, mantissa)) return std::nullopt;
  if (negative) mantissa = -mantissa;
  // value = mantissa * 10^scale. |exponent| <= max_exponent and frac_len is
  // bounded by the text length, so this cannot overflow; a negative scale
  // costs memory proportional to the text plus max_exponent, which is the
  // bound we promise.
  if (exponent <= std::numeric_limits<long>::min() + frac_len) return std::nullopt;  // absurd max_exponent
  long scale = exponent - frac_len;
  if (mantissa == 0) return Rational(0);
  mpz_class power;
  mpz_ui_pow_ui(power.get_mpz_t(), 10, static_cast<unsigned long>(scale < 0 ? -scale : scale));
  Rational r = scale >= 0 ? Rational(mantissa * power) : Rational(mantissa, power);
  r.canonicalize();
  return r;
}

Rational parse_rational(std::string_view text) {
  if (auto r = try_parse_rational(text)) return *r;
  std::string shown(text.substr(0, 64));
  if (text.size() > 64) shown += "...";
  throw Error(ErrorCategory::parse, "not an exact number: '" + shown + "'");
}

Rational rational_from_double(double value) {
  if (!std::isfinite(value))
    throw Error(ErrorCategory::invalid_argument, "cannot convert a non-finite double to a rational");
  return Rational(value);  // mpq_set_d is exact
}

Rational rational_from_float(float value) { return rational_from_double(static_cast<double>(value)); }

std::string to_string(const Rational& value) {
  const mpz_class& den = value.get_den();
  // Strip factors 2 and 5 from the denominator; a finite decimal exists iff nothing else remains.
  mpz_class rest = den;
  unsigned long twos = mpz_remove(rest.get_mpz_t(), rest.get_mpz_t(), mpz_class(2).get_mpz_t());
  unsigned long fives = mpz_remove(rest.get_mpz_t(), rest.get_mpz_t(), mpz_class(5).get_mpz_t());
  if (rest != 1) return value.get_str();
  unsigned long places = twos > fives ? twos : fives;
  if (places == 0) return value.get_num().get_str();
  // value * 10^places is an integer: num * (10^places / den).
  mpz_class scale;
  mpz_ui_pow_ui(scale.get_mpz_t(), 10, places);
  mpz_class scaled = value.get_num() * (scale / den);
  bool negative = scaled < 0;
  if (negative) scaled = -scaled;
  std::string digits = scaled.get_str();
  if (digits.size() <= places) digits.insert(0, places + 1 - digits.size(), '0');
  digits.insert(digits.size() - places, 1, '.');
  return negative ? "-" + digits : digits;
}

double to_double_nearest(const Rational& value) {
  double truncated = value.get_d();  // rounds toward zero; infinity beyond the range
  if (std::isinf(truncated) || is_double_exact(value)) return truncated;
  // A negative value that rounds to zero is -0, as IEEE rounding gives.
  if (truncated == 0.0) truncated = std::copysign(0.0, static_cast<double>(sgn(value)));
  double away = std::nextafter(truncated, sgn(value) > 0 ? std::numeric_limits<double>::infinity()
                                                         : -std::numeric_limits<double>::infinity());
  // The candidates are truncated and away; when away is infinite the
  // midpoint is DBL_MAX + ulp(DBL_MAX)/2 = 2^1024 - 2^970, and at the tie
  // IEEE rounds to infinity (DBL_MAX's significand is odd).
  Rational upper =
      std::isinf(away) ? Rational(truncated) * 2 - Rational(std::nextafter(truncated, 0.0)) : Rational(away);
  Rational midpoint = (Rational(truncated) + upper) / 2;
  int c = cmp(abs(value), abs(midpoint));
  if (c < 0) return truncated;
  if (c > 0) return away;
  // Tie: the one whose significand is even (last bit of the encoding zero,
  // which also holds for subnormals and for the overflow case above).
  return (std::bit_cast<std::uint64_t>(truncated) & 1u) == 0 ? truncated : away;
}

bool is_double_exact(const Rational& value) { return is_double_exact_fast(value); }

}  // namespace cvms
