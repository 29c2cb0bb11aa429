// SPDX-License-Identifier: MIT
// fixed_det4_sign (fixed_det4.hpp has the overflow proof).
#include "fixed_det4.hpp"

#include <algorithm>

namespace cvms::detail {
namespace {

template <int E>
int det_sign(const std::array<std::array<mpz_srcptr, 4>, 4>& m) {
  return fixed_det4_sign<E>(fixed_row<E>(m[0]), fixed_row<E>(m[1]), fixed_row<E>(m[2]), fixed_row<E>(m[3]));
}

}  // namespace

std::optional<int> fixed_det4_sign(const std::array<std::array<mpz_srcptr, 4>, 4>& m) {
  int limbs = 1;
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
