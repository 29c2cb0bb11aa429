// SPDX-License-Identifier: MIT
// The commands on convex sets of every dimension (see set_commands.hpp).
#include "set_commands.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <ostream>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/set_io.hpp"
#include "cvms/set_sum.hpp"
#include "cvms/shapes.hpp"
#include "files.hpp"
#include "sizes.hpp"

namespace cvms::cli {

namespace {

const char* kind(const ConvexSet& s) {
  static const char* const names[] = {"empty set", "point", "segment", "convex polygon", "convex polyhedron"};
  return names[s.dimension() + 1];
}

std::string size_text(const ConvexSet& s) {
  std::string text = "dimension " + std::to_string(s.dimension()) + ", V " + std::to_string(s.num_vertices());
  if (s.dimension() == 3)
    text += " E " + std::to_string(s.polyhedron().num_edges()) + " F " + std::to_string(s.polyhedron().num_facets());
  return text;
}

}  // namespace

ConvexSet set_from_soup(PolygonSoup soup, const std::string& source) {
  try {
    return convex_set_from_soup(std::move(soup));
  } catch (const Error& e) {
    throw Error(e.category(), source + ": " + e.message());
  }
}

ConvexSet read_set(const std::string& path) {
  if (!is_std_stream(path)) return read_convex_set(path, read_limits());
  return set_from_soup(read_soup(path), input_name(path));
}

void write_set(const std::string& path, const ConvexSet& set, Coordinates coordinates, const std::string& format) {
  const FileFormat chosen = output_format(path, format);
  if (!is_std_stream(path)) return write_file(path, set, chosen, coordinates);
  write_stdout([&](std::ostream& out) { write(out, set, chosen, "standard output", coordinates); });
}

void run_set_sum(const std::vector<ConvexSet>& operands, const Options& options, const std::string& output,
                 const std::string& format, Coordinates coordinates, bool stats, std::ostream& report) {
  const auto start = std::chrono::steady_clock::now();
  const ConvexSet sum = [&] {
    try {
      return minkowski_sum(operands, options);
    } catch (const Error& e) {
      rethrow_with_limit_hint(e);  // as for two polyhedra: the option to raise
    }
  }();
  const std::chrono::duration<double, std::milli> time = std::chrono::steady_clock::now() - start;
  write_set(output, sum, coordinates, format);
  if (!stats) return;
  for (std::size_t i = 0; i < operands.size(); ++i)
    report << "operand " << i + 1 << ": " << kind(operands[i]) << ", " << size_text(operands[i]) << "\n";
  char ms[64];
  std::snprintf(ms, sizeof ms, "%.3f ms", time.count());
  report << "sum: " << kind(sum) << ", " << size_text(sum) << "\nalgorithm: " << to_string(options.algorithm)
         << "\ntime: " << ms << "\n";
}

void report_set(const std::string& name, const ConvexSet& set, std::ostream& report) {
  report << name << ": " << kind(set) << "\n" << size_text(set) << "\n";
  if (set.dimension() == 2) {
    const Vec3& n = set.normal();
    report << "plane: normal " << to_string(n.x) << " " << to_string(n.y) << " " << to_string(n.z) << ", offset "
           << to_string(set.plane_offset()) << "\n";
  }
}

ConvexSet random_zonotope(int generators, std::uint64_t seed) {
  std::vector<Vec3> g = shapes::random_points(seed, generators < 4 ? 4 : generators);
  g.resize(static_cast<std::size_t>(generators));
  return zonotope(Vec3{0, 0, 0}, g);
}

}  // namespace cvms::cli
