// SPDX-License-Identifier: MIT
// Peer rows of cvms_pieces_bench (built only with CVMS_BENCH_PEERS and a
// found qhull): the floating-point hull-of-pairs sum of two non-convex
// solids, as Manifold-style Minkowski sums do it: for every pair of convex
// pieces, qhull's hull of the pairwise vertex sums in doubles. The pieces are
// the same exact decompositions the exact rows sum; every vertex sum is
// formed exactly and rounded to the nearest double before the timed loop
// (which favours qhull), so only the hulls are timed. On one and two threads
// (the pairs shared through an atomic counter; the reentrant qhull keeps all
// its state in its own context).
#include <benchmark/benchmark.h>

#ifdef CVMS_BENCH_HAVE_QHULL

#include <atomic>
#include <thread>
#include <vector>

#include "cvms/rational.hpp"
#include "peer_qhull.hpp"
#include "pieces_operands.hpp"

namespace {

using cvms::ConvexPolyhedron;

// The vertex sums of one piece pair, x0 y0 z0 x1 ..., each coordinate the
// exact sum rounded to the nearest double.
std::vector<double> vertex_sums(const ConvexPolyhedron& p, const ConvexPolyhedron& q) {
  std::vector<double> xyz;
  xyz.reserve(3 * static_cast<std::size_t>(p.num_vertices()) * q.num_vertices());
  for (cvms::VertexId u : p.mesh().vertices())
    for (cvms::VertexId v : q.mesh().vertices())
      for (int i = 0; i < 3; ++i) xyz.push_back(cvms::to_double_nearest(p.vertex(u)[i] + q.vertex(v)[i]));
  return xyz;
}

std::vector<std::vector<double>> all_pair_sums(const cvms_bench::SumPair& pair) {
  std::vector<std::vector<double>> sums;
  for (const ConvexPolyhedron& p : cvms_bench::bench_pieces(pair.a).pieces())
    for (const ConvexPolyhedron& q : cvms_bench::bench_pieces(pair.b).pieces()) sums.push_back(vertex_sums(p, q));
  return sums;
}

struct Totals {
  std::size_t facets = 0;  // qhull's facets over all pairs
  std::size_t failed = 0;  // pairs qhull reported an error for
};

Totals hull_all(const std::vector<std::vector<double>>& sums, unsigned threads) {
  std::atomic<std::size_t> next{0}, facets{0}, failed{0};
  auto work = [&] {
    for (std::size_t i = next++; i < sums.size(); i = next++) {
      const cvms_bench::QhullHull h = cvms_bench::qhull_hull(sums[i]);
      facets += h.facets;
      failed += h.facets == 0 ? 1 : 0;
    }
  };
  std::vector<std::thread> workers;
  for (unsigned t = 1; t < threads; ++t) workers.emplace_back(work);
  work();
  for (std::thread& w : workers) w.join();
  return {facets.load(), failed.load()};
}

void qhull_pairs(benchmark::State& state, const cvms_bench::SumPair& pair, unsigned threads) {
  const std::vector<std::vector<double>> sums = all_pair_sums(pair);
  Totals totals;
  for (auto _ : state) {
    totals = hull_all(sums, threads);
    benchmark::DoNotOptimize(totals);
  }
  if (totals.failed != 0) state.SkipWithError("qhull failed on a piece pair");
  double points = 0;
  for (const std::vector<double>& s : sums) points += static_cast<double>(s.size() / 3);
  state.counters["pairs"] = static_cast<double>(sums.size());
  state.counters["points"] = points;
  state.counters["peer_facets"] = static_cast<double>(totals.facets);
}

const bool registered = [] {
  cvms_bench::register_pair_rows("BM_QhullPairs", qhull_pairs);
  return true;
}();

}  // namespace

#endif  // CVMS_BENCH_HAVE_QHULL
