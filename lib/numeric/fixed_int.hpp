// SPDX-License-Identifier: MIT
// Signed integers of a fixed number L of 64-bit limbs (two's complement,
// least significant limb first) on the stack: the exact arithmetic of
// predicates whose operands are known to be short, without GMP's
// allocation, size bookkeeping or calls. Nothing here checks for overflow:
// every caller proves a bit-length bound for each result and picks L from
// it (fixed_det4.hpp). The invariant of a FixedInt<L> x used as an operand
// is |x| < 2^(64 L − 1), i.e. the value fits the signed range, so that
// negation and the magnitude are exact. Private to the library.
#pragma once

#include <array>
#include <cstdint>

#include <gmp.h>

namespace cvms::detail {

static_assert(GMP_NUMB_BITS == 64 && sizeof(mp_limb_t) == 8, "FixedInt reads GMP's limbs as 64-bit words");

__extension__ using FixedUint128 = unsigned __int128;

template <int L>
struct FixedInt {
  std::array<std::uint64_t, L> limb{};

  [[nodiscard]] bool negative() const noexcept { return (limb[L - 1] >> 63) != 0; }
  [[nodiscard]] bool zero() const noexcept {
    for (std::uint64_t w : limb)
      if (w != 0) return false;
    return true;
  }
  /// -1, 0 or 1.
  [[nodiscard]] int sign() const noexcept { return negative() ? -1 : (zero() ? 0 : 1); }

  void negate() noexcept {
    std::uint64_t carry = 1;
    for (std::uint64_t& w : limb) {
      w = ~w + carry;
      carry = carry != 0 && w == 0 ? 1 : 0;
    }
  }

  /// The value of x. \pre mpz_sizeinbase(x, 2) <= 64 L − 1 (or x == 0).
  static FixedInt from(mpz_srcptr x) noexcept {
    FixedInt r;
    const std::size_t n = mpz_size(x);
    for (std::size_t i = 0; i < n; ++i) r.limb[i] = mpz_getlimbn(x, static_cast<mp_size_t>(i));
    if (mpz_sgn(x) < 0) r.negate();
    return r;
  }

  /// The same value in M >= L limbs (sign extension).
  template <int M>
  [[nodiscard]] FixedInt<M> widened() const noexcept {
    static_assert(M >= L);
    FixedInt<M> r;
    const std::uint64_t fill = negative() ? ~std::uint64_t{0} : 0;
    for (int i = 0; i < M; ++i) r.limb[i] = i < L ? limb[i] : fill;
    return r;
  }
};

/// out = x. \pre |x| < 2^(64 L − 1) (the invariant above).
template <int L>
void assign_to(mpz_ptr out, FixedInt<L> x) noexcept {
  const bool negative = x.negative();
  if (negative) x.negate();
  mpz_import(out, L, -1, sizeof(std::uint64_t), 0, 0, x.limb.data());
  if (negative) mpz_neg(out, out);
}

/// a + b modulo 2^(64 L) (exact when the true sum fits the signed range).
template <int L>
void add_to(FixedInt<L>& a, const FixedInt<L>& b) noexcept {
  std::uint64_t carry = 0;
  for (int i = 0; i < L; ++i) {
    const FixedUint128 s = static_cast<FixedUint128>(a.limb[i]) + b.limb[i] + carry;
    a.limb[i] = static_cast<std::uint64_t>(s);
    carry = static_cast<std::uint64_t>(s >> 64);
  }
}

/// a − b modulo 2^(64 L) (exact when the true difference fits).
template <int L>
void subtract_from(FixedInt<L>& a, const FixedInt<L>& b) noexcept {
  std::uint64_t borrow = 0;
  for (int i = 0; i < L; ++i) {
    const FixedUint128 d = static_cast<FixedUint128>(a.limb[i]) - b.limb[i] - borrow;
    a.limb[i] = static_cast<std::uint64_t>(d);
    borrow = static_cast<std::uint64_t>(d >> 64) != 0 ? 1 : 0;
  }
}

/// The exact product in A + B limbs: |a| < 2^(64A − 1) and |b| < 2^(64B − 1)
/// give |a b| < 2^(64(A + B) − 2), inside the signed range of A + B limbs.
/// Schoolbook on the magnitudes; each step t = r + x y + carry stays below
/// 2^128 since (2^64 − 1) + (2^64 − 1)^2 + (2^64 − 1) = 2^128 − 1.
template <int A, int B>
FixedInt<A + B> multiply(FixedInt<A> a, FixedInt<B> b) noexcept {
  const bool negative = a.negative() != b.negative();
  if (a.negative()) a.negate();
  if (b.negative()) b.negate();
  FixedInt<A + B> r;
  for (int i = 0; i < A; ++i) {
    if (a.limb[i] == 0) continue;
    std::uint64_t carry = 0;
    for (int j = 0; j < B; ++j) {
      const FixedUint128 t = static_cast<FixedUint128>(a.limb[i]) * b.limb[j] + r.limb[i + j] + carry;
      r.limb[i + j] = static_cast<std::uint64_t>(t);
      carry = static_cast<std::uint64_t>(t >> 64);
    }
    r.limb[i + B] = carry;
  }
  if (negative) r.negate();
  return r;
}

}  // namespace cvms::detail
