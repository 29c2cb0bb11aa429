// SPDX-License-Identifier: MIT
// Entry point of the `cvms` command-line tool: registers the commands
// (commands.hpp), parses the command line with CLI11, runs the command it
// selects and maps outcomes to exit codes: 0 success, 1 bad input (one line
// on stderr, from the library's Error), 2 usage, 130 interrupted by Ctrl-C
// (interrupt.hpp).
#include <gmp.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <new>
#include <string>

#include "commands.hpp"
#include "cvms/error.hpp"
#include "files.hpp"
#include "heap_pages.hpp"
#include "interrupt.hpp"
#include "options.hpp"
#include "progress_line.hpp"
#include "usage_error.hpp"

namespace {

constexpr int exit_bad_input = 1;
constexpr int exit_usage = 2;

// One line, whatever the message holds, and no control bytes: a file name
// with terminal escape codes is shown as \x1b[..., never run.
std::string one_line(const std::string& text) { return cvms::cli::printable(text); }

// --version: the project's version (CMake's project(VERSION)), the version
// of the GMP library running (gmp_version, which may differ from the one
// built against) and the build type.
std::string version_text() {
  return std::string("cvms ") + CVMS_VERSION + "\nGMP " + gmp_version + "\nbuild type: " + CVMS_BUILD_TYPE;
}

// In the order --help lists them.
cvms::cli::Commands register_commands(CLI::App& app) {
  using namespace cvms::cli;
  Commands commands;
  register_sum(app, commands);
  register_hull(app, commands);
  register_gen(app, commands);
  register_check(app, commands);
  register_demo(app, commands);
  register_distance(app, commands);
  register_penetration(app, commands);
  register_diff(app, commands);
  register_halfspaces(app, commands);
  register_decompose(app, commands);
  return commands;
}

// Runs the selected command; a Ctrl-C that stopped it (Error(cancelled)
// from the progress callback) is exit 130, other errors propagate.
int run_interruptible(const cvms::cli::Commands& commands) {
  try {
    for (const cvms::cli::Command& command : commands)
      if (*command.app) command.run();
    // Every command may write to stdout (results, reports): output lost on
    // the way (a full disk, a closed pipe) is an error, never a success.
    cvms::cli::finish_stdout();
  } catch (const cvms::Error& e) {
    cvms::cli::finish_progress_line();
    if (e.category() != cvms::ErrorCategory::cancelled) throw;
    std::cerr << "cvms: interrupted; nothing was written\n";  // the callback stops only on Ctrl-C
    return cvms::cli::exit_interrupted;
  } catch (...) {
    cvms::cli::finish_progress_line();
    throw;
  }
  if (cvms::cli::interrupted()) {  // Ctrl-C after the last report: the write was atomic and is complete
    std::cerr << "cvms: interrupted after the output was written\n";
    return cvms::cli::exit_interrupted;
  }
  return 0;
}

int run_selected(const cvms::cli::Commands& commands) {
  try {
    return run_interruptible(commands);
  } catch (const cvms::cli::UsageError& e) {
    std::cerr << "cvms: " << one_line(e.what()) << "\nRun with --help for more information.\n";
    return exit_usage;
  } catch (const cvms::Error& e) {
    std::cerr << "cvms: " << one_line(e.what()) << "\n";
    return exit_bad_input;
  } catch (const std::bad_alloc&) {
    std::cerr << "cvms: out of memory\n";
    return exit_bad_input;
  } catch (const std::exception& e) {
    std::cerr << "cvms: internal error: " << one_line(e.what()) << "\n";
    return exit_bad_input;
  }
}

}  // namespace

int main(int argc, char** argv) {
  cvms::cli::prefer_huge_heap_pages();
  CLI::App app{"cvms: exact Minkowski sums of convex polyhedra (OFF/OBJ/STL/PLY; '-' is OFF on stdin/stdout)"};
  app.set_version_flag("--version", version_text(), "print the versions of cvms and GMP and the build type");
  app.require_subcommand(1);  // exactly one
  app.fallthrough();          // the read limits may follow the command name too
  cvms::cli::add_read_limit_options(app);
  const cvms::cli::Commands commands = register_commands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help, or the error with a hint
    if (code != 0) return exit_usage;
    try {
      cvms::cli::finish_stdout();  // the help text, when stdout cannot take it
    } catch (const cvms::Error& lost) {
      std::cerr << "cvms: " << one_line(lost.what()) << "\n";
      return exit_bad_input;
    }
    return 0;
  }
  return run_selected(commands);
}
