// SPDX-License-Identifier: MIT
// `cvms sum A B` when an operand is a solid that is not convex: A + B as one
// closed solid (minkowski_sum of solids, cvms/solid_sum.hpp), written as a
// mesh of its facets' triangles in any output format. Convex operands never
// come here (sum.cpp sums them as before, byte for byte); an operand file is
// parsed once, and a solid that is not convex is placed point by point
// before it is validated.
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

/// An operand of `cvms sum A B` as read: a convex set, or a placed solid
/// that is not convex (the set then empty), or the error of reading it as
/// a convex set when it is neither (for the caller to explain).
struct SetOrSolid {
  ConvexSet set;
  std::optional<Solid> solid;
  std::optional<Error> convex_error;
  /// With convex_error, for a pieces file: how many pieces it holds.
  std::optional<std::size_t> pieces;
};

/// Reads `path` once: a mesh (a file or OFF on standard input) is read into
/// memory (mesh_input.hpp), parsed and tried as a convex set; when it is
/// none, its bytes are parsed again, as pieces for a pieces file (counted,
/// for the caller's message), else as a solid, validated when its points
/// span space. Other forms are read as convex sets (read_set).
/// \throw Error naming the file with the solid's located defect for a mesh
///   that spans space but is no solid.
SetOrSolid read_set_or_solid(const std::string& path, const Placement& placement, const std::string& operand);

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
