// SPDX-License-Identifier: MIT
// Atomic file output for write_file: a failed write never destroys the
// user's file. Opening the target with truncation would lose it before the
// writer has checked or rounded anything (a sum written over one of its own
// inputs, then refused). So a regular file (or a new path) is written to a
// fresh temporary file in the target's directory, renamed over the target only once everything is written and
// closed; on any failure the temporary is removed and the target is
// untouched. A target that is not a regular file (/dev/null, a FIFO, a
// terminal) is written directly: it cannot be replaced, and there is nothing
// to lose; /dev/stdout, /dev/stderr, /dev/fd/N and /proc/self/fd/N are
// written through (a duplicate of) the descriptor they name.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

#include "cvms/io.hpp"

namespace cvms::io_detail {

/// Calls write(out) with a binary stream whose bytes end up in `path`, as
/// above. Exceptions of `write` propagate after the cleanup. The new file's
/// permissions are those of the file it replaces, or of any new file (0666
/// less the umask). With `times`, its `sync` is set to the wait for the disk
/// (fsync, rename) once the file is written; `total` is the caller's.
/// \throw Error(io) naming the path and the reason (the errno text) if the
///   target is a directory, the temporary cannot be created, or a write,
///   close or rename fails.
void write_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                      WriteTimes* times = nullptr);

}  // namespace cvms::io_detail
