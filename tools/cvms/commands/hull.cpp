// SPDX-License-Identifier: MIT
// `cvms hull POINTS` (the exact convex hull of points) and `cvms hull
// --from-halfspaces ROWS` (the set the rows bound): one of the two is needed.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/halfspace_io.hpp"
#include "cvms/halfspaces.hpp"
#include "files.hpp"
#include "keep_until_exit.hpp"
#include "options.hpp"
#include "progress_line.hpp"
#include "set_files.hpp"
#include "usage_error.hpp"

namespace cvms::cli {
namespace {

struct HullArgs {
  std::string input, output = "-";
  std::string format;  ///< --format, empty: from the output path
  std::string float_output;  ///< --float: empty, "nearest" or "outer"
  std::string rows_input;  ///< --from-halfspaces
  bool progress = false;   ///< --progress
};

// The readers name the file in their errors; from_halfspaces does not.
ConvexSet set_from_rows(const std::string& path, bool progress) {
  HalfspaceSystem rows = read_halfspace_rows(path);
  try {
    return from_halfspaces(rows, progress_callback(progress));
  } catch (const Error& e) {
    throw Error(e.category(), input_name(path) + ": " + e.message());
  }
}

// Flat, collinear or single-point clouds give the set they span.
void hull_of_points(const HullArgs& args) {
  check_output(args.output, args.format);
  std::vector<Vec3> points = read_point_cloud(args.input);
  ConvexSet hull = convex_hull_set(points, progress_callback(args.progress));
  write_set(args.output, hull, coordinates_of(args.float_output), args.format);
  keep_until_exit(std::move(hull));
  keep_until_exit(std::move(points));
}

void hull_from_halfspaces(const HullArgs& args) {
  check_output(args.output, args.format);
  ConvexSet set = set_from_rows(args.rows_input, args.progress);
  write_set(args.output, set, coordinates_of(args.float_output), args.format);
  keep_until_exit(std::move(set));
}

void run_hull(const HullArgs& args) {
  if (!args.rows_input.empty()) return hull_from_halfspaces(args);
  if (args.input.empty()) throw UsageError("hull needs POINTS or --from-halfspaces");
  hull_of_points(args);
}

}  // namespace

void register_hull(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<HullArgs>();
  CLI::App* command = app.add_subcommand("hull", "exact convex hull of points");
  CLI::Option* points = command->add_option("POINTS", args->input, "OFF/OBJ/STL/PLY vertices, cdd .ext vertices or one 'x y z' per line");
  add_output_options(*command, args->output, args->format, args->float_output);
  command
      ->add_option("--from-halfspaces", args->rows_input,
                   "the set bounded by the rows of this file (.ine cdd, other: 'a b c d' rows) instead of POINTS")
      ->excludes(points);
  add_progress_option(*command, args->progress);
  add_input_memory_option(*command);
  commands.push_back({command, [args] { run_hull(*args); }});
}

}  // namespace cvms::cli
