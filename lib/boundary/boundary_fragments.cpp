// SPDX-License-Identifier: MIT
// See boundary_fragments.hpp.
#include "boundary_fragments.hpp"

#include "cvms/error.hpp"

namespace cvms::detail {

BoundaryFragments union_boundary_fragments(std::span<const ConvexPolyhedron>, const Options&) {
  throw Error(ErrorCategory::invalid_argument, "union_boundary_fragments: not built yet");
}

}  // namespace cvms::detail
