// SPDX-License-Identifier: MIT
// A + B of solids as the union of the pairwise sums of their convex pieces:
// (A1 u ... u An) + (B1 u ... u Bm) = u (Ai + Bj).
#include "cvms/decomposition.hpp"

namespace cvms {

ConvexUnion minkowski_sum_pieces(const Solid& a, const Solid& b, const Options& options,
                                 const DecompositionOptions& decomposition) {
  DecompositionOptions heard = decomposition;
  if (!heard.progress) heard.progress = options.progress;  // a caller cancels the whole sum with one callback
  return minkowski_sum(convex_decomposition(a, heard), convex_decomposition(b, heard), options);
}

}  // namespace cvms
