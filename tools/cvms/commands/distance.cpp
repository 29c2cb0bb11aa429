// SPDX-License-Identifier: MIT
// `cvms distance A B`: the exact squared distance of A and B, its rounded
// square root, witness points and whether they intersect (proximity_report.hpp).
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

struct DistanceArgs {
  std::string a, b;
  bool json = false;
};

void run_distance(const DistanceArgs& args, std::ostream& out) {
  const Operands operands = read_operands(args.a, args.b);
  const DistanceResult d = squared_distance(operands.a, operands.b);
  if (args.json) {
    JsonObject(out)
        .exact("squared_distance", d.squared_distance)
        .number("distance", nearest_double_sqrt(d.squared_distance))
        .point("witness_a", d.witness_a)
        .point("witness_b", d.witness_b)
        .boolean("intersect", d.intersect)
        .end();
    return;
  }
  print_square_and_root(out, "squared_distance", "distance", d.squared_distance);
  print_point(out, "witness_a", d.witness_a);
  print_point(out, "witness_b", d.witness_b);
  print_intersect(out, d.intersect);
}

}  // namespace

void register_distance(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<DistanceArgs>();
  CLI::App* command = app.add_subcommand("distance", "exact squared distance of A and B, with witness points");
  add_operands(*command, args->a, args->b);
  command->add_flag("--json", args->json, "one JSON object: exact numbers as strings beside their nearest doubles");
  add_input_memory_option(*command);
  commands.push_back({command, [args] { run_distance(*args, std::cout); }});
}

}  // namespace cvms::cli
