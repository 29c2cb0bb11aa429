// SPDX-License-Identifier: MIT
// Sums of fractions whose numerators and denominators fit one machine word
// each, in 128-bit arithmetic. The vertices of a sum are sums of operand
// vertices; when those are decimals as files hold them (-0.9999510991904915
// is 9999510991904915 / 10^16), they are not dyadic, so the dyadic word path
// (dyadic.hpp) declines them, and GMP's mpq_add spends more on its calls,
// normalisation and scratch than on the few word operations the sum needs.
#pragma once

#include <optional>

#include "cvms/rational.hpp"

namespace cvms::detail {

/// A fraction in lowest terms with a positive denominator, in 128-bit words.
struct WordFraction {
  __extension__ using Int128 = __int128;
  __extension__ using Uint128 = unsigned __int128;
  Int128 numerator;     ///< below 2^127 in magnitude
  Uint128 denominator;  ///< positive
};

/// x + y in lowest terms, when both numerators are at most one limb and both
/// denominators one limb, and the two cross products stay below 2^126 in
/// magnitude; nullopt otherwise (the caller then adds in GMP). The same
/// steps as GMP's mpq_add (Knuth, TAOCP vol. 2, 4.5.1): g = gcd(dx, dy),
/// t = nx (dy / g) + ny (dx / g), h = gcd(t, g), and the sum is (t / h) /
/// ((dx / g)(dy / h)), already in lowest terms. Zero is 0 / 1.
[[nodiscard]] std::optional<WordFraction> word_fraction_sum(const Rational& x, const Rational& y) noexcept;

class LimbArena;

/// out = value, its limbs in arena (LimbArena::store of its two integers,
/// without a GMP value in between).
void store_word_fraction(LimbArena& arena, Rational& out, const WordFraction& value);

}  // namespace cvms::detail
