// SPDX-License-Identifier: MIT
// The regularised union of convex pieces as a solid: its boundary's
// fragments, assembled into one mesh.
#include "boundary_assembly.hpp"
#include "boundary_fragments.hpp"
#include "cvms/error.hpp"
#include "cvms/solid_sum.hpp"

namespace cvms {

Solid union_solid(const ConvexUnion& pieces, const Options& options) {
  if (pieces.empty()) throw Error(ErrorCategory::invalid_argument, "union_solid: the union is empty");
  return detail::assemble_boundary(detail::union_boundary_fragments(pieces.pieces(), options), options);
}

}  // namespace cvms
