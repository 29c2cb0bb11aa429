// SPDX-License-Identifier: MIT
// Command-line options that several commands share, so that each is spelled,
// checked and explained the same way wherever it appears.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

#include "cvms/minkowski.hpp"

namespace cvms::cli {

/// Accepts "-" or a path ending in .off, .obj, .stl or .ply (files.hpp's check_mesh_path).
const CLI::Validator& mesh_path();

/// Accepts a decimal integer from 0 to 2^64-1, digits only.
const CLI::Validator& unsigned_64();

/// --max-bytes and --max-line-bytes, which set read_limits() (files.hpp) for
/// every command that reads; added to the top-level app, they may stand
/// before or after the command name.
void add_read_limit_options(CLI::App& app);

/// The operands A and B, both required paths of a set in any form (set_files.hpp).
void add_operands(CLI::App& command, std::string& a, std::string& b);

/// --float[=nearest|outer] into `float_output` (empty when not given; see
/// coordinates_of in files.hpp).
void add_float_option(CLI::App& command, std::string& float_output);

/// -o, --format and --float of a command that writes a polyhedron. The
/// output is checked when the command runs (its format may come from
/// --format), before any work.
void add_output_options(CLI::App& command, std::string& output, std::string& format, std::string& float_output);

/// --max-memory SIZE into `bytes` (whose value is the default shown) and
/// into memory_budget() (input_memory.hpp), which the inputs are read
/// within: the memory the inputs or the output of `what` ("an input or a
/// sum whose output") may be estimated to need.
void add_max_memory_option(CLI::App& command, std::uint64_t& bytes, const std::string& what);

/// --max-memory SIZE into memory_budget(), for a command whose only estimate
/// is that of its inputs.
void add_input_memory_option(CLI::App& command);

/// --algorithm: cvms, essdms or chms; the default is the library's.
void add_algorithm_option(CLI::App& command, Algorithm& algorithm);

}  // namespace cvms::cli
