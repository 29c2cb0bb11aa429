// SPDX-License-Identifier: MIT
// `cvms demo`: Cube + Sphere4 with counts, algorithm and wall time.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "cvms/shapes.hpp"
#include "options.hpp"
#include "reports.hpp"
#include "timed_sum.hpp"

namespace cvms::cli {
namespace {

void run_demo(Algorithm algorithm, std::ostream& report) {
  ConvexPolyhedron a = shapes::cube();
  ConvexPolyhedron b = shapes::geodesic_sphere(4);
  Options options;
  options.algorithm = algorithm;
  Timed sum = timed_sum(a, b, options);
  report << "cvms demo: exact Minkowski sum Cube + Sphere4\n"
         << "  Cube      " << counts(a) << "\n"
         << "  Sphere4   " << counts(b) << "\n"
         << "  sum       " << counts(sum.result.polyhedron) << "\n"
         << "algorithm: " << to_string(algorithm) << "\n"
         << "time: " << milliseconds(sum.time) << " (wall, the sum only)\n";
  print_stats(report, sum.result.stats, sum.diagnostics);
}

}  // namespace

void register_demo(CLI::App& app, Commands& commands) {
  auto algorithm = std::make_shared<Algorithm>(Options{}.algorithm);
  CLI::App* command = app.add_subcommand("demo", "Cube + Sphere4 with counts and time");
  add_algorithm_option(*command, *algorithm);
  commands.push_back({command, [algorithm] { run_demo(*algorithm, std::cout); }});
}

}  // namespace cvms::cli
