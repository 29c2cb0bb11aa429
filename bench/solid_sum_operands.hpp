// SPDX-License-Identifier: MIT
/// \file
/// The operands of cvms_solid_sum_bench (sums of solids that need not be
/// convex, as one closed solid), shared by its exact rows
/// (solid_sum_bench.cpp) and its CGAL Nef rows (solid_sum_peers.cpp), and
/// written out as triangle OFF files for the peers that run outside the
/// process (Manifold under node, whole `cvms sum` runs): every peer sums the
/// identical solids.
///
/// The solids: the small non-convex fixtures (an L-block, a box with a square
/// hole, a star prism from test/data/solids; a coarse torus from
/// bench/data/solids), the cube [-1/4, 1/4]^3 (bench/data/solids), the real
/// mesh spot.obj with Sphere2 (42 vertices) scaled by 1/20 (radius 1/20, 2 %
/// of spot's bounding-box diagonal), and combs of k teeth (made here) for the
/// output-sensitive family.
#pragma once

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "cvms/solid.hpp"

namespace cvms_bench {

/// Which part of the benchmark a pair belongs to (the peers cap theirs by it).
enum class PairGroup {
  small_cube,   ///< a small non-convex fixture plus the cube (one operand convex)
  small_small,  ///< two small non-convex fixtures (both decomposed)
  mesh,         ///< spot plus the icosphere
  comb,         ///< the output-sensitive family: comb<k> plus the cube
};

/// One summed pair.
struct SolidPair {
  std::string name;  ///< the row name, "<a>+<b>"
  std::string a;     ///< first operand (a name for solid_sum_operand)
  std::string b;     ///< second operand
  PairGroup group;   ///< its part of the benchmark
  int size = 0;      ///< the comb's tooth count k (comb pairs only)
};

/// The tooth counts of the comb family.
inline constexpr int kCombTeeth[] = {4, 8, 16, 32, 64, 128};

/// Every summed pair, in a fixed order: each small fixture + the cube, each
/// fixture + each other one, spot + icosphere, comb<k> + the cube.
const std::vector<SolidPair>& solid_pairs();

/// The solid of that name, loaded or made once per process: "cube",
/// "coarse_torus" (bench/data/solids), "comb<k>" (made here: the extrusion to
/// [0, 1] in z of a comb polygon, a base [0, 3k - 2] x [0, 1] with k teeth
/// [3i, 3i + 1] x [1, 4]; its gaps, 2 wide, stay open under the cube),
/// otherwise the solids of cvms_pieces_bench (pieces_operands.hpp).
const cvms::Solid& solid_sum_operand(std::string_view name);

/// Writes every operand of solid_pairs() as `<dir>/<name>.off`: its
/// triangles with exact coordinates, for the peers outside the process.
void write_operands(const std::filesystem::path& dir);

/// A row of a summed pair on a number of threads.
using SolidPairRow = void (*)(benchmark::State&, const SolidPair&, unsigned threads);

/// Registers "<prefix>/<pair>/<threads>" in ms for the pairs `keep` accepts,
/// on one thread, and with `two_threads` on two as well for the mesh pair
/// (in wall time: the name gets "/real_time"). Returns the registered
/// benchmarks.
std::vector<benchmark::internal::Benchmark*> register_solid_rows(const char* prefix, SolidPairRow row,
                                                                 bool (*keep)(const SolidPair&), bool two_threads);

}  // namespace cvms_bench
