// SPDX-License-Identifier: MIT
// The subcommands of the cvms tool. Each one is a thin layer over the
// library: read, call one library function, write, report.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <stdexcept>
#include <string>

#include "cvms/minkowski.hpp"

namespace cvms::cli {

/// A command line that parsed but does not make sense (exit code 2).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SumArgs {
  std::string a, b, output = "-";
  std::string format;  ///< --format, empty: from the output path
  Algorithm algorithm = Options{}.algorithm;
  bool float_output = false;
  bool stats = false;
};
/// A + B written to output; with stats, counts, time and Stats go to report.
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
  bool float_output = false;
};
/// The most sides `gen prism` takes (shapes::prism's limit).
inline constexpr int max_prism_sides = 1'000'000;
/// The most points `gen random` takes (shapes::random_hull's limit).
inline constexpr int max_random_points = 10'000'000;
/// The shape names gen accepts, in the order help lists them.
inline constexpr const char* gen_shapes[] = {"tetrahedron", "cube",           "octahedron", "truncated-cube",
                                             "sphere",      "rotated-sphere", "box",        "prism",
                                             "random"};
void run_gen(const GenArgs& args);

/// Validates F and prints V E F and the facet degree histogram to report.
void run_check(const std::string& input, std::ostream& report);

struct DemoArgs {
  Algorithm algorithm = Options{}.algorithm;
};
/// Cube + Sphere4 with counts, algorithm and wall time printed to report.
void run_demo(const DemoArgs& args, std::ostream& report);

}  // namespace cvms::cli
