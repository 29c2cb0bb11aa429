// SPDX-License-Identifier: MIT
/// \file
/// Exact rational numbers (GMP's mpq_class) and their exact text and double
/// conversions. Nothing here ever rounds unless its name says so.
#pragma once

#include <gmpxx.h>

#include <optional>
#include <string>
#include <string_view>

/// Exact Minkowski sums of convex polyhedra.
namespace cvms {

/// An exact rational number: GMP's mpq_class, always kept in lowest terms.
/// Arithmetic and comparison are gmpxx's; values grow as needed, never round.
using Rational = mpq_class;

/// Parses a number exactly. Accepts integers ("-12"), decimals with optional
/// exponent ("0.1" is 1/10, "-2.5E+7", "1e-300", ".5", "5.") and fractions
/// "p/q" (q != 0). Leading '+' is allowed; no surrounding spaces. Returns
/// nothing for anything else, including "nan", "inf", exponents whose
/// magnitude exceeds max_exponent (which bounds the memory a lying input can
/// make us allocate) and values too large for GMP to hold (2^36 bits). The
/// readers of cvms/io.hpp also cap the bits of every number (ReadLimits).
std::optional<Rational> try_parse_rational(std::string_view text,
                                           long max_exponent = 100000);

/// As try_parse_rational, but throws Error(parse) naming the text.
Rational parse_rational(std::string_view text);

/// The exact value of a finite double. \throw Error(invalid_argument) for NaN
/// or infinity.
Rational rational_from_double(double value);
/// The exact value of a finite float. \throw Error(invalid_argument) for NaN
/// or infinity.
Rational rational_from_float(float value);

/// Exact text: a finite decimal ("0.1", "-2.5", "12", "0.000001") when the
/// reduced denominator is 2^a*5^b, otherwise "p/q". Never uses an exponent, so
/// the output can be long for extreme values; try_parse_rational reads it back
/// to the same value.
std::string to_string(const Rational& value);

/// The double nearest to value (ties to even); +-infinity beyond the range.
double to_double_nearest(const Rational& value);

/// True iff value is exactly representable as a double.
bool is_double_exact(const Rational& value);

}  // namespace cvms
