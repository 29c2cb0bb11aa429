// SPDX-License-Identifier: MIT
// See solid_report.hpp.
#include "solid_report.hpp"

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <vector>

#include "files.hpp"

namespace cvms::cli {

namespace {

// The points that several vertices hold: where parts of the solid touch, a
// vertex per shell or fan meets there (solid.hpp).
std::size_t touching_points(const Solid& solid) {
  std::vector<Vec3> points(solid.vertices().begin(), solid.vertices().end());
  std::sort(points.begin(), points.end());
  std::size_t count = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (points[i] == points[i - 1] && (i == 1 || points[i - 1] != points[i - 2])) ++count;
  return count;
}

}  // namespace

void report_solid(const std::string& name, const Solid& solid, std::size_t pieces, std::ostream& report) {
  report << printable(name) << ": solid (" << (solid.is_convex() ? "convex" : "not convex") << ")\n"
         << "shells " << solid.num_shells() << ", cavities " << solid.num_cavities() << ", genus " << solid.genus()
         << "\nV " << solid.vertices().size() << ", facets " << solid.num_facets() << ", reflex edges "
         << solid.num_reflex_edges() << "\nvolume " << to_string(solid.volume()) << "\nconvex pieces " << pieces
         << "\n";
  if (const std::size_t touching = touching_points(solid); touching > 0)
    report << "parts touch: " << touching << (touching == 1 ? " point is" : " points are")
           << " held by several vertices, one per part meeting there\n";
}

void add_solid_members(JsonObject& o, const std::string& name, const Solid& solid, std::size_t pieces) {
  o.text("file", name).text("kind", "solid").integer("dimension", 3).boolean("convex", solid.is_convex());
  o.integer("shells", solid.num_shells()).integer("cavities", solid.num_cavities()).integer("genus", solid.genus());
  o.integer("vertices", static_cast<std::int64_t>(solid.vertices().size()))
      .integer("facets", solid.num_facets())
      .integer("reflex_edges", solid.num_reflex_edges())
      .exact("volume", solid.volume())
      .integer("pieces", static_cast<std::int64_t>(pieces))
      .integer("touching_points", static_cast<std::int64_t>(touching_points(solid)));
}

}  // namespace cvms::cli
