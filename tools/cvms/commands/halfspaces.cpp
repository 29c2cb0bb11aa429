// SPDX-License-Identifier: MIT
// `cvms halfspaces P`: the minimal exact half-spaces of a convex set, as rows
// in the format of the output's extension.
#include <filesystem>
#include <memory>
#include <ostream>
#include <string>

#include "commands.hpp"
#include "cvms/halfspace_io.hpp"
#include "cvms/halfspaces.hpp"
#include "files.hpp"
#include "keep_until_exit.hpp"
#include "options.hpp"
#include "set_files.hpp"

namespace cvms::cli {
namespace {

struct HalfspacesArgs {
  std::string input, output = "-";
};

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

void run_halfspaces(const HalfspacesArgs& args) {
  ConvexSet set = read_set(args.input);
  write_rows(args.output, set);
  keep_until_exit(std::move(set));
}

}  // namespace

void register_halfspaces(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<HalfspacesArgs>();
  CLI::App* command = app.add_subcommand("halfspaces", "the minimal exact half-spaces of a convex set");
  command->add_option("P", args->input, "the set")->required()->check(mesh_path());
  command->add_option("-o,--output", args->output,
                      ".ine (cdd H-representation), .ext (cdd V-representation), other: 'a b c d' rows "
                      "(a*x + b*y + c*z <= d); '-': cdd on stdout");
  add_input_memory_option(*command);
  commands.push_back({command, [args] { run_halfspaces(*args); }});
}

}  // namespace cvms::cli
