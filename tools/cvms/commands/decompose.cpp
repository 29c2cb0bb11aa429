// SPDX-License-Identifier: MIT
// `cvms decompose A -o pieces.obj`: validates A as a solid (convex or not),
// cuts it into interior-disjoint convex pieces (convex_decomposition) and
// writes them as a pieces file, one OBJ object per piece. Reports the solid
// (solid_report.hpp), the piece count and the time of the decomposition:
// on stdout, or on stderr when the pieces go to stdout.
#include <chrono>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "cvms/decomposition.hpp"
#include "cvms/error.hpp"
#include "files.hpp"
#include "json.hpp"
#include "options.hpp"
#include "pieces_files.hpp"
#include "progress_line.hpp"
#include "reports.hpp"
#include "solid_report.hpp"

namespace cvms::cli {
namespace {

struct DecomposeArgs {
  std::string input, output = "-";
  std::string float_output;  ///< --float: empty, "nearest" or "outer"
  bool json = false;
  bool progress = false;  ///< --progress
  DecompositionOptions options;
};

void run_decompose(DecomposeArgs args, std::ostream& report) {
  check_pieces_output(args.output);
  args.options.progress = progress_callback(args.progress);
  const Solid solid = solid_from_soup(read_soup(args.input), input_name(args.input));
  const auto start = std::chrono::steady_clock::now();
  ConvexUnion pieces;
  try {
    pieces = convex_decomposition(solid, args.options);
  } catch (const Error& e) {
    rethrow_with_pieces_limit_hint(e);
  }
  const auto time = std::chrono::steady_clock::now() - start;
  write_pieces_output(args.output, pieces, coordinates_of(args.float_output));
  if (!args.json) {
    report_solid(input_name(args.input), solid, pieces.size(), report);
    report << "time: " << milliseconds(time) << "\n";
    return;
  }
  JsonObject o(report);
  add_solid_members(o, input_name(args.input), solid, pieces.size());
  o.number("time_ms", std::chrono::duration<double, std::milli>(time).count()).end();
}

}  // namespace

void register_decompose(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<DecomposeArgs>();
  CLI::App* command =
      app.add_subcommand("decompose", "cut a solid into convex pieces, written as one OBJ object per piece");
  command->add_option("A", args->input, "the solid (convex or not)")->required()->check(mesh_path());
  command->add_option("-o,--output", args->output, "pieces file, .obj (default -, OBJ on stdout)")->default_str("-");
  add_float_option(*command, args->float_output);
  command->add_flag("--json", args->json, "report as one JSON object: exact numbers as strings beside their doubles");
  add_decomposition_limit_options(*command, args->options.limits);
  add_progress_option(*command, args->progress);
  commands.push_back(
      {command, [args] { run_decompose(*args, args->output == "-" ? std::cerr : std::cout); }});
}

}  // namespace cvms::cli
