// SPDX-License-Identifier: MIT
// Ctrl-C for the long commands. The library never stops on its own, and a
// process killed by SIGINT in the middle of its work skips every destructor;
// so while a long command computes, SIGINT only sets a flag, which the
// command's progress callback (progress_line.hpp) reads at the library's
// next report (a millisecond or so later), returning false: the library
// throws Error(cancelled), unwinds, and main exits with 130 before anything
// is written, the output file untouched. The handler is installed for one
// signal: a second Ctrl-C (before the first is seen, e.g. while the inputs
// are still being read) ends the process the default way, which is safe too
// before the write has begun.
#pragma once

namespace cvms::cli {

/// Makes SIGINT set the flag interrupted() reads, once (the next SIGINT
/// has the default effect). Idempotent.
void catch_interrupt();

/// True once SIGINT arrived after catch_interrupt().
bool interrupted() noexcept;

/// The exit code of a command stopped by SIGINT (128 + SIGINT, what a
/// shell reports for a process the signal ended).
inline constexpr int exit_interrupted = 130;

}  // namespace cvms::cli
