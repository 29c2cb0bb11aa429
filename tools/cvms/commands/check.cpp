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
#include "json.hpp"
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

// The same facts as the text report, as one JSON object (json.hpp).
void report_json(const std::string& name, const ConvexSet& set, std::size_t input_points, std::size_t input_faces,
                 std::ostream& out) {
  JsonObject o(out);
  o.text("file", name).text("kind", kind(set)).integer("dimension", set.dimension());
  o.integer("vertices", static_cast<std::int64_t>(set.num_vertices()));
  if (set.dimension() == 2) o.point("normal", set.normal()).exact("plane_offset", set.plane_offset());
  if (set.dimension() == 3) {
    const ConvexPolyhedron& p = set.polyhedron();
    std::map<std::uint32_t, std::uint32_t> histogram;
    for (FaceId f : p.mesh().faces()) ++histogram[p.mesh().degree(f)];
    std::string degrees = "{";
    for (auto [degree, count] : histogram)
      degrees += (degrees.size() > 1 ? ", " : "") + json_string(std::to_string(degree)) + ": " + std::to_string(count);
    o.integer("edges", static_cast<std::int64_t>(p.num_edges()))
        .integer("facets", static_cast<std::int64_t>(p.num_facets()))
        .raw("facet_degrees", degrees + "}");
  }
  o.integer("input_vertices", static_cast<std::int64_t>(input_points))
      .integer("input_faces", static_cast<std::int64_t>(input_faces))
      .end();
}

void run_check(const std::string& input, bool json, std::ostream& report) {
  PolygonSoup soup = read_soup(input);
  const std::size_t input_points = soup.points.size();
  const std::size_t input_faces = soup.num_faces();
  ConvexSet set = set_from_soup(std::move(soup), input_name(input));
  if (json) {
    report_json(input_name(input), set, input_points, input_faces, report);
    return keep_until_exit(std::move(set));
  }
  if (set.dimension() != 3) return report_set(input_name(input), set, report);
  report_polyhedron(input_name(input), set.polyhedron(), input_points, input_faces, report);
  keep_until_exit(std::move(set));
}

}  // namespace

void register_check(CLI::App& app, Commands& commands) {
  auto input = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  CLI::App* command =
      app.add_subcommand("check", "validate a convex set, print its dimension, V E F and facet degrees");
  command->add_option("F", *input, "the file")->required()->check(mesh_path());
  command->add_flag("--json", *json, "one JSON object: the same facts, exact numbers as strings beside their doubles");
  add_input_memory_option(*command);
  commands.push_back({command, [input, json] { run_check(*input, *json, std::cout); }});
}

}  // namespace cvms::cli
