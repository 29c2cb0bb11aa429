// SPDX-License-Identifier: MIT
// A + B of solids as the union of the pairwise sums of their convex pieces:
// (A1 u ... u An) + (B1 u ... u Bm) = u (Ai + Bj).
#include "cvms/decomposition.hpp"

namespace cvms {

ConvexUnion minkowski_sum_pieces(const Solid& a, const Solid& b, const Options& options,
                                 const DecompositionOptions& decomposition) {
  return minkowski_sum(convex_decomposition(a, decomposition), convex_decomposition(b, decomposition),
                       options);
}

}  // namespace cvms
