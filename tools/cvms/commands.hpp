// SPDX-License-Identifier: MIT
// The subcommands of the cvms tool. Each one is a thin layer over the
// library: read, call one library function, write, report.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

#include "cvms/minkowski.hpp"

namespace cvms::cli {

/// A command line that parsed but does not make sense (exit code 2).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SumArgs {
  std::string a, b, output = "-";
  std::vector<std::string> more;  ///< operands after B (set_commands.cpp sums them)
  std::string format;  ///< --format, empty: from the output path
  Algorithm algorithm = Options{}.algorithm;
  unsigned threads = 1;  ///< --threads: Options::threads
  bool float_output = false;
  bool stats = false;
  SumLimits limits;  ///< --max-facets, --max-memory
  [[nodiscard]] Options options() const;
};
/// A + B (+ C ...) written to output; flat operands and more than two go
/// through the sum of convex sets (set_commands.hpp); with stats, counts, time and Stats go to report.
void run_sum(const SumArgs& args, std::ostream& report);

struct HullArgs {
  std::string input, output = "-";
  std::string format;  ///< --format, empty: from the output path
  bool float_output = false;
};
void run_hull(const HullArgs& args);

struct GenArgs {
  std::string shape, output = "-";
  std::string format;  ///< --format, empty: from the output path
  int subdivisions = 1;
  bool subdivisions_given = false;
  std::uint64_t seed = 1;
  bool seed_given = false;
  int points = 0;  ///< 0: the shape's default
  int generators = 0;  ///< zonotope; 0: the default (10)
  bool float_output = false;
};
/// The most sides `gen prism` takes (shapes::prism's limit).
inline constexpr int max_prism_sides = 1'000'000;
/// The most points `gen random` takes (shapes::random_hull's limit).
inline constexpr int max_random_points = 10'000'000;
/// The shape names gen accepts, in the order help lists them.
inline constexpr const char* gen_shapes[] = {"tetrahedron", "cube",           "octahedron", "truncated-cube",
                                             "sphere",      "rotated-sphere", "box",        "prism",
                                             "random",      "zonotope"};
void run_gen(const GenArgs& args);

/// Validates F and prints its dimension, V E F and the facet degree histogram
/// (for a polyhedron; for a flat set its kind, V and plane) to report.
void run_check(const std::string& input, std::ostream& report);

struct DemoArgs {
  Algorithm algorithm = Options{}.algorithm;
};
/// Cube + Sphere4 with counts, algorithm and wall time printed to report.
void run_demo(const DemoArgs& args, std::ostream& report);

}  // namespace cvms::cli
