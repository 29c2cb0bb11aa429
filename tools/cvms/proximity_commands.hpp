// SPDX-License-Identifier: MIT
// The proximity subcommands of the cvms tool: `distance A B` and
// `penetration A B` (issue 17). Kept apart from commands.hpp so that they
// register and run through two calls in main.cpp.
#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <string>

namespace cvms::cli {

struct ProximityArgs {
  std::string a, b;
  CLI::App* distance = nullptr;
  CLI::App* penetration = nullptr;
};

/// Adds `distance` and `penetration` to app; both take two mesh paths
/// checked by `mesh_path`.
void add_proximity_commands(CLI::App& app, ProximityArgs& args, const CLI::Validator& mesh_path);

/// Runs the proximity subcommand that was selected, printing its report to
/// out; false if neither was selected.
bool run_proximity_command(const ProximityArgs& args, std::ostream& out);

}  // namespace cvms::cli
