// SPDX-License-Identifier: MIT
/// \file
/// The operands of cvms_pieces_bench, shared by its exact rows
/// (pieces_bench.cpp) and its qhull rows (pieces_peers.cpp) so that both
/// measure the identical pieces: the solids of test/data/solids (the real
/// mesh spot.obj and the small non-convex fixtures), two small convex or
/// scaled operands made here, their convex decompositions (computed once per
/// process and shared) and the pairs that are summed.
#pragma once

#include <benchmark/benchmark.h>

#include <array>
#include <string_view>

#include "cvms/convex_union.hpp"
#include "cvms/solid.hpp"

namespace cvms_bench {

/// The solids whose decomposition is timed: spot first, then the small
/// non-convex fixtures (an L-block, a star prism, a holed box, a cube with a
/// cavity, nested shells, two disjoint cubes).
inline constexpr std::array<const char*, 7> kDecomposedSolids = {
    "spot", "l_block", "star_prism", "box_with_hole", "cavity_cube", "nested_shells", "two_cubes"};

/// One summed pair: the row's name and the two solids' names.
struct SumPair {
  const char* name;  ///< the row name, "<a>+<b>"
  const char* a;     ///< first operand
  const char* b;     ///< second operand
};

/// The summed pairs: a real mesh plus a small ball (an offset), the mesh
/// plus a small non-convex solid, and two non-convex fixtures.
inline constexpr std::array<SumPair, 3> kSumPairs = {{
    {"spot+icosphere", "spot", "icosphere"},
    {"spot+l_block_small", "spot", "l_block_small"},
    {"star_prism+box_with_hole", "star_prism", "box_with_hole"},
}};

/// The solid of that name: a file of test/data/solids (`<name>.off`, or
/// spot.obj), or one of the two made here: "icosphere", Sphere2 (42
/// vertices) scaled by 1/20, and "l_block_small", the L-block scaled by 1/10
/// (both about a tenth of spot's size). Loaded once per process.
const cvms::Solid& bench_solid(std::string_view name);

/// The convex decomposition of bench_solid(name), computed on first use
/// (outside any timed loop) unless a decomposition row stored it before.
const cvms::ConvexUnion& bench_pieces(std::string_view name);

/// Stores a decomposition a row computed, so later rows reuse it.
void remember_pieces(std::string_view name, const cvms::ConvexUnion& pieces);

/// A row of a summed pair on a number of threads.
using PairRow = void (*)(benchmark::State&, const SumPair&, unsigned threads);

/// Registers "<prefix>/<pair>/<threads>" for every pair of kSumPairs on 1
/// and 2 threads, in ms; the two-thread rows in wall time (their CPU time
/// would count the calling thread only; the name gets "/real_time").
void register_pair_rows(const char* prefix, PairRow row);

}  // namespace cvms_bench
