// SPDX-License-Identifier: MIT
// `cvms penetration A B`: the exact squared penetration depth of A and B,
// its rounded square root, the direction, witness points and whether they
// intersect (proximity_report.hpp).
#include <iostream>
#include <memory>
#include <string>
#include <utility>

#include "commands.hpp"
#include "cvms/proximity.hpp"
#include "options.hpp"
#include "proximity_report.hpp"

namespace cvms::cli {
namespace {

void run_penetration(const std::string& a_path, const std::string& b_path, std::ostream& out) {
  const Operands operands = read_operands(a_path, b_path);
  const PenetrationResult p = penetration(operands.a, operands.b);
  print_square_and_root(out, "squared_depth", "depth", p.squared_depth);
  print_point(out, "direction", p.direction);
  print_point(out, "witness_a", p.witness_a);
  print_point(out, "witness_b", p.witness_b);
  print_intersect(out, p.intersect);
}

}  // namespace

void register_penetration(CLI::App& app, Commands& commands) {
  auto paths = std::make_shared<std::pair<std::string, std::string>>();
  CLI::App* command =
      app.add_subcommand("penetration", "exact squared penetration depth of A and B, direction and witnesses");
  add_operands(*command, paths->first, paths->second);
  commands.push_back({command, [paths] { run_penetration(paths->first, paths->second, std::cout); }});
}

}  // namespace cvms::cli
