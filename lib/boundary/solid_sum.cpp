// SPDX-License-Identifier: MIT
// A + B of solids as one solid (see cvms/solid_sum.hpp).
#include "cvms/solid_sum.hpp"

#include "cvms/error.hpp"

namespace cvms {

Solid minkowski_sum(const Solid&, const Solid&, const Options&, const DecompositionOptions&) {
  throw Error(ErrorCategory::invalid_argument, "minkowski_sum of solids: not built yet");
}

}  // namespace cvms
