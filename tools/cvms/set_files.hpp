// SPDX-License-Identifier: MIT
// Reading and writing convex sets of every dimension (points, segments,
// polygons, polyhedra), as files.hpp does polyhedra: errors name the file.
#pragma once

#include <string>

#include "cvms/convex_set.hpp"
#include "cvms/io.hpp"
#include "cvms/polygon_soup.hpp"

namespace cvms::cli {

/// read_convex_set, or for "-" an OFF on stdin: every error names the file.
ConvexSet read_set(const std::string& path);

/// convex_set_from_soup with "<source>: " in front of every error message.
ConvexSet set_from_soup(PolygonSoup soup, const std::string& source);

/// write_file(path, set), or OFF on stdout for "-".
void write_set(const std::string& path, const ConvexSet& set, Coordinates coordinates, const std::string& format = {});

}  // namespace cvms::cli
