// SPDX-License-Identifier: MIT
// The sign of a 4×4 integer determinant in fixed-width integers
// (fixed_int.hpp) when every entry is short: the exact stage of
// homogeneous_orient3d, whose degenerate inputs (the coplanar dual points of
// a geodesic sphere's facet planes) make it decide thousands of exact zeros.
//
// Overflow proof, by the width E (in 64-bit limbs) chosen from the entries:
// every entry has at most 64E − 1 bits, so |m_ij| <= M < 2^(64E − 1), and a
// row r has Euclidean length |r| <= 2M (four entries). Sums are SignedSums
// (fixed_int.hpp): the positive and the negative terms' magnitudes are added
// apart, so each part must stay below 2^(64 L) for its L limbs, and the
// value, their difference, is at most the larger part. A part is at most the
// sum of the terms' magnitudes, which the bounds below take (every term may
// fall in one part).
//  - A 2×2 minor u_j v_k − u_k v_j: each product is at most M^2, a part at
//    most 2 M^2 < 2^(128E − 1): 2E limbs.
//  - det = s01 c23 − s02 c13 + s03 c12 + s12 c03 − s13 c02 + s23 c01
//    (Laplace along the first two rows, homogeneous_orient.cpp), s the
//    minors of rows a, b and c those of c, d: a part is at most
//    sum_k |s_k| |c_(5−k)| <= ‖s‖ ‖c‖ (Cauchy–Schwarz), and ‖s‖ <= |a| |b|
//    (Lagrange's identity: ‖s‖^2 = |a|^2 |b|^2 − (a·b)^2), so at most
//    |a| |b| |c| |d| <= 16 M^4 < 2^(256E): 4E limbs, with no bit to spare
//    (the ±M Hadamard patterns reach 16 M^4 in one part).
//  - The last row's cofactors and the determinant from them: at
//    last_row_cofactors and fixed_det4_cross_sign below.
// Entries of more than max_fixed_entry_bits bits are not handled (the
// caller falls back to GMP's mpz): huge rationals are legal input.
#pragma once

#include <array>
#include <cstddef>
#include <optional>

#include <gmp.h>

#include "fixed_int.hpp"

