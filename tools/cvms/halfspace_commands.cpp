// SPDX-License-Identifier: MIT
// The half-space subcommands (see the header).
#include "halfspace_commands.hpp"

#include <filesystem>
#include <iostream>

#include "commands.hpp"
#include "cvms/error.hpp"
#include "cvms/halfspace_io.hpp"
#include "cvms/halfspaces.hpp"
#include "files.hpp"
#include "keep_until_exit.hpp"
#include "set_commands.hpp"

namespace cvms::cli {

namespace {

bool is_vertex_file(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".ext" || ext == ".EXT";
}

// Rows to a file by extension (.ine cdd, .ext the vertices as cdd's
// V-representation, else plain), or cdd on stdout for "-".
void write_rows(const std::string& path, const ConvexSet& set) {
  if (is_std_stream(path)) {
    write_stdout([&](std::ostream& out) { write_halfspaces(out, to_halfspaces(set), HalfspaceFormat::cdd); });
    return;
  }
  check_output_directory(path);
  if (is_vertex_file(path)) {
    write_cdd_points_file(path, set);
    return;
  }
  write_halfspace_file(path, to_halfspaces(set));
}

HalfspaceSystem read_rows(const std::string& path) {
  if (!is_std_stream(path)) return read_halfspace_file(path, read_limits());
  return read_halfspaces(std::cin, HalfspaceFormat::cdd, "<stdin>", read_limits());
}

ConvexSet set_from_rows(const std::string& path) {
  try {
    return from_halfspaces(read_rows(path));
  } catch (const Error& e) {
    const std::string name = input_name(path);
    const std::string message = e.message();
    if (message.rfind(name, 0) == 0) throw;
    throw Error(e.category(), name + ": " + message);
  }
}

}  // namespace

void add_halfspace_commands(CLI::App& app, CLI::App& hull, CLI::Option& hull_points, const HullArgs& hull_args,
                            HalfspaceArgs& args, const CLI::Validator& mesh_path) {
  args.diff = app.add_subcommand("diff", "Pontryagin difference A - B = {x : x + B inside A}, exact, any dimension");
  args.diff->add_option("A", args.a, "the set eroded")->required()->check(mesh_path);
  args.diff->add_option("B", args.b, "the set it is eroded by")->required()->check(mesh_path);
  args.diff->add_option("-o,--output", args.output, "output file (.off/.obj/.stl), '-' for OFF on stdout");
  args.diff->add_option("--format", args.format, "output format off|obj|stl (default: from the extension)");
  args.diff->add_flag("--float", args.float_output, "write nearest doubles instead of exact rationals");

  args.halfspaces = app.add_subcommand("halfspaces", "the minimal exact half-spaces of a convex set");
  args.halfspaces->add_option("P", args.rows_input, "the set")->required()->check(mesh_path);
  args.halfspaces->add_option("-o,--output", args.rows_output,
                              ".ine (cdd H-representation), .ext (cdd V-representation), other: 'a b c d' rows "
                              "(a*x + b*y + c*z <= d); '-': cdd on stdout");

  hull_points.required(false);
  args.hull = &hull;
  args.hull_args = &hull_args;
  hull.add_option("--from-halfspaces", args.rows_input,
                  "the set bounded by the rows of this file (.ine cdd, other: 'a b c d' rows) instead of POINTS")
      ->excludes(&hull_points);
}

bool run_halfspace_command(const HalfspaceArgs& args, std::ostream& out) {
  if (args.diff != nullptr && *args.diff) {
    if (args.a == "-" && args.b == "-") throw UsageError("only one input can be read from stdin");
    (void)output_format(args.output, args.format);
    check_output_directory(args.output);
    ConvexSet a = read_set(args.a), b = read_set(args.b);
    ConvexSet d = pontryagin_difference(a, b);
    write_set(args.output, d, args.float_output ? Coordinates::double_ : Coordinates::exact, args.format);
    report_set("difference", d, args.output == "-" ? std::cerr : out);
    keep_until_exit(std::move(a));
    keep_until_exit(std::move(b));
    keep_until_exit(std::move(d));
    return true;
  }
  if (args.halfspaces != nullptr && *args.halfspaces) {
    ConvexSet set = read_set(args.rows_input);
    write_rows(args.rows_output, set);
    keep_until_exit(std::move(set));
    return true;
  }
  if (args.hull != nullptr && *args.hull) {
    const HullArgs& hull = *args.hull_args;
    if (args.rows_input.empty()) {
      if (hull.input.empty()) throw UsageError("hull needs POINTS or --from-halfspaces");
      return false;  // the ordinary hull of points
    }
    (void)output_format(hull.output, hull.format);
    check_output_directory(hull.output);
    ConvexSet set = set_from_rows(args.rows_input);
    write_set(hull.output, set, hull.float_output ? Coordinates::double_ : Coordinates::exact, hull.format);
    keep_until_exit(std::move(set));
    return true;
  }
  return false;
}

}  // namespace cvms::cli
