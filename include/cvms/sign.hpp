// SPDX-License-Identifier: MIT
/// \file
/// The result type of every predicate: an exact sign.
#pragma once

namespace cvms {

/// The exact sign of a quantity; converts to the int -1, 0 or 1 by static_cast.
enum class Sign : int {
  negative = -1,  ///< < 0
  zero = 0,       ///< == 0
  positive = 1    ///< > 0
};

/// The sign of an int (e.g. of gmpxx's sgn() or cmp()).
inline Sign sign_of(int s) noexcept { return s < 0 ? Sign::negative : (s > 0 ? Sign::positive : Sign::zero); }
/// The opposite sign (zero stays zero).
inline Sign operator-(Sign s) noexcept { return static_cast<Sign>(-static_cast<int>(s)); }

}  // namespace cvms
