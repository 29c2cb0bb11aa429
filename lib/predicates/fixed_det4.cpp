// SPDX-License-Identifier: MIT
// fixed_det4_sign (fixed_det4.hpp has the overflow proof).
#include "fixed_det4.hpp"

#include <algorithm>

#include "fixed_int.hpp"

namespace cvms::detail {
namespace {

// The columns of the six 2×2 minors, in the order 01, 02, 03, 12, 13, 23.
constexpr int first_column[6] = {0, 0, 0, 1, 1, 2};
constexpr int second_column[6] = {1, 2, 3, 2, 3, 3};

template <int E>
std::array<FixedInt<2 * E>, 6> minors(const std::array<mpz_srcptr, 4>& p, const std::array<mpz_srcptr, 4>& q) {
  std::array<FixedInt<E>, 4> u, v;
  for (int k = 0; k < 4; ++k) {
    u[k] = FixedInt<E>::from(p[k]);
    v[k] = FixedInt<E>::from(q[k]);
  }
  std::array<FixedInt<2 * E>, 6> out;
  for (int m = 0; m < 6; ++m) {
    const int j = first_column[m], k = second_column[m];
    out[m] = multiply(u[j], v[k]);
    subtract_from(out[m], multiply(u[k], v[j]));
  }
  return out;
}

template <int E>
int det_sign(const std::array<std::array<mpz_srcptr, 4>, 4>& m) {
  const std::array<FixedInt<2 * E>, 6> top = minors<E>(m[0], m[1]), bottom = minors<E>(m[2], m[3]);
  FixedInt<4 * E + 1> det;
  for (int k = 0; k < 6; ++k) {
    // s_jk pairs with the complementary minor c_(5 − k); signs + − + + − +.
    const FixedInt<4 * E + 1> term = multiply(top[k], bottom[5 - k]).template widened<4 * E + 1>();
    if (k == 1 || k == 4)
      subtract_from(det, term);
    else
      add_to(det, term);
  }
  return det.sign();
}

// The limbs a signed fixed-width integer needs for x: its GMP limbs, one
// more when the top bit of the top limb is set (then x has 64 n bits and
// n limbs hold only 64 n − 1 bits of magnitude).
std::size_t signed_limbs(mpz_srcptr x) {
  const std::size_t n = mpz_size(x);
  return n == 0 ? 1 : n + (mpz_getlimbn(x, static_cast<mp_size_t>(n - 1)) >> 63);
}

}  // namespace

std::optional<int> fixed_det4_sign(const std::array<std::array<mpz_srcptr, 4>, 4>& m) {
  std::size_t limbs = 1;
  for (const auto& row : m)
    for (mpz_srcptr x : row) limbs = std::max(limbs, signed_limbs(x));
  // E limbs hold entries of up to 64E − 1 bits.
  switch (limbs) {
    case 1: return det_sign<1>(m);
    case 2: return det_sign<2>(m);
    case 3: return det_sign<3>(m);
    case 4: return det_sign<4>(m);
    default: return std::nullopt;
  }
}

}  // namespace cvms::detail
