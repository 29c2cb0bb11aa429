// SPDX-License-Identifier: MIT
// Factors of 128-bit unsigned integers without division (a 128-bit
// division is a library call of about a hundred cycles) and without GMP:
// the gcd by the binary method (Stein: shifts, subtractions and
// trailing-zero counts on two machine words), and exact division by 5 (a
// multiplication by its inverse modulo 2^128), with which the factors 2
// and 5 that decimal and dyadic denominators bring are counted off
// (scaled_points.cpp, small_direction.cpp).
#pragma once

#include <cstdint>
#include <utility>

namespace cvms::detail {

__extension__ using Gcd128Word = unsigned __int128;

/// The number of trailing zero bits of x. \pre x != 0.
[[nodiscard]] inline int trailing_zeros128(Gcd128Word x) noexcept {
  const auto low = static_cast<std::uint64_t>(x);
  return low != 0 ? __builtin_ctzll(low) : 64 + __builtin_ctzll(static_cast<std::uint64_t>(x >> 64));
}

/// gcd(a, b), with gcd(0, b) = b and gcd(0, 0) = 0.
[[nodiscard]] inline Gcd128Word gcd128(Gcd128Word a, Gcd128Word b) noexcept {
  if (a == 0) return b;
  if (b == 0) return a;
  const int shift = trailing_zeros128(a | b);  // the power of two both share
  a >>= trailing_zeros128(a);
  // Invariant: a odd; gcd(a, b) times 2^shift is the answer.
  do {
    b >>= trailing_zeros128(b);
    if (a > b) std::swap(a, b);
    b -= a;  // even, and below the larger of the two
  } while (b != 0);
  return a << shift;
}

/// The inverse of 5 modulo 2^128 (Newton's iteration: 5 is its own
/// inverse modulo 8, and each step doubles the correct low bits, 3 to 192).
inline constexpr Gcd128Word inverse_of_5 = [] {
  Gcd128Word inverse = 5;
  for (int k = 0; k < 6; ++k) inverse *= 2 - 5 * inverse;
  return inverse;
}();
static_assert(inverse_of_5 * 5 == 1);

/// Whether x is a multiple of 5, and then x / 5 into x: x times the
/// inverse is x / 5 exactly for the multiples, which are the x whose
/// product is at most (2^128 - 1) / 5 (the map is a bijection and sends
/// the multiples onto [0, (2^128 - 1) / 5]).
[[nodiscard]] inline bool divide_by_5(Gcd128Word& x) noexcept {
  const Gcd128Word quotient = x * inverse_of_5;
  if (quotient > ~Gcd128Word{0} / 5) return false;
  x = quotient;
  return true;
}

}  // namespace cvms::detail
