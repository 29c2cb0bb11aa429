// SPDX-License-Identifier: MIT
/// \file
/// Half-space and vertex files, read and written exactly:
///  - cdd's H-representation (`.ine`): optional `H-representation` and
///    `linearity k i1 ... ik` lines (before `begin` or after `end`), `begin`,
///    `m 4 integer|rational|real`, m rows `b c_x c_y c_z` each meaning
///    b + c·x >= 0 (so a·x <= b with a = −c), `end`; the rows listed in
///    `linearity` (1-based) are equalities. Lines starting with `*` are
///    comments; anything after `end` other than `linearity` is ignored
///    (cdd's LP options). Every number is read exactly, whatever the type
///    word says ("real" decimals too).
///  - cdd's V-representation (`.ext`): `V-representation`, `begin`,
///    `m 4 ...`, rows `1 x y z` (vertices), `end`. Rays (`0 x y z`) and
///    linearity (lines) are refused: the sets here are bounded.
///  - a plain text form: one row `a b c d` per line meaning
///    a·x + b·y + c·z <= d; `#` starts a comment; an equality is written
///    as two opposite rows.
/// Hostile input: every error is Error(parse) or Error(limit) naming the
/// source and line; nothing is allocated from a header count (rows are
/// counted as they come and compared with the header at `end`); the limits
/// of cvms/io.hpp (ReadLimits) bound lines, numbers and rows.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string_view>
#include <vector>

#include "cvms/halfspaces.hpp"
#include "cvms/io.hpp"

namespace cvms {

/// Which text form of half-spaces.
enum class HalfspaceFormat {
  cdd,    ///< cdd's H-representation (.ine)
  plain,  ///< one row `a b c d` per line: a·x + b·y + c·z <= d
};

/// The format of a path: `.ine` is cdd, anything else plain.
HalfspaceFormat halfspace_format_from_extension(const std::filesystem::path& path);

/// Reads a system of half-spaces (see the file comment). At most
/// limits.max_faces rows.
/// \throw Error(parse) naming the source and line for malformed input (a
///   missing `begin` or `end`, a row of the wrong length, a bad number, a row
///   count unlike the header's, a linearity index out of range, a
///   V-representation), Error(limit) for input beyond the limits.
HalfspaceSystem read_halfspaces(std::istream& in, HalfspaceFormat format, std::string_view source = "<stream>",
                                const ReadLimits& limits = {});

/// Reads a file of half-spaces, its format by extension.
/// \throw Error(io) if it cannot be opened, and the errors of read_halfspaces.
HalfspaceSystem read_halfspace_file(const std::filesystem::path& path, const ReadLimits& limits = {});

/// Writes the system exactly: cdd with type `integer` when every number is
/// an integer, else `rational`, equalities first and listed in `linearity`;
/// plain with each equality as two rows.
void write_halfspaces(std::ostream& out, const HalfspaceSystem& system, HalfspaceFormat format);

/// Writes a file of half-spaces, its format by extension, atomically (see
/// write_file in cvms/io.hpp).
/// \throw Error(io) naming the path if it cannot be written.
void write_halfspace_file(const std::filesystem::path& path, const HalfspaceSystem& system);

/// Reads the points of a cdd V-representation (`.ext`).
/// \throw Error(parse) naming the source and line for malformed input, a
///   ray or a linearity line; Error(limit) beyond limits.max_vertices or the
///   other limits.
std::vector<Vec3> read_cdd_points(std::istream& in, std::string_view source = "<stream>",
                                  const ReadLimits& limits = {});

/// Writes the vertices of the set as a cdd V-representation (type
/// `integer` or `rational`); the empty set gives `0 4` rows.
void write_cdd_points(std::ostream& out, const ConvexSet& set);

/// write_cdd_points to a file, atomically (see write_file in cvms/io.hpp).
/// \throw Error(io) naming the path if it cannot be written.
void write_cdd_points_file(const std::filesystem::path& path, const ConvexSet& set);

}  // namespace cvms
