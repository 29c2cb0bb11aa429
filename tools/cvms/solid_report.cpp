// SPDX-License-Identifier: MIT
// See solid_report.hpp.
#include "solid_report.hpp"

#include <cstdint>
#include <ostream>

#include "files.hpp"

namespace cvms::cli {

void report_solid(const std::string& name, const Solid& solid, std::size_t pieces, std::ostream& report) {
  report << printable(name) << ": solid (" << (solid.is_convex() ? "convex" : "not convex") << ")\n"
         << "shells " << solid.num_shells() << ", cavities " << solid.num_cavities() << ", genus " << solid.genus()
         << "\nV " << solid.vertices().size() << ", facets " << solid.num_facets() << ", reflex edges "
         << solid.num_reflex_edges() << "\nvolume " << to_string(solid.volume()) << "\nconvex pieces " << pieces
         << "\n";
}

void add_solid_members(JsonObject& o, const std::string& name, const Solid& solid, std::size_t pieces) {
  o.text("file", name).text("kind", "solid").integer("dimension", 3).boolean("convex", solid.is_convex());
  o.integer("shells", solid.num_shells()).integer("cavities", solid.num_cavities()).integer("genus", solid.genus());
  o.integer("vertices", static_cast<std::int64_t>(solid.vertices().size()))
      .integer("facets", solid.num_facets())
      .integer("reflex_edges", solid.num_reflex_edges())
      .exact("volume", solid.volume())
      .integer("pieces", static_cast<std::int64_t>(pieces));
}

}  // namespace cvms::cli
