// SPDX-License-Identifier: MIT
// See proximity_report.hpp.
#include "proximity_report.hpp"

#include <charconv>
#include <ostream>

#include "cvms/error.hpp"
#include "cvms/proximity.hpp"
#include "files.hpp"
#include "pieces_files.hpp"
#include "set_files.hpp"
#include "usage_error.hpp"

namespace cvms::cli {
namespace {

std::string shortest(double d) {
  char digits[64];
  auto result = std::to_chars(digits, digits + sizeof digits, d);
  return std::string(digits, result.ptr);
}

ConvexSet read_operand(const std::string& path) {
  ConvexSet s = read_set(path);
  if (s.empty())
    throw Error(ErrorCategory::invalid_argument, input_name(path) + ": the empty set has no distance or depth");
  return s;
}

}  // namespace

Operands read_operands(const std::string& a, const std::string& b, std::string_view non_convex_hint) {
  if (a == "-" && b == "-") throw UsageError("only one input can be read from stdin");
  auto read = [non_convex_hint](const std::string& path) {
    try {
      return read_operand(path);
    } catch (const Error& e) {
      if (non_convex_hint.empty()) throw;
      rethrow_explaining_non_convex(e, path, non_convex_hint);
    }
  };
  ConvexSet first = read(a);
  ConvexSet second = read(b);
  return {std::move(first), std::move(second)};
}

AnyOperand read_any_operand(const std::string& path) {
  if (is_pieces_path(path)) return {ConvexSet(), read_union_operand(path, {})};
  try {
    return {read_operand(path), ConvexUnion()};
  } catch (const Error& e) {
    const bool shape_error = e.category() == ErrorCategory::not_convex || e.category() == ErrorCategory::topology;
    if (!shape_error || is_std_stream(path) || !check_mesh_path(path).empty() || is_cdd_points_path(path)) throw;
    PolygonSoup soup = read_soup(path);
    if (!spans_space(soup)) throw;
    return {ConvexSet(), decompose_soup(std::move(soup), path, {})};
  }
}

void print_square_and_root(std::ostream& out, const char* name, const char* rounded_name, const Rational& square) {
  out << name << ' ' << to_string(square) << '\n'
      << rounded_name << ' ' << shortest(nearest_double_sqrt(square)) << '\n';
}

void print_point(std::ostream& out, const char* name, const Vec3& p) {
  out << name << ' ' << to_string(p.x) << ' ' << to_string(p.y) << ' ' << to_string(p.z) << '\n';
}

void print_intersect(std::ostream& out, bool intersect) { out << "intersect " << (intersect ? "yes" : "no") << '\n'; }

}  // namespace cvms::cli
