// SPDX-License-Identifier: MIT
// Report text shared by the commands (see reports.hpp).
#include "reports.hpp"

#include <cstdio>
#include <ostream>

#include "cvms/rational.hpp"

namespace cvms::cli {

std::string counts(const ConvexPolyhedron& p) {
  return "V " + std::to_string(p.num_vertices()) + " E " + std::to_string(p.num_edges()) + " F " +
         std::to_string(p.num_facets());
}

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

void report_set(const std::string& name, const ConvexSet& set, std::ostream& report) {
  report << name << ": " << kind(set) << "\n" << size_text(set) << "\n";
  if (set.dimension() == 2) {
    const Vec3& n = set.normal();
    report << "plane: normal " << to_string(n.x) << " " << to_string(n.y) << " " << to_string(n.z) << ", offset "
           << to_string(set.plane_offset()) << "\n";
  }
}

void print_stats(std::ostream& report, const Stats& s, const SumDiagnostics& d) {
  report << "facets: translated " << s.translated_facets << ", corner " << s.corner_facets << ", edge "
         << s.edge_facets << "\n"
         << "contributing-vertex ties: " << d.contributing_ties << "\n"
         << "predicates: filtered " << d.predicate_filtered << ", exact " << d.predicate_exact << "\n";
}

std::string milliseconds(std::chrono::steady_clock::duration d) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3f ms", std::chrono::duration<double, std::milli>(d).count());
  return text;
}

}  // namespace cvms::cli
