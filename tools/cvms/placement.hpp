// SPDX-License-Identifier: MIT
// Placing an operand of `cvms sum` before the sum: a rotation (an exact
// matrix, or a quaternion whose matrix is exact without a square root) or
// any invertible linear map, then a translation, then a negation:
//   x -> -(R x + t)
// in that order, so that R and t are the operand's pose (turn it about the
// origin, then move it there, as a rigid motion is written) and --negate
// reflects the placed operand, which is what A + (-B) needs for the
// configuration-space obstacle of a robot B at that pose. Numbers are read
// exactly as the file readers read them ("0.1" is 1/10, "1/3", "2.5e-3").
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "cvms/convex_set.hpp"
#include "cvms/polygon_soup.hpp"

namespace cvms::cli {

/// The placement options of one operand, as written on the command line.
struct Placement {
  std::vector<std::string> rotate;      ///< --rotate-X: 9 numbers, row-major
  std::vector<std::string> quaternion;  ///< --quaternion-X: w x y z
  std::vector<std::string> linear;      ///< --linear-X: 9 numbers, row-major
  std::vector<std::string> translate;   ///< --translate-X: x y z
  bool negate = false;                  ///< --negate-X
};

/// --rotate-X, --quaternion-X, --linear-X (one of the three), --translate-X
/// and --negate-X for the operand named `operand` ("a" or "b").
void add_placement_options(CLI::App& command, Placement& placement, const std::string& operand);

/// Fails before any work for the errors placed() would raise.
void check_placement(const Placement& placement, const std::string& operand);

/// The set placed: x -> -(M x + t) as the file comment says (each part only
/// if given). \throw UsageError naming the option for a number that does
/// not parse, a zero quaternion, a --rotate matrix that is not a rotation
/// (not orthogonal, or determinant -1), a singular --linear matrix.
ConvexSet placed(ConvexSet set, const Placement& placement, const std::string& operand);

/// A mesh placed the same way, point by point; each face's order is
/// reversed when the map reverses orientation (a negative determinant:
/// --negate-X, or a --linear-X matrix with det < 0, but not both), so that
/// an outward surface stays outward. 	hrow UsageError as above.
PolygonSoup placed(PolygonSoup soup, const Placement& placement, const std::string& operand);

}  // namespace cvms::cli
