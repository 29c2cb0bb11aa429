// SPDX-License-Identifier: MIT
// Sums of solids that need not be convex, as one closed solid
// (minkowski_sum(Solid, Solid), cvms/solid_sum.hpp), in process, on the pairs
// of solid_sum_operands.hpp, with the references the union is judged by:
//  - BM_SolidSum/<pair>/<threads>: the whole sum, from the two validated
//    solids to the result solid (the road the library chooses: no
//    decomposition when one operand is convex, the pieces otherwise);
//    counters for the output (facets, vertices, triangles, shells, genus,
//    the exact volume rounded to a double).
//  - BM_WriteResult/<pair>/1: writing that result as exact OFF text (to
//    memory), so that "sum + write" and "pieces + write" can be compared.
//  - BM_PiecesStage/<pair>/<threads>: the convex pieces alone, before any
//    union: minkowski_sum_pieces (decomposition and pairwise sums) when both
//    operands are non-convex, and the convex sums of A's boundary triangles
//    with B (sums of flat operands, cvms/set_sum.hpp) when B is convex.
//  - BM_FaceSums/<pair>/<threads>: where one operand is convex, the pieces
//    that road really sums: the other operand's facet polygons (A's
//    triangles merged into convex polygons) each + the convex one, through
//    the boundary layer's face sums (lib/boundary/face_sums.hpp).
//  - BM_UnionOfPieces/<pair>/1: the other road where one operand is convex:
//    the union of the pieces of both decompositions, so that the two roads
//    are compared on the same pairs.
// The CGAL Nef peer is in solid_sum_peers.cpp (CVMS_BENCH_PEERS); Manifold
// and whole `cvms sum` runs read the operands that `--write_operands=DIR`
// writes (bench/manifold_peer.py, bench/solid_sum_end_to_end.py).
#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/decomposition.hpp"
#include "cvms/io.hpp"
#include "cvms/rational.hpp"
#include "cvms/set_sum.hpp"
#include "cvms/solid_sum.hpp"
#include "face_sums.hpp"
#include "facet_polygons.hpp"
#include "solid_sum_operands.hpp"

