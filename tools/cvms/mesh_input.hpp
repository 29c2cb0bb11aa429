// SPDX-License-Identifier: MIT
// A mesh operand's bytes, read once and parsed from memory as often as the
// command needs: `cvms sum` and `cvms check` try an input as a convex set
// and, when it is not one, tell a pieces file (an OBJ of several objects)
// from a solid and validate the solid. Reading the file again for each of those, or
// copying the parsed soup in case it is needed, costs on every run what
// only a refused or non-convex operand needs; bytes in memory cost a
// parse on that path alone. A regular file is read with one read() of the
// size fstat gives; standard input in chunks.
#pragma once

#include <string>

#include "cvms/io.hpp"
#include "cvms/polygon_soup.hpp"
#include "cvms/union_io.hpp"

namespace cvms::cli {

/// An input's bytes with what parsing them needs.
struct MeshInput {
  std::string path;    ///< as given ("-": standard input)
  FileFormat format = FileFormat::off;  ///< the extension's (OFF on standard input)
  ReadLimits limits;   ///< those of input_read_limits(path, InputCost::mesh)
  std::string bytes;   ///< at most limits.max_bytes + 1: a longer input fails in the parser, located
};

/// Reads a mesh input (a file in a format of its extension, or OFF on
/// stdin for "-") within the memory budget (input_memory.hpp).
/// \throw Error(io) naming the file as read_file does ("cannot open ...",
///   "cannot read ...: it is a directory") or standard input; Error(limit)
///   from the budget.
MeshInput read_mesh_input(const std::string& path);

/// The soup the bytes hold, as read_file (or read_off on stdin) would give.
/// \throw Error as the reader, naming the file and line; a stream longer
///   than the budget's share names the option that raises it.
PolygonSoup parse_soup(const MeshInput& input);

/// True for an OBJ of two or more `o` statements (a pieces file, read with
/// read_pieces).
bool holds_pieces(const MeshInput& input);

/// The pieces the bytes hold, as read_pieces_file would give.
/// \throw Error as read_pieces, naming the file.
ConvexUnion read_pieces_text(const MeshInput& input);

}  // namespace cvms::cli
