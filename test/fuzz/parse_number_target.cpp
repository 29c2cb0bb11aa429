// SPDX-License-Identifier: MIT
// The number-parser harness body (see parse_number_target.hpp): the parser
// against an independent reading of the same text. The reference checks the
// syntax with a separate grammar walk, and builds the value the slow,
// obvious way (all digits as one integer times a power of ten, then GMP's
// canonicalize), never with the parser's early bit estimates or its
// cancellation of twos and fives.
#include "parse_number_target.hpp"

#include <string>
#include <string_view>

#include "cvms/error.hpp"
#include "cvms/rational.hpp"
#include "rational_text.hpp"
#include "support/fuzz_targets.hpp"

namespace cvms::fuzz {
namespace {

using detail::NumberTextLimits;
using detail::NumberTextResult;
using detail::NumberTextStatus;

[[noreturn]] void finding(const std::string& what, std::string_view text) {
  std::string shown(text.substr(0, 80));
  if (text.size() > 80) shown += "...";
  throw FuzzFinding(what + " for '" + shown + "'");
}

bool digit(char c) { return c >= '0' && c <= '9'; }

std::string_view without_leading_zeros(std::string_view digits) {
  while (!digits.empty() && digits.front() == '0') digits.remove_prefix(1);
  return digits;
}

// The text as the grammar of try_parse_rational reads it:
//   [+-] digits '/' digits                       (a fraction, q != 0)
//   [+-] (digits ['.' [digits]] | '.' digits) [(e|E) [+-] digits]
struct Reading {
  bool valid = false;
  bool fraction = false;
  bool negative = false;
  std::string_view numerator, denominator;     // fraction, as written
  std::string_view integer_part, fraction_part;  // decimal
  bool exponent_negative = false;
  std::string_view exponent;  // decimal, without its sign
};

std::string_view take_digits(std::string_view& rest) {
  std::size_t n = 0;
  while (n < rest.size() && digit(rest[n])) ++n;
  std::string_view out = rest.substr(0, n);
  rest.remove_prefix(n);
  return out;
}

Reading read(std::string_view text) {
  Reading r;
  std::string_view rest = text;
  if (!rest.empty() && (rest[0] == '+' || rest[0] == '-')) {
    r.negative = rest[0] == '-';
    rest.remove_prefix(1);
  }
  if (text.find('/') != std::string_view::npos) {
    r.fraction = true;
    r.numerator = take_digits(rest);
    if (r.numerator.empty() || rest.empty() || rest[0] != '/') return r;
    rest.remove_prefix(1);
    r.denominator = take_digits(rest);
    r.valid = !r.denominator.empty() && rest.empty() && !without_leading_zeros(r.denominator).empty();
    return r;
  }
  r.integer_part = take_digits(rest);
  if (!rest.empty() && rest[0] == '.') {
    rest.remove_prefix(1);
    r.fraction_part = take_digits(rest);
  }
  if (r.integer_part.empty() && r.fraction_part.empty()) return r;
  if (!rest.empty() && (rest[0] == 'e' || rest[0] == 'E')) {
    rest.remove_prefix(1);
    if (!rest.empty() && (rest[0] == '+' || rest[0] == '-')) {
      r.exponent_negative = rest[0] == '-';
      rest.remove_prefix(1);
    }
    r.exponent = take_digits(rest);
    if (r.exponent.empty()) return r;
  }
  r.valid = rest.empty();
  return r;
}

// |exponent| saturated at 10^9 (beyond every cap).
long exponent_magnitude(std::string_view exponent) {
  exponent = without_leading_zeros(exponent);
  if (exponent.size() > 9) return 1000000000L;
  long e = 0;
  for (char c : exponent) e = e * 10 + (c - '0');
  return e;
}

std::uint64_t bits(const mpz_class& z) { return z == 0 ? 0 : mpz_sizeinbase(z.get_mpz_t(), 2); }

mpz_class integer_of(std::string_view digits) {
  digits = without_leading_zeros(digits);
  if (digits.empty()) return 0;
  return mpz_class(std::string(digits), 10);
}

// The value of a valid decimal the slow way, if |scale| <= 20,000.
bool reference_decimal(const Reading& r, Rational& out) {
  const long e = exponent_magnitude(r.exponent);
  const long scale = (r.exponent_negative ? -e : e) - static_cast<long>(r.fraction_part.size());
  if (scale > 20000 || scale < -20000) return false;
  mpz_class m = integer_of(std::string(r.integer_part) + std::string(r.fraction_part));
  mpz_class power;
  mpz_ui_pow_ui(power.get_mpz_t(), 10, static_cast<unsigned long>(scale < 0 ? -scale : scale));
  if (scale >= 0) {
    out = Rational(m * power);
  } else {
    out = Rational(m, power);
    out.canonicalize();
  }
  if (r.negative) out = -out;
  return true;
}

void check_refusal(const NumberTextResult& got, const NumberTextLimits& limits, std::uint64_t true_bits,
                   std::string_view text) {
  if (got.bits <= limits.max_bits) finding("a refusal reports " + std::to_string(got.bits) + " bits, within the cap", text);
  if (true_bits != 0 && got.bits > true_bits)
    finding("a refusal reports " + std::to_string(got.bits) + " bits, more than the " + std::to_string(true_bits) +
                " the value has",
            text);
}

void check_accepted(const Rational& value, const NumberTextLimits& limits, std::string_view text) {
  Rational copy = value;
  copy.canonicalize();
  if (copy != value || copy.get_num() != value.get_num() || copy.get_den() != value.get_den())
    finding("an accepted value is not in lowest terms", text);
  if (bits(value.get_num()) > limits.max_bits || bits(value.get_den()) > limits.max_bits)
    finding("an accepted value breaks the bit cap", text);
  // Printed and read back (without caps: to_string never writes an exponent).
  const std::string printed = to_string(value);
  Rational again;
  const NumberTextResult back = detail::parse_rational_into(printed, {0, detail::gmp_max_bits}, again);
  if (back.status != NumberTextStatus::ok || again != value) finding("to_string does not read back", text);
}

// The status and value the caps allow, from the reference reading.
void check_against_reference(std::string_view text, const NumberTextLimits& limits, const NumberTextResult& got,
                             const Rational& value) {
  const Reading r = read(text);
  if (!r.valid) {
    if (got.status != NumberTextStatus::not_a_number) finding("invalid syntax was not refused", text);
    return;
  }
  if (got.status == NumberTextStatus::not_a_number) finding("valid syntax was refused as not a number", text);
  if (r.fraction) {
    const std::uint64_t p = bits(integer_of(r.numerator)), q = bits(integer_of(r.denominator));
    // When both parts are beyond the cap, either may be named.
    const bool both_over = p > limits.max_bits && q > limits.max_bits;
    const NumberTextStatus expected = p > limits.max_bits   ? NumberTextStatus::numerator_too_large
                                      : q > limits.max_bits ? NumberTextStatus::denominator_too_large
                                                            : NumberTextStatus::ok;
    if (both_over && got.status == NumberTextStatus::denominator_too_large) {
      check_refusal(got, limits, q, text);
      return;
    }
    if (got.status != expected)
      finding("status " + std::to_string(static_cast<int>(got.status)) + " (bits " + std::to_string(got.bits) +
                  ") for a fraction whose parts have " + std::to_string(p) + " and " + std::to_string(q) +
                  " bits (cap " + std::to_string(limits.max_bits) + ")",
              text);
    if (expected == NumberTextStatus::numerator_too_large) check_refusal(got, limits, p, text);
    if (expected == NumberTextStatus::denominator_too_large) check_refusal(got, limits, q, text);
    if (expected == NumberTextStatus::ok) {
      Rational want(integer_of(r.numerator), integer_of(r.denominator));
      want.canonicalize();
      if (r.negative) want = -want;
      if (value != want) finding("wrong value for a fraction", text);
    }
    return;
  }
  if (exponent_magnitude(r.exponent) > limits.max_exponent) {
    if (got.status != NumberTextStatus::exponent_too_large) finding("an exponent beyond the cap was not refused", text);
    return;
  }
  if (got.status == NumberTextStatus::exponent_too_large) finding("an exponent within the cap was refused", text);
  Rational want;
  if (!reference_decimal(r, want)) return;  // too large to build the slow way
  const std::uint64_t p = bits(want.get_num()), q = bits(want.get_den());
  const bool num_over = p > limits.max_bits, den_over = q > limits.max_bits;
  switch (got.status) {
    case NumberTextStatus::ok:
      if (num_over || den_over) finding("a value beyond the cap was accepted", text);
      if (value != want) finding("wrong value for a decimal", text);
      break;
    case NumberTextStatus::numerator_too_large:
      if (!num_over) finding("a numerator within the cap was refused", text);
      check_refusal(got, limits, p, text);
      break;
    case NumberTextStatus::denominator_too_large:
      if (!den_over) finding("a denominator within the cap was refused", text);
      check_refusal(got, limits, q, text);
      break;
    default:
      break;
  }
}

// The public entry points agree with the private one.
void check_public_api(std::string_view text, const NumberTextLimits& limits, const NumberTextResult& got,
                      const Rational& value) {
  const std::optional<Rational> loose = try_parse_rational(text, limits.max_exponent);
  if (got.status == NumberTextStatus::ok && (!loose || *loose != value))
    finding("try_parse_rational refuses or changes a value the caps accept", text);
  if (limits.max_bits >= detail::gmp_max_bits && loose.has_value() != (got.status == NumberTextStatus::ok))
    finding("try_parse_rational disagrees with parse_rational_into without a bit cap", text);
  const std::optional<Rational> by_default = try_parse_rational(text);
  try {
    const Rational parsed = parse_rational(text);
    if (!by_default || parsed != *by_default) finding("parse_rational accepts what try_parse_rational refuses", text);
  } catch (const Error& e) {
    if (e.category() != ErrorCategory::parse) finding("parse_rational threw a non-parse Error", text);
    if (by_default) finding("parse_rational refuses what try_parse_rational accepts", text);
  }
}

}  // namespace

void parse_number_target(std::span<const std::uint8_t> data) {
  if (data.empty()) return;
  constexpr std::uint64_t bit_caps[] = {64, 1075, 4096, detail::gmp_max_bits};
  constexpr long exponent_caps[] = {0, 10, 400, 100000};
  const NumberTextLimits limits{exponent_caps[(data[0] >> 2) & 3], bit_caps[data[0] & 3]};
  const std::string_view text(reinterpret_cast<const char*>(data.data()) + 1, data.size() - 1);
  Rational value;
  const NumberTextResult got = detail::parse_rational_into(text, limits, value);
  if (got.status == NumberTextStatus::ok) check_accepted(value, limits, text);
  check_against_reference(text, limits, got, value);
  check_public_api(text, limits, got, value);
}

}  // namespace cvms::fuzz
