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
///  - a plain point list (read_plain_points): one `x y z` per line, `#`
///    comments.
/// Files of the plane: every form above also comes with one column fewer
/// (cdd `m 3`: rows `b c_x c_y`, vertices `1 x y`; plain rows `a b c`
/// meaning a·x + b·y <= c; points `x y`), the dimension set by the header
/// (cdd) or the first row (plain) and kept by every row. Such a file
/// describes a set in the plane z = 0 of space: points get z = 0, and rows
/// get a zero z coefficient plus the equality z == 0 (so from_halfspaces
/// gives the polygon, not a prism). Writers given dimension 2 write a set
/// in that plane back in the same form.
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

/// A system read from a file and the dimension of the file: 3, or 2 for a
/// file of the plane, whose system has the equality z == 0 first (see the
/// file comment).
struct HalfspaceFile {
  HalfspaceSystem system;  ///< in space, whatever the file's dimension
  int dimension = 3;       ///< 2 or 3
};

/// Points read from a file and the dimension of the file: 3, or 2 for a file
/// of the plane, whose points have z == 0.
struct PointFile {
  std::vector<Vec3> points;  ///< in space, whatever the file's dimension
  int dimension = 3;         ///< 2 or 3
};

/// Reads a system of half-spaces of either dimension (see the file comment).
/// At most limits.max_faces rows.
/// \throw the errors of read_halfspaces.
HalfspaceFile read_halfspaces_of_any_dimension(std::istream& in, HalfspaceFormat format,
                                               std::string_view source = "<stream>", const ReadLimits& limits = {});

/// Reads a file of half-spaces of either dimension, its format by extension.
/// \throw Error(io) if it cannot be opened, and the errors of read_halfspaces.
HalfspaceFile read_halfspace_file_of_any_dimension(const std::filesystem::path& path, const ReadLimits& limits = {});

/// Reads a system of half-spaces (see the file comment): the system of
/// read_halfspaces_of_any_dimension. At most limits.max_faces rows.
/// \throw Error(parse) naming the source and line for malformed input (a
///   missing `begin` or `end`, a row of the wrong length (or, in a plain
///   file, of another length than the first row), a bad number, a row
///   count unlike the header's, a linearity index out of range, a
///   V-representation), Error(limit) for input beyond the limits.
HalfspaceSystem read_halfspaces(std::istream& in, HalfspaceFormat format, std::string_view source = "<stream>",
                                const ReadLimits& limits = {});

/// Reads a file of half-spaces, its format by extension.
/// \throw Error(io) if it cannot be opened, and the errors of read_halfspaces.
HalfspaceSystem read_halfspace_file(const std::filesystem::path& path, const ReadLimits& limits = {});

/// Writes the system exactly: cdd with type `integer` when every number is
/// an integer, else `rational`, equalities first and listed in `linearity`;
/// plain with each equality as two rows. With dimension 2 the system must
/// describe a set in the plane z = 0 (an empty set too): each row is
/// written restricted to that plane (its z coefficient dropped, made
/// primitive), and rows that hold on the whole plane (the plane's own
/// equality) are left out.
/// \throw Error(invalid_argument) for a dimension other than 2 or 3;
///   Error(io) if the stream fails.
void write_halfspaces(std::ostream& out, const HalfspaceSystem& system, HalfspaceFormat format, int dimension = 3);

/// Writes a file of half-spaces, its format by extension, atomically (see
/// write_file in cvms/io.hpp); dimension as write_halfspaces.
/// \throw Error(io) naming the path if it cannot be written.
void write_halfspace_file(const std::filesystem::path& path, const HalfspaceSystem& system, int dimension = 3);

/// Reads the points of a cdd V-representation of either dimension.
/// \throw the errors of read_cdd_points.
PointFile read_cdd_points_of_any_dimension(std::istream& in, std::string_view source = "<stream>",
                                           const ReadLimits& limits = {});

/// Reads the points of a cdd V-representation (`.ext`): the points of
/// read_cdd_points_of_any_dimension.
/// \throw Error(parse) naming the source and line for malformed input, a
///   ray or a linearity line; Error(limit) beyond limits.max_vertices or the
///   other limits.
std::vector<Vec3> read_cdd_points(std::istream& in, std::string_view source = "<stream>",
                                  const ReadLimits& limits = {});

/// Writes the vertices of the set as a cdd V-representation (type
/// `integer` or `rational`); the empty set gives `0 4` rows (`0 3` in the
/// plane). With dimension 2, as a file of the plane.
/// \throw Error(invalid_argument) for a dimension other than 2 or 3, or
///   with dimension 2 for a vertex off the plane z = 0; Error(io) if the
///   stream fails.
void write_cdd_points(std::ostream& out, const ConvexSet& set, int dimension = 3);

/// write_cdd_points to a file, atomically (see write_file in cvms/io.hpp);
/// the set is checked before the file is touched.
/// \throw Error(io) naming the path if it cannot be written, and the errors
///   of write_cdd_points.
void write_cdd_points_file(const std::filesystem::path& path, const ConvexSet& set, int dimension = 3);

/// Reads a plain point list: one `x y z` (or, in the plane, `x y`) per
/// line, `#` comments, at most limits.max_vertices points.
/// \throw Error(parse) naming the source and line for a bad number, a
///   line with fewer than 2 or more than 3 numbers or with another count
///   than the first, a file without points; Error(limit) beyond the limits.
PointFile read_plain_points(std::istream& in, std::string_view source = "<stream>", const ReadLimits& limits = {});

/// Writes the vertices of the set, one line each (in the plane: `x y`).
/// \throw Error(invalid_argument) for the empty set (a point list cannot
///   hold it), and as write_cdd_points (Error(io) if the stream fails).
void write_plain_points(std::ostream& out, const ConvexSet& set, int dimension = 3);

/// write_plain_points to a file, atomically; the set is checked before the
/// file is touched.
/// \throw Error(io) naming the path if it cannot be written, and the errors
///   of write_plain_points.
void write_plain_points_file(const std::filesystem::path& path, const ConvexSet& set, int dimension = 3);

}  // namespace cvms
