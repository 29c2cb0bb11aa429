// SPDX-License-Identifier: MIT
// The subcommands of the cvms tool (see commands.hpp).
#include "commands.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iomanip>
#include <map>
#include <ostream>
#include <string_view>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/shapes.hpp"
#include "files.hpp"
#include "keep_until_exit.hpp"
#include "set_commands.hpp"
#include "sizes.hpp"

namespace cvms::cli {
namespace {

Coordinates coordinates_of(bool float_output) {
  return float_output ? Coordinates::double_ : Coordinates::exact;
}

std::string counts(const ConvexPolyhedron& p) {
  return "V " + std::to_string(p.num_vertices()) + " E " + std::to_string(p.num_edges()) + " F " +
         std::to_string(p.num_facets());
}

std::string milliseconds(std::chrono::steady_clock::duration d) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3f ms", std::chrono::duration<double, std::milli>(d).count());
  return text;
}

struct Timed {
  MinkowskiResult result;
  SumDiagnostics diagnostics;
  std::chrono::steady_clock::duration time;
};

// The time of the sum alone: a loaded polyhedron makes its facet planes when
// they are first read (ConvexPolyhedron::normal), which is loading's work, so
// they are made before the clock starts, as an in-process caller's operands
// have them after their first use.
Timed timed_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Options& options) {
  for (const ConvexPolyhedron* p : {&a, &b})
    if (p->num_facets() > 0) (void)p->normal(FaceId(0));
  SumDiagnostics diagnostics;
  Options counted = options;
  counted.diagnostics = &diagnostics;
  auto start = std::chrono::steady_clock::now();
  MinkowskiResult result = minkowski_sum(a, b, counted);
  return {std::move(result), diagnostics, std::chrono::steady_clock::now() - start};
}

void print_stats(std::ostream& report, const Stats& s, const SumDiagnostics& d) {
  report << "facets: translated " << s.translated_facets << ", corner " << s.corner_facets << ", edge "
         << s.edge_facets << "\n"
         << "contributing-vertex ties: " << d.contributing_ties << "\n"
         << "predicates: filtered " << d.predicate_filtered << ", exact " << d.predicate_exact << "\n";
}

// A limit error names the option that raises it (sizes.hpp).
Timed limited_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const SumArgs& args) {
  try {
    return timed_sum(a, b, args.options());
  } catch (const Error& e) {
    rethrow_with_limit_hint(e);
  }
}

// Fails before any work if the output cannot be written: an unknown format
// (a usage error), a missing directory, a directory.
void check_output(const std::string& path, const std::string& format) {
  (void)output_format(path, format);
  check_output_directory(path);
}

}  // namespace

Options SumArgs::options() const {
  Options options;
  options.algorithm = algorithm;
  options.threads = threads;
  options.limits = limits;
  return options;
}

void run_sum(const SumArgs& args, std::ostream& report) {
  if (args.a == "-" && args.b == "-") throw UsageError("only one input can be read from stdin");
  check_output(args.output, args.format);
  // Flat operands, or more than two: the sum of convex sets.
  if (std::count(args.more.begin(), args.more.end(), "-") + (args.a == "-") + (args.b == "-") > 1)
    throw UsageError("only one input can be read from stdin");
  // Moved in one by one: a braced list would copy every operand (its
  // elements are const), which cost as much as the sum itself on Sphere6.
  std::vector<ConvexSet> sets;
  sets.reserve(2 + args.more.size());
  sets.push_back(read_set(args.a));
  sets.push_back(read_set(args.b));
  for (const std::string& path : args.more) sets.push_back(read_set(path));
  if (sets.size() > 2 || sets[0].dimension() != 3 || sets[1].dimension() != 3) {
    run_set_sum(sets, args.options(), args.output, args.format, coordinates_of(args.float_output), args.stats,
                report);
    return keep_until_exit(std::move(sets));
  }
  const ConvexPolyhedron& a = sets[0].polyhedron();
  const ConvexPolyhedron& b = sets[1].polyhedron();
  Timed sum = limited_sum(a, b, args);
  write_polyhedron(args.output, sum.result.polyhedron, coordinates_of(args.float_output), args.format);
  if (args.stats) {
    report << "A: " << counts(a) << "\nB: " << counts(b) << "\nA+B: " << counts(sum.result.polyhedron)
           << "\nalgorithm: " << to_string(args.algorithm) << "\ntime: " << milliseconds(sum.time) << "\n";
    print_stats(report, sum.result.stats, sum.diagnostics);
  }
  keep_until_exit(std::move(sum.result.polyhedron));
  keep_until_exit(std::move(sets));
}

