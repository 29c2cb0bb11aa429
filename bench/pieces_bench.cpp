// SPDX-License-Identifier: MIT
// Non-convex solids: the exact convex decomposition (time, and the piece
// count as a counter: the count drives every later step) of the real mesh
// spot.obj and of the small non-convex fixtures of test/data/solids; and
// sums as unions of convex pieces (the pairwise CVMS sums of the operands'
// pieces, minkowski_sum(ConvexUnion, ConvexUnion)) on one and two threads.
// A sum row times the pairwise step alone: the operands' decompositions are
// the decomposition rows' results (or computed once before the timed loop).
// The floating-point peer, qhull on the pairwise vertex sums of every piece
// pair (what a hull-of-pairs sum does), is in pieces_peers.cpp, built with
// CVMS_BENCH_PEERS.
#include <benchmark/benchmark.h>

#include <string>

#include "cvms/decomposition.hpp"
#include "pieces_operands.hpp"

namespace {

using cvms::ConvexPolyhedron;
using cvms::ConvexUnion;

double total_facets(const ConvexUnion& u) {
  double facets = 0;
  for (const ConvexPolyhedron& piece : u.pieces()) facets += piece.num_facets();
  return facets;
}

void decompose(benchmark::State& state, const char* name) {
  const cvms::Solid& solid = cvms_bench::bench_solid(name);
  ConvexUnion pieces;
  for (auto _ : state) {
    pieces = cvms::convex_decomposition(solid);
    benchmark::DoNotOptimize(pieces);
  }
  cvms_bench::remember_pieces(name, pieces);
  state.counters["pieces"] = static_cast<double>(pieces.size());
  state.counters["piece_facets"] = total_facets(pieces);
  state.counters["reflex_edges"] = solid.num_reflex_edges();
  state.counters["facets"] = solid.num_facets();
  state.counters["vertices"] = static_cast<double>(solid.vertices().size());
}

void sum_pieces(benchmark::State& state, const cvms_bench::SumPair& pair, unsigned threads) {
  const ConvexUnion& a = cvms_bench::bench_pieces(pair.a);
  const ConvexUnion& b = cvms_bench::bench_pieces(pair.b);
  cvms::Options options;
  options.threads = threads;
  ConvexUnion sum;
  for (auto _ : state) {
    sum = cvms::minkowski_sum(a, b, options);
    benchmark::DoNotOptimize(sum);
  }
  state.counters["pieces_A"] = static_cast<double>(a.size());
  state.counters["pieces_B"] = static_cast<double>(b.size());
  state.counters["out_pieces"] = static_cast<double>(sum.size());
  state.counters["out_facets"] = total_facets(sum);
}

const bool registered = [] {
  for (const char* name : cvms_bench::kDecomposedSolids)
    benchmark::RegisterBenchmark((std::string("BM_Decompose/") + name).c_str(), decompose, name)
        ->Unit(benchmark::kMillisecond);
  cvms_bench::register_pair_rows("BM_SumPieces", sum_pieces);
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
