// SPDX-License-Identifier: MIT
// Convex sets of every dimension in files (see set_files.hpp).
#include "set_files.hpp"

#include <ostream>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/set_io.hpp"
#include "files.hpp"

namespace cvms::cli {

ConvexSet set_from_soup(PolygonSoup soup, const std::string& source) {
  try {
    return convex_set_from_soup(std::move(soup));
  } catch (const Error& e) {
    throw Error(e.category(), source + ": " + e.message());
  }
}

ConvexSet read_set(const std::string& path) {
  if (!is_std_stream(path) && !is_cdd_points_path(path)) return read_convex_set(path, read_limits());
  return set_from_soup(read_soup(path), input_name(path));
}

void write_set(const std::string& path, const ConvexSet& set, Coordinates coordinates, const std::string& format) {
  const FileFormat chosen = output_format(path, format);
  if (!is_std_stream(path)) return write_file(path, set, chosen, coordinates);
  write_stdout([&](std::ostream& out) { write(out, set, chosen, "standard output", coordinates); });
}

}  // namespace cvms::cli
