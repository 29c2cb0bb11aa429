// SPDX-License-Identifier: MIT
// Peer rows of cvms_set_bench (built only with CVMS_BENCH_PEERS and a found
// qhull): what one does without a sum of a flat operand, qhull's
// floating-point 3D hull of all pairwise vertex sums (|P| |Q| points),
// timed from the points in doubles (the sums are formed and rounded before
// the timed loop, which favours qhull). The 1,000-gon row has 41 million
// points, beyond what a benchmark run should allocate, so the polygon peer
// runs on the 100-gon (4 million points) against the same row of cvms.
#include <benchmark/benchmark.h>

#ifdef CVMS_BENCH_HAVE_QHULL

#include <cstdint>
#include <vector>

#include "peer_qhull.hpp"
#include "set_operands.hpp"

namespace {

std::vector<double> pairwise_sums(const cvms::ConvexSet& a, const cvms::ConvexSet& b) {
  const std::vector<cvms::Vec3> va = a.vertices(), vb = b.vertices();
  std::vector<double> xyz;
  xyz.reserve(3 * va.size() * vb.size());
  for (const cvms::Vec3& p : va)
    for (const cvms::Vec3& q : vb)
      for (int i = 0; i < 3; ++i) xyz.push_back(cvms::Rational(p[i] + q[i]).get_d());
  return xyz;
}

void qhull_of_sums(benchmark::State& state, const cvms::ConvexSet& a) {
  const std::vector<double> xyz = pairwise_sums(a, cvms_bench::sphere6_set());
  cvms_bench::QhullHull h;
  for (auto _ : state) {
    h = cvms_bench::qhull_hull(xyz);
    benchmark::DoNotOptimize(h);
  }
  if (h.facets == 0) state.SkipWithError("qhull failed");
  state.counters["points"] = static_cast<double>(xyz.size() / 3);
  state.counters["V"] = static_cast<double>(h.vertices);
  state.counters["F"] = static_cast<double>(h.facets);
}

void BM_QhullPolygonPlusSphere6(benchmark::State& state) {
  qhull_of_sums(state, cvms_bench::tilted_polygon(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_QhullPolygonPlusSphere6)->Arg(100)->Unit(benchmark::kMillisecond);

void BM_QhullSegmentPlusSphere6(benchmark::State& state) { qhull_of_sums(state, cvms_bench::bench_segment()); }
BENCHMARK(BM_QhullSegmentPlusSphere6)->Unit(benchmark::kMillisecond);

}  // namespace

#endif  // CVMS_BENCH_HAVE_QHULL
