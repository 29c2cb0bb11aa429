// SPDX-License-Identifier: MIT
// Convex sets in files (the conventions are in cvms/set_io.hpp): the mesh
// readers and writers of lib/io/ plus convex_set_from_soup.
#include "cvms/set_io.hpp"

#include <fstream>
#include <string>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/float_mesh.hpp"
#include "float_coordinates.hpp"

namespace cvms {

namespace {

bool is_mesh_extension(const std::filesystem::path& path) {
  try {
    (void)format_from_extension(path);
    return true;
  } catch (const Error&) {
    return false;
  }
}

std::vector<Vec3> read_point_file(const std::filesystem::path& path, const ReadLimits& limits) {
  std::ifstream in(path, std::ios::binary);
  if (!in || std::filesystem::is_directory(path))
    throw Error(ErrorCategory::io, path.string() + ": cannot open the file for reading");
  return read_points(in, path.string(), limits);
}

// OBJ cannot hold the empty set, STL nothing below a polygon: refused before
// anything is written.
void check_format_holds(const ConvexSet& set, FileFormat format, const std::string& name) {
  if (set.empty() && format == FileFormat::obj)
    throw Error(ErrorCategory::invalid_argument,
                name + ": OBJ cannot hold the empty set (an OBJ without statements is not read back; use OFF)");
  if (set.dimension() < 2 && format == FileFormat::stl)
    throw Error(ErrorCategory::invalid_argument,
                name + ": STL cannot hold a set of dimension " + std::to_string(set.dimension()) + " (use OFF or OBJ)");
}

}  // namespace

ConvexSet read_convex_set(const std::filesystem::path& path, const ReadLimits& limits) {
  if (!is_mesh_extension(path)) return convex_hull_set(read_point_file(path, limits));
  PolygonSoup soup = read_file(path, limits);
  try {
    return convex_set_from_soup(std::move(soup));
  } catch (const Error& e) {
    throw Error(e.category(), path.string() + ": " + e.message());
  }
}

void write_file(const std::filesystem::path& path, const ConvexSet& set, Coordinates coordinates) {
  write_file(path, set, format_from_extension(path), coordinates);
}

void write_file(const std::filesystem::path& path, const ConvexSet& set, FileFormat format, Coordinates coordinates) {
  check_format_holds(set, format, path.string());
  const auto round = [&set](FloatMode mode) { return round_to_doubles(set, mode); };
  if (const auto rounded = io_detail::rounded_soup(format, coordinates, path.string(), round))
    return write_file(path, *rounded, format, Coordinates::double_);
  // A solid straight from its polyhedron: to_soup would copy every exact
  // coordinate first.
  if (set.dimension() == 3) return write_file(path, set.polyhedron(), format, coordinates);
  write_file(path, set.to_soup(), format, coordinates);
}

void write(std::ostream& out, const ConvexSet& set, FileFormat format, const std::string& name,
           Coordinates coordinates) {
  check_format_holds(set, format, name);
  const auto round = [&set](FloatMode mode) { return round_to_doubles(set, mode); };
  if (const auto rounded = io_detail::rounded_soup(format, coordinates, name, round))
    return write(out, *rounded, format, Coordinates::double_);
  if (set.dimension() == 3) return write(out, set.polyhedron(), format, coordinates);
  write(out, set.to_soup(), format, coordinates);
}

}  // namespace cvms
