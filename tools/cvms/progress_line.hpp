// SPDX-License-Identifier: MIT
// The progress callback of the long commands (sum, hull, diff): it stops
// the library's work once Ctrl-C was pressed (interrupt.hpp) and, when asked
// to, shows how far the work is on stderr. Shown by default only when
// stderr is a terminal, so that scripts and tests see the same output as
// ever; --progress shows it anyway. On a terminal each stage is one line,
// rewritten in place (carriage return) at most ten times a second; elsewhere
// (--progress into a file or a pipe) one line a second at most, and one at
// each stage's end.
#pragma once

#include <CLI/CLI.hpp>

#include "cvms/progress.hpp"

namespace cvms::cli {

/// Adds --progress (force the progress line) to a long command.
void add_progress_option(CLI::App& command, bool& forced);

/// The callback for a long command: catches Ctrl-C (catch_interrupt) and
/// returns false once it came; shows the progress on stderr when `forced`
/// or stderr is a terminal.
ProgressCallback progress_callback(bool forced);

/// Ends a progress line left open on the terminal (by an error or Ctrl-C in
/// the middle of a stage), so that what follows starts on a line of its own.
void finish_progress_line();

}  // namespace cvms::cli
