// SPDX-License-Identifier: MIT
// Reading and writing the CLI's files: a path in the format of its extension,
// or "-" for OFF on stdin/stdout. Errors name the file.
#pragma once

#include <string>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/io.hpp"
#include "cvms/polygon_soup.hpp"
#include "cvms/vec.hpp"

namespace cvms::cli {

/// The name used for a path in messages ("<stdin>" / "<stdout>" for "-").
std::string input_name(const std::string& path);

/// Reads a polygon mesh. \throw Error naming the file.
PolygonSoup read_soup(const std::string& path);

/// Validates a mesh read from path as a convex polyhedron; errors (topology,
/// convexity) are prefixed with the file name.
ConvexPolyhedron to_polyhedron(PolygonSoup soup, const std::string& path);

/// Reads a mesh and validates it as a convex polyhedron. Errors found after
/// parsing (topology, convexity) are prefixed with the file name.
ConvexPolyhedron read_polyhedron(const std::string& path);

/// Points for a hull: OFF/OBJ vertices or "x y z" lines; STL triangle corners.
std::vector<Vec3> read_point_cloud(const std::string& path);

/// Writes a polyhedron. \throw Error(io) naming the file if it cannot be written.
void write_polyhedron(const std::string& path, const ConvexPolyhedron& p, Coordinates coordinates);

/// Fails early, before a long computation, if the output's directory does
/// not exist. \throw Error(io) naming the file.
void check_output_directory(const std::string& path);

/// Empty if path is "-" or ends in .off/.obj/.stl (any case), else a message;
/// used as a CLI11 validator so a wrong extension is a usage error.
std::string check_mesh_path(const std::string& path);

}  // namespace cvms::cli
