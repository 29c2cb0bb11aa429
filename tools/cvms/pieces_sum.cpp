// SPDX-License-Identifier: MIT
// See pieces_sum.hpp.
#include "pieces_sum.hpp"

#include <chrono>
#include <cstdint>
#include <ostream>
#include <utility>
#include <vector>

#include "cvms/convex_union.hpp"
#include "cvms/error.hpp"
#include "files.hpp"
#include "keep_until_exit.hpp"
#include "pieces_files.hpp"
#include "reports.hpp"
#include "usage_error.hpp"

namespace cvms::cli {
namespace {

ConvexUnion placed(const ConvexUnion& u, const Placement& placement, const std::string& operand) {
  std::vector<ConvexPolyhedron> pieces;
  pieces.reserve(u.size());
  for (const ConvexPolyhedron& piece : u.pieces()) pieces.push_back(placed(piece, placement, operand).polyhedron());
  return ConvexUnion(std::move(pieces));
}

std::string piece_count(const ConvexUnion& u) {
  return std::to_string(u.size()) + (u.size() == 1 ? " convex piece" : " convex pieces");
}

std::uint64_t total_facets(const ConvexUnion& u) {
  std::uint64_t facets = 0;
  for (const ConvexPolyhedron& piece : u.pieces()) facets += piece.num_facets();
  return facets;
}

}  // namespace

void add_pieces_options(CLI::App& command, PiecesOptions& pieces) {
  command.add_flag("--pieces", pieces.enabled,
                   "operands may be non-convex solids or pieces files: write the pairwise sums of their convex "
                   "pieces (OBJ)");
  add_decomposition_limit_options(command, pieces.decomposition.limits);
}

void run_pieces_sum(const PiecesSum& sum, std::ostream& report) {
  if (sum.more_operands) throw UsageError("--pieces sums two operands");
  if (!sum.format.empty() && sum.format != "obj" && sum.format != "OBJ")
    throw UsageError("--pieces writes OBJ objects: --format must be obj");
  if (sum.a == "-" && sum.b == "-") throw UsageError("only one input can be read from stdin");
  check_pieces_output(sum.output);
  check_placement(sum.place_a, "a");
  check_placement(sum.place_b, "b");
  const ConvexUnion a = placed(read_union_operand(sum.a, sum.decomposition), sum.place_a, "a");
  const ConvexUnion b = placed(read_union_operand(sum.b, sum.decomposition), sum.place_b, "b");
  const auto start = std::chrono::steady_clock::now();
  ConvexUnion result;
  try {
    result = minkowski_sum(a, b, sum.options);
  } catch (const Error& e) {
    rethrow_with_pieces_limit_hint(e);
  }
  const auto time = std::chrono::steady_clock::now() - start;
  write_pieces_output(sum.output, result, coordinates_of(sum.float_output));
  if (sum.stats)
    report << "A: " << piece_count(a) << "\nB: " << piece_count(b) << "\nA+B: " << piece_count(result) << ", F "
           << total_facets(result) << " in all\nalgorithm: " << to_string(sum.options.algorithm)
           << "\ntime: " << milliseconds(time) << "\n";
  keep_until_exit(std::move(result));
}

}  // namespace cvms::cli
