// SPDX-License-Identifier: MIT
/// \file
/// Exact convex decomposition of a solid, and Minkowski sums of non-convex
/// solids as unions of the pairwise sums of their convex pieces: the use the
/// paper names for CVMS ("the pairwise Minkowski sums for non-convex
/// polyhedra, along with convex decomposition and union steps").
#pragma once

#include <cstdint>

#include "cvms/convex_union.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/progress.hpp"
#include "cvms/solid.hpp"

namespace cvms {

/// Bounds on a decomposition's work; exceeding one raises Error(limit).
struct DecompositionLimits {
  std::uint64_t max_pieces = std::uint64_t{1} << 20;          ///< pieces in the result
  std::uint64_t max_memory_bytes = std::uint64_t{4} << 30;    ///< working memory, estimated before it is taken
};

/// How to decompose.
struct DecompositionOptions {
  DecompositionLimits limits;  ///< bounds on pieces and working memory
  /// Hears the stages "decomposition: partition" (one unit: done is 0 until
  /// the partition ends, as its size is not known before; reported after
  /// every cell it splits or finishes), "hull" (inside the partition, for a
  /// large cell tested for convexity) and "decomposition: merge" (units:
  /// two per cell of the partition: its hull, its merge sweep); returning false stops the call with
  /// Error(cancelled) (cvms/progress.hpp).
  ProgressCallback progress;
};

/// Interior-disjoint convex polyhedra whose union is the solid, exactly; few
/// of them (the count drives every later step). A convex solid gives itself
/// as its one piece. Deterministic: the same solid gives the same pieces in
/// the same order.
/// \throw Error(invalid_argument) for an empty solid;
/// \throw Error(limit) if the pieces or the memory would exceed the limits;
/// \throw Error(cancelled) if options.progress asks to stop.
ConvexUnion convex_decomposition(const Solid& solid, const DecompositionOptions& options = {});

/// A + B for solids that need not be convex, as the union of the pairwise
/// sums of their convex pieces (convex_decomposition of each, then
/// minkowski_sum of the two unions with `options`). options.progress also
/// hears the decompositions' stages when decomposition.progress is empty.
/// \throw as convex_decomposition and minkowski_sum(ConvexUnion, ConvexUnion).
ConvexUnion minkowski_sum_pieces(const Solid& a, const Solid& b, const Options& options = {},
                                 const DecompositionOptions& decomposition = {});

}  // namespace cvms
