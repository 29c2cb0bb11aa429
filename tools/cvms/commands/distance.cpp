// SPDX-License-Identifier: MIT
// `cvms distance A B`: the exact squared distance of A and B, its rounded
// square root, witness points and whether they intersect (proximity_report.hpp).
// Either operand may also be a solid that is not convex or a pieces file:
// it is then a union of convex pieces, the distance is the minimum over its
// pieces (ConvexUnion::squared_distance), and the piece that attains it is
// printed too, numbered from 1 as in a pieces file.
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "commands.hpp"
#include "cvms/proximity.hpp"
#include "json.hpp"
#include "options.hpp"
#include "proximity_report.hpp"
#include "usage_error.hpp"

namespace cvms::cli {
namespace {

struct DistanceArgs {
  std::string a, b;
  bool json = false;
};

// The distance and, for an operand that is a union, the piece (1-based)
// that attains it.
struct Answer {
  DistanceResult d;
  std::optional<std::size_t> piece_a, piece_b;
};

Answer distance(const AnyOperand& a, const AnyOperand& b) {
  const bool union_a = a.set.empty(), union_b = b.set.empty();
  if (!union_a && !union_b) return {squared_distance(a.set, b.set), {}, {}};
  if (union_a && union_b) {
    const UnionDistance u = a.pieces.squared_distance(b.pieces);
    return {u.distance, u.piece + 1, u.other_piece + 1};
  }
  if (union_a) {
    const UnionDistance u = a.pieces.squared_distance(b.set);
    return {u.distance, u.piece + 1, {}};
  }
  UnionDistance u = b.pieces.squared_distance(a.set);
  std::swap(u.distance.witness_a, u.distance.witness_b);
  return {u.distance, {}, u.piece + 1};
}

void run_distance(const DistanceArgs& args, std::ostream& out) {
  if (args.a == "-" && args.b == "-") throw UsageError("only one input can be read from stdin");
  const AnyOperand a = read_any_operand(args.a);
  const AnyOperand b = read_any_operand(args.b);
  const Answer answer = distance(a, b);
  const DistanceResult& d = answer.d;
  if (args.json) {
    JsonObject o(out);
    o.exact("squared_distance", d.squared_distance)
        .number("distance", nearest_double_sqrt(d.squared_distance))
        .point("witness_a", d.witness_a)
        .point("witness_b", d.witness_b)
        .boolean("intersect", d.intersect);
    if (answer.piece_a) o.integer("piece_a", static_cast<std::int64_t>(*answer.piece_a));
    if (answer.piece_b) o.integer("piece_b", static_cast<std::int64_t>(*answer.piece_b));
    o.end();
    return;
  }
  print_square_and_root(out, "squared_distance", "distance", d.squared_distance);
  print_point(out, "witness_a", d.witness_a);
  print_point(out, "witness_b", d.witness_b);
  print_intersect(out, d.intersect);
  if (answer.piece_a) out << "piece_a " << *answer.piece_a << "\n";
  if (answer.piece_b) out << "piece_b " << *answer.piece_b << "\n";
}

}  // namespace

void register_distance(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<DistanceArgs>();
  CLI::App* command =
      app.add_subcommand("distance", "exact squared distance of A and B, with witness points (also solids, pieces files)");
  add_operands(*command, args->a, args->b);
  command->add_flag("--json", args->json, "one JSON object: exact numbers as strings beside their nearest doubles");
  add_input_memory_option(*command);
  commands.push_back({command, [args] { run_distance(*args, std::cout); }});
}

}  // namespace cvms::cli
