// SPDX-License-Identifier: MIT
// Reading and writing the CLI's files: a path in the format of its extension,
// or "-" for OFF on stdin/stdout. Errors name the file.
#pragma once

#include <fstream>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/error.hpp"
#include "cvms/halfspaces.hpp"
#include "cvms/io.hpp"
#include "cvms/polygon_soup.hpp"
#include "cvms/vec.hpp"
#include "input_memory.hpp"

namespace cvms::cli {

/// The name used for a path in messages ("<stdin>" / "<stdout>" for "-").
std::string input_name(const std::string& path);

/// The limits every input is read with; --max-bytes and --max-line-bytes
/// change them before a command runs, and read_within_budget lowers
/// max_bytes to the memory budget's share.
ReadLimits& read_limits();

/// `text` with every control byte (escape sequences of a terminal, '\n',
/// '\r', DEL) shown as \xNN, so a file name cannot drive the terminal or
/// break the one-line message.
std::string printable(std::string_view text);

/// The format an output path is written in: `format` ("off", "obj", "stl")
/// if given, else OFF for "-" and for devices without an extension
/// (/dev/null, /dev/stdout, /dev/full, ...), else the path's extension. \throw UsageError when none of them
/// tells.
FileFormat output_format(const std::string& path, const std::string& format);

/// Runs `read` with the limits of input_read_limits(path, cost)
/// (input_memory.hpp: the memory a file is estimated to need is taken from
/// --max-memory first); a stream stopped by the budget is reported with the
/// option that raises it.
template <class Read>
auto read_within_budget(const std::string& path, InputCost cost, Read&& read) {
  const ReadLimits limits = input_read_limits(path, cost);
  try {
    return read(limits);
  } catch (const Error& e) {
    rethrow_with_memory_hint(e, limits, cost);
  }
}

/// Reads a polygon mesh; a cdd V-representation (.ext) is its points without
/// faces, as a points-only OFF. \throw Error naming the file.
PolygonSoup read_soup(const std::string& path);

/// cvms::read_polyhedron, or for "-" the same on stdin: every error names the
/// file ("<stdin>").
ConvexPolyhedron read_polyhedron(const std::string& path);

/// The rows of a half-space file (.ine cdd, other: plain rows), or cdd on
/// stdin for "-". \throw Error naming the file once ("<stdin>").
HalfspaceSystem read_halfspace_rows(const std::string& path);

/// Points for a hull: OFF/OBJ vertices or "x y z" lines; STL triangle
/// corners; the vertices of a cdd V-representation (.ext).
std::vector<Vec3> read_point_cloud(const std::string& path);

/// cvms::write_file (atomic: a failed write leaves an existing file as it
/// was), or stdout for "-", in output_format(path, format). With `times`,
/// the write's time and its wait for the disk (zero for stdout) go there.
/// \throw Error naming the file ("standard output" for "-") and the reason.
void write_polyhedron(const std::string& path, const ConvexPolyhedron& p, Coordinates coordinates,
                      const std::string& format = {}, VertexOrder order = VertexOrder::as_is,
                      WriteTimes* times = nullptr);

/// write_file of a soup (atomic), or stdout for "-", in output_format(path,
/// format). \throw Error naming the file ("standard output" for "-").
void write_soup(const std::string& path, const PolygonSoup& soup, Coordinates coordinates,
                const std::string& format = {});

/// Opens a file for reading. \throw Error(io) naming it, with the reason,
/// if it cannot be opened or is a directory.
std::ifstream open_input(const std::string& path);

/// The extension of a path in lower case (".off"), empty if none.
std::string lower_extension(const std::string& path);

/// True for a path ending in .ext (any case): cdd's V-representation, points.
bool is_cdd_points_path(const std::string& path);

/// Standard input must be open for reading and not a directory; otherwise a
/// read fails at once and would look like an empty input.
/// \throw Error(io) "cannot read standard input: <reason>".
void check_stdin();

/// True for "-" (stdin or stdout).
bool is_std_stream(const std::string& path);

/// Runs `write` on std::cout and flushes it.
/// \throw Error(io) "cannot write standard output: <reason>" if that fails.
void write_stdout(const std::function<void(std::ostream&)>& write);

/// Flushes std::cout and stdout: a command's last write to standard output
/// (a report, a result, help) is only known to have arrived then.
/// \throw Error(io) "cannot write standard output: <reason>" if any write to
/// it failed, earlier or now.
void finish_stdout();

/// Fails early, before a long computation, if the output's directory does
/// not exist or the output is a directory. \throw Error(io) naming the file.
void check_output_directory(const std::string& path);

/// Fails before any work if the output cannot be written: an unknown format
/// (a UsageError), a missing directory, a directory.
void check_output(const std::string& path, const std::string& format);

/// The coordinates --float asks for: exact rationals when it is not given
/// (empty), Coordinates::double_ for "nearest", Coordinates::double_outer
/// for "outer".
Coordinates coordinates_of(const std::string& float_output);

/// Empty if path is "-" or ends in .off/.obj/.stl/.ext (any case), else a message;
/// used as a CLI11 validator so a wrong extension is a usage error.
std::string check_mesh_path(const std::string& path);

}  // namespace cvms::cli
