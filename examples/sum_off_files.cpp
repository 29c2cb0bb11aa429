// SPDX-License-Identifier: MIT
// Example: the Minkowski sum of two OFF files, written as an OFF file.
//
//   sum_off_files A.off B.off SUM.off
//
// Every step is exact: the coordinates are read as rationals ("0.1" is 1/10),
// the sum is computed with exact predicates, and the result is written with
// exact decimals (or p/q where no finite decimal exists).
#include <cvms/convex_polyhedron.hpp>
#include <cvms/error.hpp>
#include <cvms/io.hpp>
#include <cvms/minkowski.hpp>
#include <iostream>

namespace {

void print_counts(const char* name, const cvms::ConvexPolyhedron& p) {
  std::cout << name << ": V=" << p.num_vertices() << " E=" << p.num_edges() << " F=" << p.num_facets()
            << '\n';
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: sum_off_files A.off B.off SUM.off\n";
    return 2;
  }
  try {
    // read_polyhedron picks the format from the extension (.off, .obj or
    // .stl) and checks that the mesh is a closed convex polyhedron.
    const cvms::ConvexPolyhedron a = cvms::read_polyhedron(argv[1]);
    const cvms::ConvexPolyhedron b = cvms::read_polyhedron(argv[2]);

    cvms::Options options;  // the defaults: the CVMS algorithm
    cvms::SumDiagnostics diagnostics;
    options.diagnostics = &diagnostics;  // optional: the search's counters
    const cvms::MinkowskiResult sum = cvms::minkowski_sum(a, b, options);

    cvms::write_file(argv[3], sum.polyhedron);  // exact coordinates

    print_counts("A", a);
    print_counts("B", b);
    print_counts("A+B", sum.polyhedron);
    const cvms::Stats& stats = sum.stats;
    std::cout << "facets: " << stats.translated_facets << " translated, " << stats.corner_facets
              << " corner, " << stats.edge_facets << " edge\n"
              << "predicates: " << diagnostics.predicate_filtered << " decided in double, "
              << diagnostics.predicate_exact
              << " needed exact arithmetic\n";
    return 0;
  } catch (const cvms::Error& e) {
    std::cerr << "sum_off_files: " << e.what() << '\n';  // "<category>: <file>: <what and where>"
    return 1;
  }
}
