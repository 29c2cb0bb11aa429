// SPDX-License-Identifier: MIT
// The commands of the cvms tool, one file each in commands/. A register
// function adds its command to the command line and records what the
// command does; main runs that for the one command the line selected, once
// the whole line has parsed. Each command is a thin layer over the library:
// read, call one library function, write, report.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <vector>

namespace cvms::cli {

/// A command on the command line and what it does when selected.
struct Command {
  const CLI::App* app;
  std::function<void()> run;
};
using Commands = std::vector<Command>;

/// A + B [+ C ...] of convex sets of any dimension.
void register_sum(CLI::App& app, Commands& commands);
/// The convex hull of points, or the set bounded by half-spaces (--from-halfspaces).
void register_hull(CLI::App& app, Commands& commands);
/// A built-in shape.
void register_gen(CLI::App& app, Commands& commands);
/// Validates a convex set and prints its sizes.
void register_check(CLI::App& app, Commands& commands);
/// Cube + Sphere4 with counts and time.
void register_demo(CLI::App& app, Commands& commands);
/// The exact squared distance of A and B.
void register_distance(CLI::App& app, Commands& commands);
/// The exact squared penetration depth of A and B.
void register_penetration(CLI::App& app, Commands& commands);
/// The Pontryagin difference A - B.
void register_diff(CLI::App& app, Commands& commands);
/// The minimal half-spaces of a convex set.
void register_halfspaces(CLI::App& app, Commands& commands);
/// A solid cut into convex pieces, written as a pieces file.
void register_decompose(CLI::App& app, Commands& commands);

}  // namespace cvms::cli
