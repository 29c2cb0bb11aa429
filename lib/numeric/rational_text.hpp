// SPDX-License-Identifier: MIT
// Exact number parsing under size caps, for untrusted text. The caps are
// checked on the text before any number larger than the text itself is
// built: "1e99999" is 7 bytes that would be a 332,000-bit integer, and
// "1e-99999" a 332,000-bit denominator, so the parser reads the size of the
// value off the digit count and the exponent and refuses it before GMP is
// asked for the power of ten. What is built is then never more than the cap
// (plus a few bits) or the text, whichever is larger.
//
// Sizes are those of the value in lowest terms, which a decimal gives away
// cheaply: d_1..d_D x 10^s with the trailing zeros of the digits folded into
// s is an integer of floor(log2(M 10^s)) + 1 bits when s >= 0; when s < 0 it
// is M / (2^k 5^k) with k = -s, and since M is not a multiple of 10 at most
// one of 2 and 5 cancels, so the reduced denominator 2^(k-a) 5^(k-b) (a, b
// the powers of 2 and 5 in M, capped at k) has at least k + 1 bits. A
// fraction p/q is judged by p and q as written: reducing a huge one would
// cost the time the cap is there to save.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "cvms/rational.hpp"

namespace cvms::detail {

/// Bits beyond which GMP cannot hold an integer (its sizes are int limbs):
/// the cap when the caller sets none.
inline constexpr std::uint64_t gmp_max_bits = std::uint64_t{1} << 36;

/// Caps for parse_rational_into.
struct NumberTextLimits {
  long max_exponent = 100000;  ///< largest accepted |exponent| of a decimal, as written
  /// Largest accepted bit length of the numerator and of the denominator
  /// (in lowest terms; p/q as written).
  std::uint64_t max_bits = gmp_max_bits;
};

/// What parse_rational_into found; checked in this order, except that when
/// both the numerator and the denominator are beyond max_bits either may be
/// reported (whichever estimate shows it first).
enum class NumberTextStatus {
  ok,
  not_a_number,           ///< not the syntax of try_parse_rational (or q = 0)
  exponent_too_large,     ///< |exponent| beyond max_exponent
  numerator_too_large,    ///< numerator beyond max_bits
  denominator_too_large,  ///< denominator beyond max_bits
};

/// The outcome, and for the *_too_large ones how many bits the part needs
/// at least (exact when it was cheap to know).
struct NumberTextResult {
  NumberTextStatus status = NumberTextStatus::ok;
  std::uint64_t bits = 0;
};

/// Parses text with the syntax of try_parse_rational into `out` (in lowest
/// terms), refusing it as soon as the text shows that a cap is exceeded.
/// `out` is unspecified when the status is not ok.
/// Complexity: linear in the text for the syntax; the number built has at
/// most max(max_bits + 4, 4 x the text length) bits.
NumberTextResult parse_rational_into(std::string_view text, const NumberTextLimits& limits, Rational& out);

/// Appends the text of to_string(value) to `out`: integers and decimals of up
/// to about 770 digits straight from machine words, others through
/// exact_text_general.
void append_exact_text(std::string& out, const Rational& value);
/// The same for the dyadic value numerator / 2^exponent, without a
/// Rational (a packed coordinate, dyadic_points.hpp).
/// \pre in lowest terms: the numerator is odd or the exponent 0.
void append_exact_text(std::string& out, mpz_srcptr numerator, mp_bitcnt_t exponent);

/// to_string's text by the general route (strip 2s and 5s from the
/// denominator, scale by a power of ten, print): the reference the fast
/// printer is tested against.
std::string exact_text_general(const Rational& value);

}  // namespace cvms::detail
