// SPDX-License-Identifier: MIT
// `cvms check F`: validates a convex set and prints its dimension, V E F and
// facet degree histogram (for a polyhedron; for a flat set its kind, V and
// plane). A file that is not a convex set but spans space is validated as a
// solid instead (convex or not, several shells, cavities, holes): a valid
// one is reported with the piece count of its convex decomposition
// (solid_report.hpp), an invalid one fails with the solid's located defect.
// A pieces file (pieces_files.hpp) is reported as its pieces.
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "commands.hpp"
#include "cvms/union_io.hpp"
#include "files.hpp"
#include "json.hpp"
#include "keep_until_exit.hpp"
#include "mesh_input.hpp"
#include "options.hpp"
#include "pieces_files.hpp"
#include "progress_line.hpp"
#include "reports.hpp"
#include "set_files.hpp"
#include "solid_report.hpp"

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

// A pieces file: each piece validated as a convex polyhedron by read_pieces.
void check_pieces(const std::string& input, const ConvexUnion& pieces, bool json, std::ostream& report) {
  std::int64_t vertices = 0, facets = 0;
  for (const ConvexPolyhedron& piece : pieces.pieces()) {
    vertices += static_cast<std::int64_t>(piece.num_vertices());
    facets += static_cast<std::int64_t>(piece.num_facets());
  }
  if (json) {
    JsonObject(report)
        .text("file", input_name(input))
        .text("kind", "pieces")
        .integer("pieces", static_cast<std::int64_t>(pieces.size()))
        .integer("vertices", vertices)
        .integer("facets", facets)
        .end();
    return;
  }
  report << printable(input_name(input)) << ": pieces file\nconvex pieces " << pieces.size() << "\nV " << vertices
         << ", F " << facets << " (over all pieces)\n";
}

// The mesh input as a solid, its bytes parsed again, after it failed as a
// convex set with `convex_error` (which stays the answer for a file that
// cannot be a solid).
void check_solid(const MeshInput& mesh, const Error& convex_error, bool json, bool progress, std::ostream& report) {
  const std::string& input = mesh.path;
  if (convex_error.category() != ErrorCategory::not_convex && convex_error.category() != ErrorCategory::topology)
    throw convex_error;
  if (holds_pieces(mesh)) return check_pieces(input, read_pieces_text(mesh), json, report);
  PolygonSoup soup = parse_soup(mesh);
  if (!spans_space(soup)) throw convex_error;
  const Solid solid = solid_from_soup(std::move(soup), input_name(input));
  ConvexUnion pieces;
  try {
    pieces = convex_decomposition(solid, DecompositionOptions{.limits = {}, .progress = progress_callback(progress)});
  } catch (const Error& e) {
    rethrow_with_pieces_limit_hint(e);
  }
  if (!json) return report_solid(input_name(input), solid, pieces.size(), report);
  JsonObject o(report);
  add_solid_members(o, input_name(input), solid, pieces.size());
  o.end();
}

void run_check(const std::string& input, bool json, bool progress, std::ostream& report) {
  // A mesh is read once into memory and parsed again only if it is not
  // convex; a cdd .ext is points (their hull: never a solid).
  std::optional<MeshInput> mesh;
  if (!is_cdd_points_path(input)) mesh = read_mesh_input(input);
  PolygonSoup soup = mesh ? parse_soup(*mesh) : read_soup(input);
  const std::size_t input_points = soup.points.size();
  const std::size_t input_faces = soup.num_faces();
  ConvexSet set;
  try {
    set = set_from_soup(std::move(soup), input_name(input));
  } catch (const Error& e) {
    if (!mesh) throw;
    return check_solid(*mesh, e, json, progress, report);
  }
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
      app.add_subcommand("check", "validate a convex set (dimension, V E F, facet degrees) or a solid (shells, volume, pieces)");
  command->add_option("F", *input, "the file")->required()->check(mesh_path());
  command->add_flag("--json", *json, "one JSON object: the same facts, exact numbers as strings beside their doubles");
  add_input_memory_option(*command);
  auto progress = std::make_shared<bool>(false);
  add_progress_option(*command, *progress);
  commands.push_back({command, [input, json, progress] { run_check(*input, *json, *progress, std::cout); }});
}

}  // namespace cvms::cli
