// SPDX-License-Identifier: MIT
// `cvms gen SHAPE`: writes a built-in shape (shapes.hpp), or a random zonotope.
#include <cstdint>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "cvms/error.hpp"
#include "cvms/shapes.hpp"
#include "cvms/set_sum.hpp"
#include "files.hpp"
#include "machine_memory.hpp"
#include "options.hpp"
#include "set_files.hpp"
#include "sizes.hpp"
#include "usage_error.hpp"

namespace cvms::cli {
namespace {

struct GenArgs {
  std::string shape, output = "-";
  std::string format;  ///< --format, empty: from the output path
  int subdivisions = 1;
  bool subdivisions_given = false;
  std::uint64_t seed = 1;
  bool seed_given = false;
  int points = 0;      ///< 0: the shape's default
  int generators = 0;  ///< zonotope; 0: the default (10)
  std::string float_output;  ///< --float: empty, "nearest" or "outer"
  SumLimits limits;  ///< --max-memory (zonotope)
};

// shapes::prism's and shapes::random_hull's limits.
constexpr int max_prism_sides = 1'000'000;
constexpr int max_random_points = 10'000'000;

// In the order help lists them.
constexpr const char* gen_shapes[] = {"tetrahedron", "cube",  "octahedron", "truncated-cube", "sphere",
                                      "rotated-sphere", "box", "prism",      "random",         "zonotope"};

// An option given to a shape it does not apply to is a usage error.
void check_shape_options(const GenArgs& args) {
  const std::string& s = args.shape;
  const bool sphere = s == "sphere" || s == "rotated-sphere";
  const bool counted = s == "random" || s == "prism";
  if (args.subdivisions_given && !sphere)
    throw UsageError("--subdivisions applies only to sphere and rotated-sphere");
  if (args.seed_given && s != "random" && s != "zonotope")
    throw UsageError("--seed applies only to random and zonotope");
  if (args.generators != 0 && s != "zonotope") throw UsageError("--generators applies only to zonotope");
  if (args.points != 0 && !counted) throw UsageError("--points applies only to random and prism");
}

// The zonotope of n generators random_points(seed, n) (integer coordinates
// in [-1000, 1000]) centred at the origin; flat for fewer than 3 generators.
// zonotope() checks the limits before it builds anything.
ConvexSet random_zonotope(int generators, std::uint64_t seed, const SumLimits& limits) {
  std::vector<Vec3> g = shapes::random_points(seed, generators < 4 ? 4 : generators);
  g.resize(static_cast<std::size_t>(generators));
  try {
    return zonotope(Vec3{0, 0, 0}, g, limits);
  } catch (const Error& e) {
    rethrow_with_limit_hint(e);
  }
}

ConvexPolyhedron counted_shape(const GenArgs& args) {
  if (args.shape == "prism") {
    int n = args.points != 0 ? args.points : 6;
    if (n < 3 || n > max_prism_sides)
      throw UsageError("prism needs --points from 3 to " + std::to_string(max_prism_sides));
    return shapes::prism(n, Rational(2));
  }
  int n = args.points != 0 ? args.points : 100;
  if (n < 4) throw UsageError("random needs --points >= 4");
  return shapes::random_hull(args.seed, n);
}

ConvexPolyhedron polyhedron(const GenArgs& args) {
  const std::string& s = args.shape;
  if (s == "tetrahedron") return shapes::tetrahedron();
  if (s == "cube") return shapes::cube();
  if (s == "octahedron") return shapes::octahedron();
  if (s == "truncated-cube") return shapes::truncated_cube();
  if (s == "sphere") return shapes::geodesic_sphere(args.subdivisions);
  if (s == "rotated-sphere") return shapes::rotated_geodesic_sphere(args.subdivisions);
  if (s == "box") return shapes::box({Rational(0), Rational(0), Rational(0)}, {Rational(1), Rational(2), Rational(3)});
  if (s == "prism" || s == "random") return counted_shape(args);
  throw UsageError("unknown shape '" + s + "'");
}

void run_gen(const GenArgs& args) {
  check_shape_options(args);
  check_output(args.output, args.format);
  const Coordinates coordinates = coordinates_of(args.float_output);
  if (args.shape == "zonotope")
    return write_set(args.output, random_zonotope(args.generators != 0 ? args.generators : 10, args.seed, args.limits),
                     coordinates, args.format);
  write_polyhedron(args.output, polyhedron(args), coordinates, args.format);
}

}  // namespace

void register_gen(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<GenArgs>();
  std::string shape_list;
  for (const char* s : gen_shapes) shape_list += std::string(shape_list.empty() ? "" : " ") + s;
  CLI::App* command = app.add_subcommand("gen", "write a built-in shape");
  command->add_option("SHAPE", args->shape, shape_list + " (box is [0,1]x[0,2]x[0,3], prism has height 2)")
      ->required()
      ->check(CLI::IsMember(std::vector<std::string>(std::begin(gen_shapes), std::end(gen_shapes))));
  CLI::Option* subdivisions =
      command->add_option("--subdivisions", args->subdivisions, "K for Sphere_K (1..9)")->check(CLI::Range(1, 9));
  CLI::Option* seed =
      command->add_option("--seed", args->seed, "seed of random and zonotope (0 to 2^64-1)")->check(unsigned_64());
  command
      ->add_option("--points", args->points,
                   "points of random (4.." + std::to_string(max_random_points) + ", default 100), sides of prism (3.." +
                       std::to_string(max_prism_sides) + ", default 6)")
      ->check(CLI::Range(1, max_random_points));
  command->add_option("--generators", args->generators, "generators of zonotope (default 10)")
      ->check(CLI::Range(1, 100'000));
  add_output_options(*command, args->output, args->format, args->float_output);
  args->limits = sum_limits_for_memory(usable_memory_bytes());
  add_max_memory_option(*command, args->limits.max_memory_bytes, "a zonotope whose output");
  commands.push_back({command, [args, subdivisions, seed] {
                        args->subdivisions_given = subdivisions->count() > 0;
                        args->seed_given = seed->count() > 0;
                        run_gen(*args);
                      }});
}

}  // namespace cvms::cli
