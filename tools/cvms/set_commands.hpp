// SPDX-License-Identifier: MIT
// The cvms tool's commands on convex sets of every dimension (issue 15):
// sums of two or more operands, flat inputs, zonotopes. Kept apart from
// commands.cpp, which calls these where a set may be flat.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "cvms/convex_set.hpp"
#include "cvms/io.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/polygon_soup.hpp"

namespace cvms::cli {

/// read_convex_set, or for "-" an OFF on stdin: every error names the file.
ConvexSet read_set(const std::string& path);

/// convex_set_from_soup with "<source>: " in front of every error message.
ConvexSet set_from_soup(PolygonSoup soup, const std::string& source);

/// write_file(path, set), or OFF on stdout for "-".
void write_set(const std::string& path, const ConvexSet& set, Coordinates coordinates, const std::string& format = {});

/// The sum of the sets, written to output; with stats, the operands' and
/// the result's sizes and the time go to report.
void run_set_sum(const std::vector<ConvexSet>& operands, const Options& options, const std::string& output,
                 const std::string& format, Coordinates coordinates, bool stats, std::ostream& report);

/// "point", "segment", "polygon" ... and its vertex count, for check.
void report_set(const std::string& name, const ConvexSet& set, std::ostream& report);

/// The zonotope of n generators random_points(seed, n) (integer coordinates
/// in [-1000, 1000]) centred at the origin.
ConvexSet random_zonotope(int generators, std::uint64_t seed);

}  // namespace cvms::cli
