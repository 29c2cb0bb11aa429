// SPDX-License-Identifier: MIT
// Reading and writing convex sets of every dimension (points, segments,
// polygons, polyhedra), as files.hpp does polyhedra: errors name the file.
//
// A set's file takes one of five forms, told by the extension (any case),
// never by the content: a plain file of three numbers a line could be 2-D
// rows (a b c) or 3-D points (x y z), so a content-based guess could give
// a wrong set without a word. Each form has its own extensions, and `.txt`,
// which either could be, is refused with a message naming them:
//   mesh          .off .obj .stl .ply, or "-" (OFF on stdin/stdout)
//   cdd vertices  .ext             (cdd V-representation)
//   cdd rows      .ine             (cdd H-representation)
//   plain rows    .rows .hrep      (a b c d: a*x + b*y + c*z <= d)
//   plain points  .xyz .pts        (x y z)
// The four non-mesh forms also come in the plane (one column fewer:
// cvms/halfspace_io.hpp): such a file is a set in the plane z = 0, and
// writers asked for dimension 2 write it back in that form.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "cvms/convex_set.hpp"
#include "cvms/io.hpp"
#include "cvms/polygon_soup.hpp"

namespace cvms::cli {

/// The forms of a set's file (see the file comment).
enum class SetForm { mesh, cdd_points, cdd_rows, plain_rows, plain_points };

/// The form of a path by its extension. \throw UsageError for any other
/// extension, naming the forms (and, for .txt, why it is refused).
SetForm set_form(const std::string& path);

/// Accepts a path whose extension names a set form (a CLI11 validator, so
/// that a wrong extension is a usage error before any work).
const CLI::Validator& set_path();

/// A set read from a file, and the dimension of the file: 2 for a file of
/// the plane (the set then lies in z = 0), else 3 (meshes always).
struct SetFile {
  ConvexSet set;
  int dimension = 3;
};

/// Reads a set in any form (see the file comment): rows through
/// from_halfspaces, points through convex_hull_set. Every error names the
/// file, an unbounded system of rows too.
SetFile read_set_file(const std::string& path);

/// read_set_file(path).set: for a mesh, read_convex_set, or for "-" an OFF
/// on stdin.
ConvexSet read_set(const std::string& path);

/// convex_set_from_soup with "<source>: " in front of every error message.
ConvexSet set_from_soup(PolygonSoup soup, const std::string& source);

/// write_file(path, set), or OFF on stdout for "-".
void write_set(const std::string& path, const ConvexSet& set, Coordinates coordinates, const std::string& format = {});

/// As write_set, a polyhedron in VertexOrder::canonical (flat sets
/// are canonical already), so that the bytes depend on the set alone; in
/// doubles, the set rounded as a whole (round_to_doubles) is numbered so.
void write_canonical_set(const std::string& path, const ConvexSet& set, Coordinates coordinates,
                         const std::string& format = {});

/// Fails before any work if a set cannot be written to `path` as
/// write_set_file would: checks of check_output for a mesh; for the other
/// forms, no --format and no --float (rows and points are written exactly),
/// and the output's directory.
void check_set_output(const std::string& path, const std::string& format, const std::string& float_output);

/// Writes the set in the form of the path's extension (a mesh: write_set),
/// a file of the plane when dimension is 2; atomically, as write_file.
void write_set_file(const std::string& path, const ConvexSet& set, int dimension, Coordinates coordinates,
                    const std::string& format = {});

}  // namespace cvms::cli
