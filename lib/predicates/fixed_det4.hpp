// SPDX-License-Identifier: MIT
// The sign of a 4×4 integer determinant in fixed-width integers
// (fixed_int.hpp) when every entry is short: the exact stage of
// homogeneous_orient3d, whose degenerate inputs (the coplanar dual points of
// a geodesic sphere's facet planes) make it decide thousands of exact zeros.
//
// Overflow proof, by the width E (in 64-bit limbs) chosen from the entries:
// every entry has at most 64E − 1 bits, so |m_ij| < 2^(64E − 1).
//  - A 2×2 minor u_j v_k − u_k v_j: each product is below 2^(128E − 2)
//    (multiply in fixed_int.hpp), the difference below 2^(128E − 1): it fits
//    the signed range of 2E limbs.
//  - det = s01 c23 − s02 c13 + s03 c12 + s12 c03 − s13 c02 + s23 c01
//    (Laplace along the first two rows, homogeneous_orient.cpp): each
//    product of two minors is below 2^(256E − 2), the sum of six below
//    6 · 2^(256E − 2) < 2^(256E + 1), inside the signed range of 4E + 1
//    limbs (2^(256E + 63)), where the products are added after sign
//    extension. Every intermediate of the sum is a partial sum of at most
//    six such terms, so none wraps either.
// Entries of more than max_fixed_entry_bits bits are not handled (the
// caller falls back to GMP's mpz): huge rationals are legal input.
#pragma once

#include <array>
#include <optional>

#include <gmp.h>

namespace cvms::detail {

/// Entries up to this many bits (E = 4 limbs) take the fixed-width path.
inline constexpr std::size_t max_fixed_entry_bits = 4 * 64 - 1;

/// The sign (−1, 0 or 1) of det[m], or nothing if an entry has more than
/// max_fixed_entry_bits bits.
std::optional<int> fixed_det4_sign(const std::array<std::array<mpz_srcptr, 4>, 4>& m);

}  // namespace cvms::detail
