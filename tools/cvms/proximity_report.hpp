// SPDX-License-Identifier: MIT
// What `cvms distance` and `cvms penetration` share: their operands and the
// lines they print. The exact numbers come first, printed as the writers
// print coordinates (cvms::to_string: a decimal when finite, else p/q); the
// rounded value is the double nearest to the exact square root, printed in
// the shortest form that reads back to it. The operands are read as convex
// sets of any dimension (as `cvms sum` reads them), so a flat OBJ, a segment
// or a point is a valid operand; proximity.hpp says what a flat A + (-B)
// means for the penetration. `cvms distance` also takes solids that are not
// convex and pieces files, as unions of convex pieces.
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>

#include "cvms/convex_set.hpp"
#include "cvms/convex_union.hpp"
#include "cvms/rational.hpp"
#include "cvms/vec.hpp"

namespace cvms::cli {

/// A and B, read as convex sets. \throw UsageError if both are "-";
/// Error naming the file for the empty set, which the library can only call A or B.
struct Operands {
  ConvexSet a, b;
};
/// With a `non_convex_hint`, an operand that is a solid but not convex, or
/// a pieces file, is refused with that hint (pieces_files.hpp).
Operands read_operands(const std::string& a, const std::string& b, std::string_view non_convex_hint = {});

/// One operand as a convex set (read_operands' check for the empty set), or
/// when the file holds none, as the convex pieces of a pieces file or of a
/// solid (pieces_files.hpp); `set` is then empty.
struct AnyOperand {
  ConvexSet set;
  ConvexUnion pieces;
};
AnyOperand read_any_operand(const std::string& path);

/// "<name> <exact value>" and "<rounded name> <nearest double of its square root>".
void print_square_and_root(std::ostream& out, const char* name, const char* rounded_name, const Rational& square);

/// "<name> x y z", exact.
void print_point(std::ostream& out, const char* name, const Vec3& p);

/// "intersect yes" or "intersect no".
void print_intersect(std::ostream& out, bool intersect);

}  // namespace cvms::cli
