// SPDX-License-Identifier: MIT
// `cvms check F`: validates a convex set and prints its dimension, V E F and
// facet degree histogram (for a polyhedron; for a flat set its kind, V and
// plane).
#include <cstdint>
#include <iostream>
#include <map>
#include <memory>
#include <string>

#include "commands.hpp"
#include "files.hpp"
#include "keep_until_exit.hpp"
#include "options.hpp"
#include "reports.hpp"
#include "set_files.hpp"

namespace cvms::cli {
namespace {

void report_polyhedron(const std::string& name, const ConvexPolyhedron& p, std::size_t input_points,
                       std::size_t input_faces, std::ostream& report) {
  std::map<std::uint32_t, std::uint32_t> histogram;
  for (FaceId f : p.mesh().faces()) ++histogram[p.mesh().degree(f)];
  report << printable(name) << ": convex polyhedron\ndimension 3\n" << counts(p) << "\n";
  if (input_points != p.num_vertices() || input_faces != p.num_facets())
    report << "input: V " << input_points << " F " << input_faces
           << " (normalised: coplanar faces merged, non-extreme vertices dropped)\n";
  report << "facet degree histogram:\n";
  for (auto [degree, count] : histogram) report << "  " << degree << ": " << count << "\n";
}

void run_check(const std::string& input, std::ostream& report) {
  PolygonSoup soup = read_soup(input);
  const std::size_t input_points = soup.points.size();
  const std::size_t input_faces = soup.num_faces();
  ConvexSet set = set_from_soup(std::move(soup), input_name(input));
  if (set.dimension() != 3) return report_set(input_name(input), set, report);
  report_polyhedron(input_name(input), set.polyhedron(), input_points, input_faces, report);
  keep_until_exit(std::move(set));
}

}  // namespace

void register_check(CLI::App& app, Commands& commands) {
  auto input = std::make_shared<std::string>();
  CLI::App* command =
      app.add_subcommand("check", "validate a convex set, print its dimension, V E F and facet degrees");
  command->add_option("F", *input, "the file")->required()->check(mesh_path());
  commands.push_back({command, [input] { run_check(*input, std::cout); }});
}

}  // namespace cvms::cli
