// SPDX-License-Identifier: MIT
// Signed integers of a fixed number L of 64-bit limbs on the stack, as a
// magnitude (least significant limb first) and a sign: the exact arithmetic
// of predicates whose operands are known to be short, without GMP's
// allocation, size bookkeeping or calls. Nothing here checks for overflow:
// every caller proves a bit-length bound for each result and picks L from
// it (fixed_det4.hpp).
//
// Why sign and magnitude rather than two's complement: these predicates are
// sums of products of signed numbers. In two's complement every product
// negates up to three operands (each factor to its magnitude, the product
// back); here a product multiplies the magnitudes and xors the signs, and a
// sum (SignedSum) adds each term's magnitude to the positive or the negative
// part, subtracting the two once at the end, or only comparing them when the
// sign is all that is asked, which saves about 5 % of the instructions of
// from_halfspaces on a sphere's facet planes (callgrind).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <gmp.h>

namespace cvms::detail {

static_assert(GMP_NUMB_BITS == 64 && sizeof(mp_limb_t) == 8, "FixedInt reads GMP's limbs as 64-bit words");

__extension__ using FixedUint128 = unsigned __int128;

template <int L>
using Limbs = std::array<std::uint64_t, L>;

template <int L>
struct FixedInt {
  Limbs<L> magnitude{};
  bool negative = false;  // may be set on a zero magnitude: sign() reads 0 then

  [[nodiscard]] bool zero() const noexcept {
    for (std::uint64_t w : magnitude)
      if (w != 0) return false;
    return true;
  }
  /// -1, 0 or 1.
  [[nodiscard]] int sign() const noexcept { return zero() ? 0 : (negative ? -1 : 1); }

  /// The value of x. \pre mpz_size(x) <= L.
  static FixedInt from(mpz_srcptr x) noexcept {
    FixedInt r;
    const mp_limb_t* limbs = mpz_limbs_read(x);
    const std::size_t n = mpz_size(x);
    for (std::size_t i = 0; i < n; ++i) r.magnitude[i] = limbs[i];
    r.negative = mpz_sgn(x) < 0;
    return r;
  }
};

/// out = x, negated when `negate`.
template <int L>
void assign_to(mpz_ptr out, const FixedInt<L>& x, bool negate = false) noexcept {
  // The limbs written directly (mpz_import's generic word order and size
  // handling cost 300 instructions a number).
  int n = L;
  while (n > 0 && x.magnitude[static_cast<std::size_t>(n - 1)] == 0) --n;
  mp_limb_t* limbs = mpz_limbs_write(out, n > 0 ? n : 1);
  for (int i = 0; i < n; ++i) limbs[i] = x.magnitude[static_cast<std::size_t>(i)];
  mpz_limbs_finish(out, x.negative != negate ? -n : n);
}

/// The exact product in A + B limbs (the magnitudes' product is below
/// 2^(64(A + B))). Schoolbook; each step t = r + x y + carry stays below
/// 2^128 since (2^64 − 1) + (2^64 − 1)^2 + (2^64 − 1) = 2^128 − 1. Zero
/// limbs of a are skipped: put the operand whose top limbs are often zero
/// first. (Product scanning, one column at a time in a register
/// accumulator, made the dual hull of Sphere6 a fifth slower: GCC does not
/// unroll its triangular loops for the long operands.)
template <int A, int B>
FixedInt<A + B> multiply(const FixedInt<A>& a, const FixedInt<B>& b) noexcept {
  FixedInt<A + B> r;
  for (int i = 0; i < A; ++i) {
    if (a.magnitude[i] == 0) continue;
    std::uint64_t carry = 0;
    for (int j = 0; j < B; ++j) {
      const FixedUint128 t =
          static_cast<FixedUint128>(a.magnitude[i]) * b.magnitude[j] + r.magnitude[i + j] + carry;
      r.magnitude[i + j] = static_cast<std::uint64_t>(t);
      carry = static_cast<std::uint64_t>(t >> 64);
    }
    r.magnitude[i + B] = carry;
  }
  r.negative = a.negative != b.negative;
  return r;
}

/// A sum of signed terms of at most L limbs, kept as the sum P of the
/// positive terms' magnitudes and the sum N of the negative ones'.
/// \pre (the caller's proof) P and N each stay below 2^(64 L).
template <int L>
class SignedSum {
 public:
  template <int K>
  void add(const FixedInt<K>& term) noexcept {
    accumulate(term.negative ? negative_ : positive_, term.magnitude);
  }
  template <int K>
  void subtract(const FixedInt<K>& term) noexcept {
    accumulate(term.negative ? positive_ : negative_, term.magnitude);
  }

  /// The sign of P − N (-1, 0 or 1).
  [[nodiscard]] int sign() const noexcept {
    for (int i = L - 1; i >= 0; --i)
      if (positive_[i] != negative_[i]) return positive_[i] > negative_[i] ? 1 : -1;
    return 0;
  }

  /// P − N.
  [[nodiscard]] FixedInt<L> value() const noexcept {
    FixedInt<L> r;
    r.negative = sign() < 0;
    const Limbs<L>& larger = r.negative ? negative_ : positive_;
    const Limbs<L>& smaller = r.negative ? positive_ : negative_;
    std::uint64_t borrow = 0;
    for (int i = 0; i < L; ++i) {
      const FixedUint128 d = static_cast<FixedUint128>(larger[i]) - smaller[i] - borrow;
      r.magnitude[i] = static_cast<std::uint64_t>(d);
      borrow = static_cast<std::uint64_t>(d >> 64) != 0 ? 1 : 0;
    }
    return r;
  }

 private:
  template <std::size_t K>
  static void accumulate(Limbs<L>& sum, const std::array<std::uint64_t, K>& x) noexcept {
    static_assert(K <= static_cast<std::size_t>(L));
    std::uint64_t carry = 0;
    for (std::size_t i = 0; i < static_cast<std::size_t>(L); ++i) {
      const FixedUint128 s = static_cast<FixedUint128>(sum[i]) + (i < K ? x[i] : 0) + carry;
      sum[i] = static_cast<std::uint64_t>(s);
      carry = static_cast<std::uint64_t>(s >> 64);
    }
  }

  Limbs<L> positive_{};
  Limbs<L> negative_{};
};

}  // namespace cvms::detail
