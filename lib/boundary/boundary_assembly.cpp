// SPDX-License-Identifier: MIT
// See boundary_assembly.hpp.
#include "boundary_assembly.hpp"

#include "cvms/error.hpp"

namespace cvms::detail {

Solid assemble_boundary(const BoundaryFragments&, const Options&) {
  throw Error(ErrorCategory::invalid_argument, "assemble_boundary: not built yet");
}

}  // namespace cvms::detail
