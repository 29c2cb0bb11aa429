// SPDX-License-Identifier: MIT
// The half-space subcommands of the cvms tool (issue 16): `diff A B`
// (Pontryagin difference), `halfspaces P` (the minimal rows of a set) and
// `hull --from-halfspaces ROWS` (the set the rows bound). Kept apart from
// commands.hpp so that they register and run through two calls in main.cpp.
#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <string>

#include "commands.hpp"

namespace cvms::cli {

struct HalfspaceArgs {
  std::string a, b, output = "-", format;
  bool float_output = false;
  std::string rows_input;      ///< halfspaces: the set; hull: --from-halfspaces
  std::string rows_output = "-";
  CLI::App* diff = nullptr;
  CLI::App* halfspaces = nullptr;
  CLI::App* hull = nullptr;
  const HullArgs* hull_args = nullptr;  ///< the hull's POINTS (now optional) and output
};

/// Adds `diff` and `halfspaces` to app, and `--from-halfspaces` to the hull
/// command (whose POINTS option becomes optional: one of the two is needed).
void add_halfspace_commands(CLI::App& app, CLI::App& hull, CLI::Option& hull_points, const HullArgs& hull_args,
                            HalfspaceArgs& args, const CLI::Validator& mesh_path);

/// Runs the selected half-space command (reports to out, or to std::cerr
/// when the result goes to stdout); false if none was selected.
/// \throw UsageError for `hull` with neither POINTS nor --from-halfspaces.
bool run_halfspace_command(const HalfspaceArgs& args, std::ostream& out);

}  // namespace cvms::cli
