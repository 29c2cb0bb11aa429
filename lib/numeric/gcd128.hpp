// SPDX-License-Identifier: MIT
// The gcd of two 128-bit unsigned integers by the binary method (Stein):
// shifts, subtractions and trailing-zero counts on two machine words, no
// division (a 128-bit division is a library call of about a hundred
// cycles) and no GMP value. Edge directions of operands carried as
// two-word integers (two_word_scaled.hpp) are made primitive with it.
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

}  // namespace cvms::detail