namespace {

using cvms_bench::PairGroup;
using cvms_bench::SolidPair;

// Results of BM_SolidSum, kept for BM_WriteResult (computed there if absent).
std::map<std::string, cvms::Solid>& results() {
  static std::map<std::string, cvms::Solid> kept;
  return kept;
}

cvms::Options with_threads(unsigned threads) {
  cvms::Options options;
  options.threads = threads;
  return options;
}

void solid_sum(benchmark::State& state, const SolidPair& pair, unsigned threads) {
  const cvms::Solid& a = cvms_bench::solid_sum_operand(pair.a);
  const cvms::Solid& b = cvms_bench::solid_sum_operand(pair.b);
  cvms::Solid sum;
  try {
    for (auto _ : state) {
      sum = cvms::minkowski_sum(a, b, with_threads(threads));
      benchmark::DoNotOptimize(sum);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  results().insert_or_assign(pair.name, sum);
  state.counters["out_facets"] = sum.num_facets();
  state.counters["out_vertices"] = static_cast<double>(sum.vertices().size());
  state.counters["out_triangles"] = static_cast<double>(sum.triangles().size());
  state.counters["shells"] = sum.num_shells();
  state.counters["cavities"] = sum.num_cavities();
  state.counters["genus"] = sum.genus();
  state.counters["volume"] = cvms::to_double_nearest(sum.volume());
  state.counters["in_facets"] = a.num_facets() + b.num_facets();
}

void write_result(benchmark::State& state, const SolidPair& pair, unsigned /*threads*/) {
  auto it = results().find(pair.name);
  try {
    if (it == results().end())
      it = results()
               .emplace(pair.name, cvms::minkowski_sum(cvms_bench::solid_sum_operand(pair.a),
                                                       cvms_bench::solid_sum_operand(pair.b)))
               .first;
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::ostringstream out;
    cvms::write_off(out, it->second.to_soup());
    bytes = out.view().size();
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}

// The convex sums of the triangles of `flat` with `convex`, the pieces of
// the road that decomposes nothing, shared by `threads` threads through an
// atomic counter. Returns their total facet count.
double triangle_sums(const std::vector<cvms::ConvexSet>& triangles, const cvms::ConvexSet& convex,
                     unsigned threads) {
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> facets{0};
  auto work = [&] {
    for (std::size_t i = next++; i < triangles.size(); i = next++) {
      const cvms::ConvexSet piece = cvms::minkowski_sum(triangles[i], convex);
      facets += piece.polyhedron().num_facets();
    }
  };
  std::vector<std::thread> workers;
  for (unsigned t = 1; t < threads; ++t) workers.emplace_back(work);
  work();
  for (std::thread& w : workers) w.join();
  return static_cast<double>(facets.load());
}

void pieces_with_convex(benchmark::State& state, const cvms::Solid& a, const cvms::Solid& b, unsigned threads) {
  const cvms::Solid& flat = a.is_convex() ? b : a;
  const cvms::ConvexSet convex(cvms::convex_hull((a.is_convex() ? a : b).vertices()));
  std::vector<cvms::ConvexSet> triangles;
  for (const auto& t : flat.triangles()) {
    const std::array<cvms::Vec3, 3> corners = {flat.vertices()[t[0]], flat.vertices()[t[1]], flat.vertices()[t[2]]};
    triangles.push_back(cvms::ConvexSet::polygon(corners));
  }
  double facets = 0;
  for (auto _ : state) {
    facets = triangle_sums(triangles, convex, threads);
    benchmark::DoNotOptimize(facets);
  }
  state.counters["out_pieces"] = static_cast<double>(triangles.size());
  state.counters["piece_facets"] = facets;
}

void pieces_stage(benchmark::State& state, const SolidPair& pair, unsigned threads) {
  const cvms::Solid& a = cvms_bench::solid_sum_operand(pair.a);
  const cvms::Solid& b = cvms_bench::solid_sum_operand(pair.b);
  try {
    if (a.is_convex() || b.is_convex()) return pieces_with_convex(state, a, b, threads);
    cvms::ConvexUnion pieces;
    for (auto _ : state) {
      pieces = cvms::minkowski_sum_pieces(a, b, with_threads(threads));
      benchmark::DoNotOptimize(pieces);
    }
    double facets = 0;
    for (const cvms::ConvexPolyhedron& piece : pieces.pieces()) facets += piece.num_facets();
    state.counters["out_pieces"] = static_cast<double>(pieces.size());
    state.counters["piece_facets"] = facets;
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
  }
}

void face_sums_stage(benchmark::State& state, const SolidPair& pair, unsigned threads) {
  const cvms::Solid& a = cvms_bench::solid_sum_operand(pair.a);
  const cvms::Solid& b = cvms_bench::solid_sum_operand(pair.b);
  if (!a.is_convex() && !b.is_convex()) {
    state.SkipWithError("neither operand is convex");
    return;
  }
  const cvms::Solid& flat = b.is_convex() ? a : b;
  const cvms::ConvexPolyhedron convex = cvms::convex_hull((b.is_convex() ? b : a).vertices());
  const std::vector<std::vector<cvms::Vec3>> polygons = cvms::detail::facet_polygons(flat);
  double facets = 0;
  try {
    for (auto _ : state) {
      const std::vector<cvms::ConvexPolyhedron> sums = cvms::detail::face_sums(polygons, convex, with_threads(threads));
      facets = 0;
      for (const cvms::ConvexPolyhedron& sum : sums) facets += sum.num_facets();
      benchmark::DoNotOptimize(facets);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  state.counters["out_pieces"] = static_cast<double>(polygons.size());
  state.counters["piece_facets"] = facets;
}

void union_of_pieces(benchmark::State& state, const SolidPair& pair, unsigned threads) {
  const cvms::Solid& a = cvms_bench::solid_sum_operand(pair.a);
  const cvms::Solid& b = cvms_bench::solid_sum_operand(pair.b);
  cvms::Solid sum;
  try {
    for (auto _ : state) {
      sum = cvms::union_solid(cvms::minkowski_sum_pieces(a, b, with_threads(threads)), with_threads(threads));
      benchmark::DoNotOptimize(sum);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  state.counters["out_facets"] = sum.num_facets();
}

bool every_pair(const SolidPair& /*pair*/) { return true; }
bool one_convex(const SolidPair& pair) { return pair.group != PairGroup::small_small; }
bool one_convex_small(const SolidPair& pair) {
  return pair.group == PairGroup::small_cube || pair.group == PairGroup::comb;
}

const bool registered = [] {
  cvms_bench::register_solid_rows("BM_SolidSum", solid_sum, every_pair, true);
  cvms_bench::register_solid_rows("BM_WriteResult", write_result, every_pair, false);
  cvms_bench::register_solid_rows("BM_PiecesStage", pieces_stage, every_pair, true);
  cvms_bench::register_solid_rows("BM_FaceSums", face_sums_stage, one_convex, true);
  cvms_bench::register_solid_rows("BM_UnionOfPieces", union_of_pieces, one_convex_small, false);
  return true;
}();

}  // namespace

// Google Benchmark's main, plus `--write_operands=DIR`: write every operand
// as a triangle OFF file for the peers outside the process, and stop.
int main(int argc, char** argv) {
  constexpr std::string_view kWrite = "--write_operands=";
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (!arg.starts_with(kWrite)) continue;
    try {
      cvms_bench::write_operands(std::string(arg.substr(kWrite.size())));
    } catch (const std::exception& e) {
      std::cerr << e.what() << '\n';
      return 1;
    }
    return 0;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
