// SPDX-License-Identifier: MIT
// `cvms penetration A B`: the exact squared penetration depth of A and B,
// its rounded square root, the direction, witness points and whether they
// intersect (proximity_report.hpp).
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "cvms/proximity.hpp"
#include "json.hpp"
#include "options.hpp"
#include "proximity_report.hpp"

namespace cvms::cli {
namespace {

struct PenetrationArgs {
  std::string a, b;
  bool json = false;
};

void run_penetration(const PenetrationArgs& args, std::ostream& out) {
  const Operands operands =
      read_operands(args.a, args.b, "the penetration depth is computed for convex sets only (cvms distance takes it)");
  const PenetrationResult p = penetration(operands.a, operands.b);
  if (args.json) {
    JsonObject(out)
        .exact("squared_depth", p.squared_depth)
        .number("depth", nearest_double_sqrt(p.squared_depth))
        .point("direction", p.direction)
        .point("witness_a", p.witness_a)
        .point("witness_b", p.witness_b)
        .boolean("intersect", p.intersect)
        .end();
    return;
  }
  print_square_and_root(out, "squared_depth", "depth", p.squared_depth);
  print_point(out, "direction", p.direction);
  print_point(out, "witness_a", p.witness_a);
  print_point(out, "witness_b", p.witness_b);
  print_intersect(out, p.intersect);
}

}  // namespace

void register_penetration(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<PenetrationArgs>();
  CLI::App* command =
      app.add_subcommand("penetration", "exact squared penetration depth of A and B, direction and witnesses");
  add_operands(*command, args->a, args->b);
  command->add_flag("--json", args->json, "one JSON object: exact numbers as strings beside their nearest doubles");
  add_input_memory_option(*command);
  commands.push_back({command, [args] { run_penetration(*args, std::cout); }});
}

}  // namespace cvms::cli
