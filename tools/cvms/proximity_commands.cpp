// SPDX-License-Identifier: MIT
// `cvms distance A B` and `cvms penetration A B` (see proximity_commands.hpp).
// The exact numbers come first, printed as the writers print coordinates
// (cvms::to_string: a decimal when finite, else p/q); the rounded distance is
// the double nearest to the exact square root, printed in the shortest form
// that reads back to it. The operands are read as convex sets of any
// dimension (as `cvms sum` reads them), so a flat OBJ, a segment or a point
// is a valid operand; proximity.hpp says what a flat A + (-B) means for the
// penetration.
#include "proximity_commands.hpp"

#include <charconv>
#include <ostream>

#include "cvms/error.hpp"
#include "cvms/proximity.hpp"
#include "files.hpp"
#include "commands.hpp"
#include "set_commands.hpp"

namespace cvms::cli {
namespace {

std::string shortest(double d) {
  char digits[64];
  auto result = std::to_chars(digits, digits + sizeof digits, d);
  return std::string(digits, result.ptr);
}

void print_point(std::ostream& out, const char* name, const Vec3& p) {
  out << name << ' ' << to_string(p.x) << ' ' << to_string(p.y) << ' ' << to_string(p.z) << '\n';
}

void print_intersect(std::ostream& out, bool intersect) { out << "intersect " << (intersect ? "yes" : "no") << '\n'; }

void run_distance(const ConvexSet& a, const ConvexSet& b, std::ostream& out) {
  const DistanceResult d = squared_distance(a, b);
  out << "squared_distance " << to_string(d.squared_distance) << '\n'
      << "distance " << shortest(nearest_double_sqrt(d.squared_distance)) << '\n';
  print_point(out, "witness_a", d.witness_a);
  print_point(out, "witness_b", d.witness_b);
  print_intersect(out, d.intersect);
}

void run_penetration(const ConvexSet& a, const ConvexSet& b, std::ostream& out) {
  const PenetrationResult p = penetration(a, b);
  out << "squared_depth " << to_string(p.squared_depth) << '\n'
      << "depth " << shortest(nearest_double_sqrt(p.squared_depth)) << '\n'
      << "direction " << to_string(p.direction.x) << ' ' << to_string(p.direction.y) << ' '
      << to_string(p.direction.z) << '\n';
  print_point(out, "witness_a", p.witness_a);
  print_point(out, "witness_b", p.witness_b);
  print_intersect(out, p.intersect);
}

// An operand; the empty set (an OFF with no points) is named by its file
// here, as the library can only call it A or B.
ConvexSet read_operand(const std::string& path) {
  ConvexSet s = read_set(path);
  if (s.empty()) throw Error(ErrorCategory::invalid_argument, input_name(path) + ": the empty set has no distance or depth");
  return s;
}

}  // namespace

void add_proximity_commands(CLI::App& app, ProximityArgs& args, const CLI::Validator& mesh_path) {
  args.distance = app.add_subcommand("distance", "exact squared distance of A and B, with witness points");
  args.penetration =
      app.add_subcommand("penetration", "exact squared penetration depth of A and B, direction and witnesses");
  for (CLI::App* command : {args.distance, args.penetration}) {
    command->add_option("A", args.a, "first operand")->required()->check(mesh_path);
    command->add_option("B", args.b, "second operand")->required()->check(mesh_path);
  }
}

bool run_proximity_command(const ProximityArgs& args, std::ostream& out) {
  const bool distance = args.distance != nullptr && *args.distance;
  const bool penetration = args.penetration != nullptr && *args.penetration;
  if (!distance && !penetration) return false;
  if (args.a == "-" && args.b == "-") throw UsageError("only one input can be read from stdin");
  const ConvexSet a = read_operand(args.a);
  const ConvexSet b = read_operand(args.b);
  if (distance)
    run_distance(a, b, out);
  else
    run_penetration(a, b, out);
  return true;
}

}  // namespace cvms::cli