namespace cvms::detail {

/// Entries up to this many bits (E = 4 limbs) take the fixed-width path.
inline constexpr std::size_t max_fixed_entry_bits = 4 * 64 - 1;

/// The width E for x that the bounds here assume (|x| < 2^(64E − 1)): its
/// GMP limbs, one more when the top bit of the top limb is set. The missing
/// bit is the determinants' (the Laplace bound above has none to spare),
/// not the sign's: a FixedInt<E> could hold 64E bits, the proofs could not.
/// \pre every entry has at most 64E − 1 bits.
inline int signed_limbs(mpz_srcptr x) noexcept {
  const std::size_t n = mpz_size(x);
  return n == 0 ? 1 : static_cast<int>(n + (mpz_getlimbn(x, static_cast<mp_size_t>(n - 1)) >> 63));
}

/// A matrix row in E limbs per entry. \pre every entry has at most 64E − 1 bits.
template <int E>
using FixedRow = std::array<FixedInt<E>, 4>;

template <int E>
FixedRow<E> fixed_row(const std::array<mpz_srcptr, 4>& entries) noexcept {
  FixedRow<E> r;
  for (int k = 0; k < 4; ++k) r[k] = FixedInt<E>::from(entries[k]);
  return r;
}

namespace fixed_det4_internal {

// The columns of the six 2×2 minors, in the order 01, 02, 03, 12, 13, 23.
inline constexpr int first_column[6] = {0, 0, 0, 1, 1, 2};
inline constexpr int second_column[6] = {1, 2, 3, 2, 3, 3};

template <int E>
std::array<FixedInt<2 * E>, 6> minors(const FixedRow<E>& u, const FixedRow<E>& v) noexcept {
  std::array<FixedInt<2 * E>, 6> out;
  for (int m = 0; m < 6; ++m) {
    const int j = first_column[m], k = second_column[m];
    SignedSum<2 * E> minor;
    minor.add(multiply(u[j], v[k]));
    minor.subtract(multiply(u[k], v[j]));
    out[m] = minor.value();
  }
  return out;
}

}  // namespace fixed_det4_internal

/// The sign (−1, 0 or 1) of det[a; b; c; d] (the bound above holds).
template <int E>
int fixed_det4_sign(const FixedRow<E>& a, const FixedRow<E>& b, const FixedRow<E>& c, const FixedRow<E>& d) noexcept {
  const std::array<FixedInt<2 * E>, 6> top = fixed_det4_internal::minors<E>(a, b),
                                       bottom = fixed_det4_internal::minors<E>(c, d);
  SignedSum<4 * E> det;
  for (int k = 0; k < 6; ++k) {
    // s_jk pairs with the complementary minor c_(5 − k); signs + − + + − +.
    if (k == 1 || k == 4)
      det.subtract(multiply(top[k], bottom[5 - k]));
    else
      det.add(multiply(top[k], bottom[5 - k]));
  }
  return det.sign();
}

/// The cofactors of the last row of [a; b; c; d]: det = sum_k d_k cof_k for
/// every d, so that many d against the same a, b, c cost four products each.
/// Bound: cof_k = ±(a_p m_qr − a_q m_pr + a_r m_pq), the 3×3 determinant
/// of a, b, c without column k, with m the 2×2 minors of b, c in the other
/// three columns: as above, a part is at most |a'| |b'| |c'| for the rows
/// restricted to those columns, each of length at most √3 M, so below
/// 3√3 M^3 < 2^(192E): 3E limbs. The determinant from them, sum_k d_k cof_k:
/// a part is at most |d| ‖cof‖ (Cauchy–Schwarz), and ‖cof‖ <= |a| |b| |c|
/// (the cofactors are the 3-volume of a, b, c by its coordinate
/// projections; Hadamard's inequality), so at most 16 M^4 < 2^(256E): 4E
/// limbs.
template <int E>
using Cofactors = std::array<FixedInt<3 * E>, 4>;

template <int E>
Cofactors<E> last_row_cofactors(const FixedRow<E>& a, const FixedRow<E>& b, const FixedRow<E>& c) noexcept {
  const std::array<FixedInt<2 * E>, 6> m = fixed_det4_internal::minors<E>(b, c);  // 01 02 03 12 13 23
  // D_k, the 3×3 determinant without column k, along the row a; cof_k =
  // (−1)^(k + 3) D_k (Laplace along the last row).
  constexpr int column[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  constexpr int minor[4][3] = {{5, 4, 3}, {5, 2, 1}, {4, 2, 0}, {3, 1, 0}};
  Cofactors<E> cof;
  // Each product with the minor first (multiply skips its zero limbs).
  for (int k = 0; k < 4; ++k) {
    SignedSum<3 * E> d;
    d.add(multiply(m[minor[k][0]], a[column[k][0]]));
    d.subtract(multiply(m[minor[k][1]], a[column[k][1]]));
    d.add(multiply(m[minor[k][2]], a[column[k][2]]));
    cof[k] = d.value();
    if (k % 2 == 0) cof[k].negative = !cof[k].negative;
  }
  return cof;
}

namespace fixed_det4_internal {

// det[a; b; c; d] from the cofactors of a, b, c, as its two parts.
template <int E>
SignedSum<4 * E> det_from_cofactors(const Cofactors<E>& cof, const FixedRow<E>& d) noexcept {
  SignedSum<4 * E> det;
  // The long operand first: multiply skips its zero limbs (the top limbs
  // of a cofactor's magnitude are often zero), each costing E products.
  for (int k = 0; k < 4; ++k) det.add(multiply(cof[k], d[k]));
  return det;
}

}  // namespace fixed_det4_internal

/// det[a; b; c; d] from the cofactors of a, b, c.
template <int E>
FixedInt<4 * E> fixed_det4(const Cofactors<E>& cof, const FixedRow<E>& d) noexcept {
  return fixed_det4_internal::det_from_cofactors<E>(cof, d).value();
}

/// Its sign (−1, 0 or 1): the parts compared, not subtracted.
template <int E>
int fixed_det4_sign(const Cofactors<E>& cof, const FixedRow<E>& d) noexcept {
  return fixed_det4_internal::det_from_cofactors<E>(cof, d).sign();
}

/// The sign (−1, 0 or 1) of det[a; b; c; p] · q_3 − det[a; b; c; q] · p_3
/// (the last entries p_3, q_3 are the homogeneous weights of
/// homogeneous_orient.hpp), from the cofactors of a, b, c. Bound: each
/// determinant is at most 16 M^4 (above) and each weight at most M, so each
/// product is at most 16 M^5 < 2^(320E − 1); both may fall in one part,
/// which is then below 2^(320E): 5E limbs.
template <int E>
int fixed_det4_cross_sign(const Cofactors<E>& cof, const FixedRow<E>& p, const FixedRow<E>& q) noexcept {
  SignedSum<5 * E> d;
  d.add(multiply(fixed_det4<E>(cof, p), q[3]));
  d.subtract(multiply(fixed_det4<E>(cof, q), p[3]));
  return d.sign();
}

/// The sign (−1, 0 or 1) of det[m], or nothing if an entry has more than
/// max_fixed_entry_bits bits.
std::optional<int> fixed_det4_sign(const std::array<std::array<mpz_srcptr, 4>, 4>& m);

}  // namespace cvms::detail
