// SPDX-License-Identifier: MIT
/// \file
/// Convex sets of every dimension in files.
///
/// How a set is written (OFF and OBJ, exact unless asked otherwise): a
/// polyhedron as its facets; a polygon as its vertices and one face,
/// counterclockwise seen from its normal(); a segment as its two endpoints
/// and a point as its one point, with no face (an OFF with 0 faces, an OBJ
/// with only `v` lines); the empty set as an OFF with no points (OBJ cannot
/// hold it: an OBJ without statements is not read back). STL holds
/// only triangles: a polygon is written fan-triangulated, a lower-dimensional
/// set not at all. PLY holds what OFF holds, as write_ply writes it (exact
/// ASCII decimals, refused for a coordinate without a finite decimal
/// expansion; binary doubles when rounded). Every file written exactly reads
/// back as the same set. In doubles (Coordinates::double_, double_outer; OFF,
/// OBJ and PLY), the set rounded as a whole by round_to_doubles is written,
/// which may have another dimension (a flat set's outer rounding is solid).
#pragma once

#include <filesystem>

#include "cvms/convex_set.hpp"
#include "cvms/io.hpp"

namespace cvms {

/// Reads the convex set a file describes. .off, .obj, .stl and .ply (any case) are
/// read as meshes (read_file) and taken as convex_set_from_soup takes them: a
/// closed convex surface is a polyhedron; one face, or coplanar faces tiling
/// a convex polygon, is that polygon; points without faces go through the
/// hull. Any other extension is a point list (read_points: one `x y z` per
/// line, or OFF/OBJ vertices) whose hull is returned. Every error names the file.
/// \throw Error(io) if the file cannot be opened;
/// \throw Error(parse), Error(limit) as the readers;
/// \throw the errors of convex_set_from_soup (topology, not_convex,
///   degenerate), the message prefixed by "<path>: ".
ConvexSet read_convex_set(const std::filesystem::path& path, const ReadLimits& limits = {});

/// Writes a set as the file comment says, in the format of the path's extension.
/// \throw Error(invalid_argument) for an unknown extension, for a set of
///   dimension below 2 in STL or the empty set in OBJ, and as
///   write_file(path, soup);
/// \throw Error(io) naming the file if it cannot be written.
void write_file(const std::filesystem::path& path, const ConvexSet& set, Coordinates coordinates = Coordinates::exact);
/// As write_file(path, set, coordinates), in the given format whatever the
/// path's extension (for paths without one, such as /dev/stdout); atomic like
/// write_file of a soup.
/// \throw Error(invalid_argument) for a set the format cannot hold (as above)
///   and as write_file(path, soup, format);
/// \throw Error(io) naming the file if it cannot be written.
void write_file(const std::filesystem::path& path, const ConvexSet& set, FileFormat format,
                Coordinates coordinates = Coordinates::exact);
/// Writes a set to a stream in the given format, by the same conventions.
/// \throw Error(invalid_argument) for a set the format cannot hold (naming
///   `name`) and as write(out, soup, format).
void write(std::ostream& out, const ConvexSet& set, FileFormat format, const std::string& name,
           Coordinates coordinates = Coordinates::exact);

}  // namespace cvms
