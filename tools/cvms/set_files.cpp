// SPDX-License-Identifier: MIT
// Convex sets of every dimension in files (see set_files.hpp).
#include "set_files.hpp"

#include <ostream>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/halfspace_io.hpp"
#include "cvms/halfspaces.hpp"
#include "cvms/float_mesh.hpp"
#include "cvms/set_io.hpp"
#include "files.hpp"
#include "usage_error.hpp"

namespace cvms::cli {
namespace {

constexpr const char* set_extensions =
    ".off, .obj, .stl, .ply (meshes), .ext (cdd vertices), .ine (cdd rows), .rows or .hrep (rows a b c d, or a b c in "
    "the plane), .xyz or .pts (points x y z, or x y)";

std::string check_set_path(const std::string& path) {
  try {
    (void)set_form(path);
    return {};
  } catch (const UsageError& e) {
    return e.what();
  }
}

// The readers name the file in their errors; from_halfspaces does not.
ConvexSet set_from_rows(const HalfspaceSystem& rows, const std::string& path) {
  try {
    return from_halfspaces(rows);
  } catch (const Error& e) {
    throw Error(e.category(), (is_std_stream(path) ? std::string("standard output") : printable(path)) + ": " + e.message());
  }
}

SetFile read_rows(const std::string& path) {
  HalfspaceFile rows = read_within_budget(path, InputCost::rows_or_points, [&](const ReadLimits& limits) {
    return read_halfspace_file_of_any_dimension(path, limits);
  });
  return {set_from_rows(rows.system, path), rows.dimension};
}

SetFile read_points_file(const std::string& path, SetForm form) {
  PointFile points = read_within_budget(path, InputCost::rows_or_points, [&](const ReadLimits& limits) {
    std::ifstream in = open_input(path);
    return form == SetForm::cdd_points ? read_cdd_points_of_any_dimension(in, path, limits)
                                       : read_plain_points(in, path, limits);
  });
  return {convex_hull_set(points.points), points.dimension};
}

}  // namespace

SetForm set_form(const std::string& path) {
  if (is_std_stream(path)) return SetForm::mesh;
  const std::string ext = lower_extension(path);
  if (ext == ".off" || ext == ".obj" || ext == ".stl" || ext == ".ply") return SetForm::mesh;
  if (ext == ".ext") return SetForm::cdd_points;
  if (ext == ".ine") return SetForm::cdd_rows;
  if (ext == ".rows" || ext == ".hrep") return SetForm::plain_rows;
  if (ext == ".xyz" || ext == ".pts") return SetForm::plain_points;
  if (ext == ".txt")
    throw UsageError(
        "'" + printable(path) +
        "': a .txt of numbers could be rows or points (three numbers: 2-D rows a b c, or 3-D points "
        "x y z); name it .rows or .hrep for rows, .xyz or .pts for points");
  throw UsageError("'" + printable(path) + "': expected '-' or a file ending in " + set_extensions);
}

const CLI::Validator& set_path() {
  static const CLI::Validator validator{check_set_path, "FILE(.off|.obj|.stl|.ply|.ext|.ine|.rows|.hrep|.xyz|.pts|-)",
                                       "set path"};
  return validator;
}

ConvexSet set_from_soup(PolygonSoup soup, const std::string& source) {
  try {
    return convex_set_from_soup(std::move(soup));
  } catch (const Error& e) {
    throw Error(e.category(), source + ": " + e.message());
  }
}

SetFile read_set_file(const std::string& path) {
  switch (set_form(path)) {
    case SetForm::mesh:
      if (is_std_stream(path)) return {set_from_soup(read_soup(path), input_name(path))};
      return {read_within_budget(path, InputCost::mesh,
                                 [&](const ReadLimits& limits) { return read_convex_set(path, limits); })};
    case SetForm::cdd_rows:
    case SetForm::plain_rows:
      return read_rows(path);
    case SetForm::cdd_points:
    case SetForm::plain_points:
      return read_points_file(path, set_form(path));
  }
  return {};
}

ConvexSet read_set(const std::string& path) { return read_set_file(path).set; }

void write_set(const std::string& path, const ConvexSet& set, Coordinates coordinates,
               const std::string& format) {
  const FileFormat chosen = output_format(path, format);
  if (!is_std_stream(path)) return write_file(path, set, chosen, coordinates);
  write_stdout([&](std::ostream& out) { write(out, set, chosen, "standard output", coordinates); });
}

namespace {

// The set a text format holds in doubles: rounded as a whole, its doubles
// then printed unchanged (Coordinates::double_ of a soup or set of doubles).
ConvexSet rounded_for_output(const std::string& path, const ConvexSet& set, Coordinates coordinates) {
  try {
    return round_to_doubles(set, coordinates == Coordinates::double_outer ? FloatMode::outer : FloatMode::nearest);
  } catch (const Error& e) {
    throw Error(e.category(), (is_std_stream(path) ? std::string("standard output") : printable(path)) + ": " + e.message());
  }
}

}  // namespace

void write_canonical_set(const std::string& path, const ConvexSet& set, Coordinates coordinates,
                         const std::string& format) {
  const FileFormat chosen = output_format(path, format);
  if (chosen == FileFormat::stl && coordinates == Coordinates::double_outer)
    return write_set(path, set, coordinates, format);  // refused there, with the reason
  const bool rounds = coordinates != Coordinates::exact && chosen != FileFormat::stl;
  const ConvexSet rounded = rounds ? rounded_for_output(path, set, coordinates) : ConvexSet();
  const ConvexSet& out = rounds ? rounded : set;
  const Coordinates printed = rounds ? Coordinates::double_ : coordinates;
  if (out.dimension() == 3) return write_polyhedron(path, out.polyhedron(), printed, format, VertexOrder::canonical);
  write_set(path, out, printed, format);
}

void check_set_output(const std::string& path, const std::string& format, const std::string& float_output) {
  if (!format.empty() || is_std_stream(path) || path.rfind("/dev/", 0) == 0)
    return check_output(path, format);
  if (set_form(path) == SetForm::mesh) return check_output(path, format);
  if (!float_output.empty())
    throw UsageError("--float rounds mesh coordinates: '" + printable(path) + "' is written exactly");
  check_output_directory(path);
}

void write_set_file(const std::string& path, const ConvexSet& set, int dimension, Coordinates coordinates,
                    const std::string& format) {
  if (!format.empty() || is_std_stream(path) || path.rfind("/dev/", 0) == 0)
    return write_set(path, set, coordinates, format);
  switch (set_form(path)) {
    case SetForm::mesh:
      return write_set(path, set, coordinates, format);
    case SetForm::cdd_rows:
    case SetForm::plain_rows:
      return write_halfspace_file(path, to_halfspaces(set), dimension);
    case SetForm::cdd_points:
      return write_cdd_points_file(path, set, dimension);
    case SetForm::plain_points:
      return write_plain_points_file(path, set, dimension);
  }
}

}  // namespace cvms::cli
