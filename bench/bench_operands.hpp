// SPDX-License-Identifier: MIT
/// \file
/// The operands of cvms_minkowski_bench, shared by its CVMS rows
/// (minkowski_bench.cpp) and its peer rows (minkowski_peers.cpp) so that
/// both measure the identical inputs under the identical row numbers.
#pragma once

#include <benchmark/benchmark.h>

#include <array>
#include <span>
#include <string>
#include <vector>

#include "cvms/convex_polyhedron.hpp"

namespace cvms_bench {

/// Operand B of each Table 1 row (A is the cube), in the paper's order;
/// the benchmark argument is the index into this array.
inline constexpr std::array<const char*, 9> kTableRows = {
    "Tetra", "Hedra", "TruncatedCube", "Sphere1", "Sphere2", "Sphere3", "Sphere4", "Sphere5", "Sphere6"};

/// Operand B of Table 1 row `row` (built once per process).
const cvms::ConvexPolyhedron& table_operand(int row);

/// The scaling families: Sphere_k + rotated Sphere_k (Gaussian maps in
/// general position, almost every output facet an edge facet) and
/// Cube + Sphere_k.
enum class Family { sphere_rotated = 0, cube_sphere = 1 };

/// The two operands of a family member.
struct Pair {
  cvms::ConvexPolyhedron a;  ///< first operand
  cvms::ConvexPolyhedron b;  ///< second operand
};

/// The operands of family member k (built once per process).
const Pair& family_pair(Family family, int k);
/// "Sphere5+rotSphere5" or "Cube+Sphere5".
std::string family_label(Family family, int k);

/// Adds the minimum over the repetitions to b's statistics ("min" in the
/// JSON, read by the scripts' --min). A shared host's speed moves in spells
/// of seconds to minutes: run with --benchmark_enable_random_interleaving, the
/// repetitions of every row spread over the whole run, and each row's
/// minimum is its time in the run's fastest spell, so rows compare fairly.
void report_minimum(benchmark::internal::Benchmark* b);

/// The largest k of the scaling families in this run: 7, or 8 when the
/// environment variable CVMS_BENCH_LARGE is 1 (Sphere8 + rotated Sphere8:
/// 327,680 + 327,680 facets; off by default to keep the default run short).
int largest_family_k();

/// The vertices of p, exact.
std::vector<cvms::Vec3> vertex_points(const cvms::ConvexPolyhedron& p);
/// The pairwise vertex sums a + b as doubles (x y z per sum), a-major. The
/// shapes' coordinates are doubles, so each double sum is the correctly
/// rounded exact sum.
std::vector<double> pairwise_sums_double(const cvms::ConvexPolyhedron& a, const cvms::ConvexPolyhedron& b);

}  // namespace cvms_bench
