// SPDX-License-Identifier: MIT
// A total order on exact points for deduplication. Hash
// containers keyed by hash_value go quadratic on inputs whose points share
// one hash, and hash_value is made of invertible steps, so an input can
// choose that; sorting (or a balanced tree) by an exact order costs
// O(n log n) comparisons whatever the values. The order compares the
// canonical representation (numerator, then denominator, as integers), not
// the values: equal exactly when the values are equal, and cheaper than
// mpq_cmp (no cross products). It has no geometric meaning.
#pragma once

#include <gmp.h>

#include "cvms/vec.hpp"

namespace cvms::detail {

/// Negative, zero or positive as a is before, equal to or after b in the
/// representation order. \pre both canonical (as GMP keeps them).
inline int compare_representation(const Rational& a, const Rational& b) noexcept {
  const int c = mpz_cmp(a.get_num_mpz_t(), b.get_num_mpz_t());
  return c != 0 ? c : mpz_cmp(a.get_den_mpz_t(), b.get_den_mpz_t());
}

/// Lexicographic (x, y, z) in the representation order; a strict weak order
/// whose equivalence is exact equality of points. Transparent, so a tree of
/// pointers can be searched with a point.
struct RepresentationLess {
  using is_transparent = void;
  static bool less(const Vec3& a, const Vec3& b) noexcept {
    for (int i = 0; i < 3; ++i)
      if (const int c = compare_representation(a[i], b[i]); c != 0) return c < 0;
    return false;
  }
  bool operator()(const Vec3& a, const Vec3& b) const noexcept { return less(a, b); }
  bool operator()(const Vec3* a, const Vec3* b) const noexcept { return less(*a, *b); }
  bool operator()(const Vec3* a, const Vec3& b) const noexcept { return less(*a, b); }
  bool operator()(const Vec3& a, const Vec3* b) const noexcept { return less(a, *b); }
};

}  // namespace cvms::detail
