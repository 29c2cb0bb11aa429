// SPDX-License-Identifier: MIT
// `cvms distance A B`: the exact squared distance of A and B, its rounded
// square root, witness points and whether they intersect (proximity_report.hpp).
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

void run_distance(const std::string& a_path, const std::string& b_path, std::ostream& out) {
  const Operands operands = read_operands(a_path, b_path);
  const DistanceResult d = squared_distance(operands.a, operands.b);
  print_square_and_root(out, "squared_distance", "distance", d.squared_distance);
  print_point(out, "witness_a", d.witness_a);
  print_point(out, "witness_b", d.witness_b);
  print_intersect(out, d.intersect);
}

}  // namespace

void register_distance(CLI::App& app, Commands& commands) {
  auto paths = std::make_shared<std::pair<std::string, std::string>>();
  CLI::App* command = app.add_subcommand("distance", "exact squared distance of A and B, with witness points");
  add_operands(*command, paths->first, paths->second);
  commands.push_back({command, [paths] { run_distance(paths->first, paths->second, std::cout); }});
}

}  // namespace cvms::cli
