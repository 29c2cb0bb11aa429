// SPDX-License-Identifier: MIT
// `cvms sum A B` when an operand is a solid that is not convex: A + B as one
// closed solid (minkowski_sum of solids, cvms/solid_sum.hpp), written as a
// mesh of its facets' triangles in any output format. Convex operands never
// come here (sum.cpp sums them as before, byte for byte); a solid that is
// not convex is read from a file (the convex reader has already consumed
// standard input) and placed point by point before it is validated.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include "cvms/decomposition.hpp"
#include "cvms/error.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/solid.hpp"
#include "placement.hpp"

namespace cvms::cli {

/// After `convex_error` from reading `path` as a convex set: the file as a
/// placed solid when it is one that is not convex (a mesh file, not a pieces
/// file, whose points span space); nullopt when it is something else (the
/// caller then explains `convex_error`). \throw Error naming the file with
/// the solid's located defect for a mesh that spans space but is no solid.
std::optional<Solid> read_non_convex_solid(const Error& convex_error, const std::string& path,
                                           const Placement& placement, const std::string& operand);

/// What a sum of solids writes, and how.
struct SolidSum {
  std::string output, format;
  Options options;                     ///< threads, limits, progress of the sum
  DecompositionOptions decomposition;  ///< when both operands need decomposing
  std::string float_output;            ///< --float: empty or "nearest" ("outer" is refused)
  bool stats = false;
};

/// Refuses before any work what run_solid_sum cannot write (--float outer).
/// \throw UsageError.
void check_solid_sum(const SolidSum& sum);

/// A + B written to sum.output; with sum.stats, sizes and time to `report`.
/// \throw Error as minkowski_sum of solids (a limit naming its option) and
///   the writers.
void run_solid_sum(const Solid& a, const Solid& b, const SolidSum& sum, std::ostream& report);

}  // namespace cvms::cli
