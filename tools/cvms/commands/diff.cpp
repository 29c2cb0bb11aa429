// SPDX-License-Identifier: MIT
// `cvms diff A B`: the exact Pontryagin difference A - B = {x : x + B inside A}
// of convex sets of any dimension, written as a set, reported as check does.
// A and B come in any form of set_files.hpp (meshes, points, cdd or plain
// rows) and so does the output: the tightened rows of a tube MPC controller
// are one command from the state and disturbance sets. When both are files
// of the plane, the difference lies in z = 0 and is written back as one.
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "cvms/error.hpp"
#include "cvms/halfspaces.hpp"
#include "files.hpp"
#include "keep_until_exit.hpp"
#include "options.hpp"
#include "progress_line.hpp"
#include "reports.hpp"
#include "set_files.hpp"
#include "usage_error.hpp"

namespace cvms::cli {
namespace {

struct DiffArgs {
  std::string a, b, output = "-", format;
  std::string float_output;  ///< --float: empty, "nearest" or "outer"
  bool progress = false;  ///< --progress
};

// The report goes to stderr when the difference goes to stdout.
void run_diff(const DiffArgs& args) {
  if (args.a == "-" && args.b == "-") throw UsageError("only one input can be read from stdin");
  check_set_output(args.output, args.format, args.float_output);
  SetFile a_file = read_set_file(args.a), b_file = read_set_file(args.b);
  ConvexSet a = std::move(a_file.set), b = std::move(b_file.set);
  if (b.empty())
    throw Error(ErrorCategory::invalid_argument,
                input_name(args.b) + ": B is empty (the difference A - B would be all of space)");
  ConvexSet d = pontryagin_difference(a, b, progress_callback(args.progress));
  const int dimension = a_file.dimension == 2 && b_file.dimension == 2 ? 2 : 3;
  write_set_file(args.output, d, dimension, coordinates_of(args.float_output), args.format);
  report_set("difference", d, args.output == "-" ? std::cerr : std::cout);
  keep_until_exit(std::move(a));
  keep_until_exit(std::move(b));
  keep_until_exit(std::move(d));
}

}  // namespace

void register_diff(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<DiffArgs>();
  CLI::App* command =
      app.add_subcommand("diff", "Pontryagin difference A - B = {x : x + B inside A}, exact, any dimension");
  command->add_option("A", args->a, "the set eroded")->required()->check(set_path());
  command->add_option("B", args->b, "the set it is eroded by")->required()->check(set_path());
  command->add_option("-o,--output", args->output,
                      "output file, its form by extension as for A and B (.ine, .rows: the tightened rows); "
                      "'-' for OFF on stdout; 2-D when A and B are files of the plane");
  command->add_option("--format", args->format, "output format off|obj|stl|ply (default: from the extension)");
  add_float_option(*command, args->float_output);
  add_progress_option(*command, args->progress);
  add_input_memory_option(*command);
  commands.push_back({command, [args] { run_diff(*args); }});
}

}  // namespace cvms::cli