void run_hull(const HullArgs& args) {
  check_output(args.output, args.format);
  std::vector<Vec3> points = read_point_cloud(args.input);
  // Flat, collinear or single-point clouds give the set they span.
  ConvexSet hull = convex_hull_set(points);
  write_set(args.output, hull, coordinates_of(args.float_output), args.format);
  keep_until_exit(std::move(hull));
  keep_until_exit(std::move(points));
}

void run_gen(const GenArgs& args) {
  const std::string& s = args.shape;
  const bool sphere = s == "sphere" || s == "rotated-sphere";
  const bool counted = s == "random" || s == "prism";
  if (args.subdivisions_given && !sphere)
    throw UsageError("--subdivisions applies only to sphere and rotated-sphere");
  if (args.seed_given && s != "random" && s != "zonotope")
    throw UsageError("--seed applies only to random and zonotope");
  if (args.generators != 0 && s != "zonotope") throw UsageError("--generators applies only to zonotope");
  if (args.points != 0 && !counted) throw UsageError("--points applies only to random and prism");

  check_output(args.output, args.format);
  if (s == "zonotope")  // a set: flat for fewer than 3 generators
    return write_set(args.output, random_zonotope(args.generators != 0 ? args.generators : 10, args.seed),
                     coordinates_of(args.float_output), args.format);
  ConvexPolyhedron p;
  if (s == "tetrahedron")
    p = shapes::tetrahedron();
  else if (s == "cube")
    p = shapes::cube();
  else if (s == "octahedron")
    p = shapes::octahedron();
  else if (s == "truncated-cube")
    p = shapes::truncated_cube();
  else if (s == "sphere")
    p = shapes::geodesic_sphere(args.subdivisions);
  else if (s == "rotated-sphere")
    p = shapes::rotated_geodesic_sphere(args.subdivisions);
  else if (s == "box")
    p = shapes::box({Rational(0), Rational(0), Rational(0)}, {Rational(1), Rational(2), Rational(3)});
  else if (s == "prism") {
    int n = args.points != 0 ? args.points : 6;
    if (n < 3 || n > max_prism_sides)
      throw UsageError("prism needs --points from 3 to " + std::to_string(max_prism_sides));
    p = shapes::prism(n, Rational(2));
  } else if (s == "random") {
    int n = args.points != 0 ? args.points : 100;
    if (n < 4) throw UsageError("random needs --points >= 4");
    p = shapes::random_hull(args.seed, n);
  } else {
    throw UsageError("unknown shape '" + s + "'");
  }
  write_polyhedron(args.output, p, coordinates_of(args.float_output), args.format);
}

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

}  // namespace

void run_check(const std::string& input, std::ostream& report) {
  PolygonSoup soup = read_soup(input);
  const std::size_t input_points = soup.points.size();
  const std::size_t input_faces = soup.num_faces();
  ConvexSet set = set_from_soup(std::move(soup), input_name(input));
  if (set.dimension() != 3) return report_set(input_name(input), set, report);
  report_polyhedron(input_name(input), set.polyhedron(), input_points, input_faces, report);
  keep_until_exit(std::move(set));
}

void run_demo(const DemoArgs& args, std::ostream& report) {
  ConvexPolyhedron a = shapes::cube();
  ConvexPolyhedron b = shapes::geodesic_sphere(4);
  Options options;
  options.algorithm = args.algorithm;
  Timed sum = timed_sum(a, b, options);
  report << "cvms demo: exact Minkowski sum Cube + Sphere4\n"
         << "  Cube      " << counts(a) << "\n"
         << "  Sphere4   " << counts(b) << "\n"
         << "  sum       " << counts(sum.result.polyhedron) << "\n"
         << "algorithm: " << to_string(args.algorithm) << "\n"
         << "time: " << milliseconds(sum.time) << " (wall, the sum only)\n";
  print_stats(report, sum.result.stats, sum.diagnostics);
}

}  // namespace cvms::cli
