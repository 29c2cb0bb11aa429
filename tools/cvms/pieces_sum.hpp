// SPDX-License-Identifier: MIT
// `cvms sum A B --pieces`: A + B for operands that need not be convex, as the
// union of the pairwise sums of their convex pieces (minkowski_sum of two
// ConvexUnions), written as a pieces file. Each operand is a pieces file or
// a solid (pieces_files.hpp); the placement options apply to every piece.
// The union's boundary is not built: the output is the pieces.
#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <string>

#include "cvms/decomposition.hpp"
#include "cvms/minkowski.hpp"
#include "placement.hpp"

namespace cvms::cli {

/// --pieces and the decomposition's limits.
struct PiecesOptions {
  bool enabled = false;                ///< --pieces
  DecompositionOptions decomposition;  ///< --max-pieces, --max-decomposition-memory
};

/// Adds --pieces, --max-pieces and --max-decomposition-memory to `sum`.
void add_pieces_options(CLI::App& command, PiecesOptions& pieces);

/// What a pieces sum reads, does and writes.
struct PiecesSum {
  std::string a, b, output, format;
  bool more_operands = false;  ///< a third operand was given (refused)
  Options options;             ///< algorithm, threads, limits of the pairwise sums
  DecompositionOptions decomposition;
  Placement place_a, place_b;
  std::string float_output;  ///< --float: empty, "nearest" or "outer"
  bool stats = false;
};

/// Runs it; with stats, the piece counts and the time go to `report`.
/// \throw UsageError for a third operand, a --format other than obj, an
///   output that is not .obj or "-"; Error as the readers and the sums.
void run_pieces_sum(const PiecesSum& sum, std::ostream& report);

}  // namespace cvms::cli
