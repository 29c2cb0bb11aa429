// SPDX-License-Identifier: MIT
// Sums of convex sets of every dimension: a 1,000-gon and a
// segment plus Sphere6 (tilted, so that no facet is parallel), zonotopes of
// n = 10 .. 200 seeded generators (output size n^2 - n + 2 vertices: time
// against output size gives the log-log slope), and the n-ary sum of 10
// random hulls. The peer row for zonotopes folds one generator at a time by
// the exact hull of the pairwise vertex sums (what one does without a
// segment sum), on the small n it can reach; qhull's floating-point hull of
// the pairwise vertex sums is the peer of the polygon and segment rows
// (set_peers.cpp, with CVMS_BENCH_PEERS). bench/zonotope_slope.py fits the
// log-log slope of the zonotope rows' time against their facet count.
#include <benchmark/benchmark.h>

#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/set_sum.hpp"
#include "cvms/shapes.hpp"
#include "set_operands.hpp"

namespace {

using cvms::ConvexSet;
using cvms::Vec3;

using cvms_bench::sphere6_set;
using cvms_bench::tilted_polygon;

void report(benchmark::State& state, const ConvexSet& sum) {
  state.counters["V"] = static_cast<double>(sum.num_vertices());
  state.counters["F"] = sum.dimension() == 3 ? sum.polyhedron().num_facets() : 0;
}

void BM_PolygonPlusSphere6(benchmark::State& state) {
  const ConvexSet polygon = tilted_polygon(static_cast<int>(state.range(0)));
  ConvexSet sum;
  for (auto _ : state) benchmark::DoNotOptimize(sum = cvms::minkowski_sum(polygon, sphere6_set()));
  report(state, sum);
}
BENCHMARK(BM_PolygonPlusSphere6)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_SegmentPlusSphere6(benchmark::State& state) {
  const ConvexSet segment = cvms_bench::bench_segment();
  ConvexSet sum;
  for (auto _ : state) benchmark::DoNotOptimize(sum = cvms::minkowski_sum(segment, sphere6_set()));
  report(state, sum);
}
BENCHMARK(BM_SegmentPlusSphere6)->Unit(benchmark::kMillisecond);

std::vector<Vec3> generators(int n) { return cvms::shapes::random_points(15, n < 4 ? 4 : n); }

void BM_Zonotope(benchmark::State& state) {
  std::vector<Vec3> g = generators(static_cast<int>(state.range(0)));
  g.resize(static_cast<std::size_t>(state.range(0)));
  ConvexSet z;
  for (auto _ : state) benchmark::DoNotOptimize(z = cvms::zonotope(Vec3{0, 0, 0}, g));
  report(state, z);
}
BENCHMARK(BM_Zonotope)->Arg(10)->Arg(20)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMillisecond);

// The peer: Z_{k+1} = hull(vertices(Z_k) +- g_k).
void BM_ZonotopeHullFold(benchmark::State& state) {
  std::vector<Vec3> g = generators(static_cast<int>(state.range(0)));
  g.resize(static_cast<std::size_t>(state.range(0)));
  ConvexSet z;
  for (auto _ : state) {
    std::vector<Vec3> points{Vec3{0, 0, 0}};
    for (const Vec3& gk : g) {
      std::vector<Vec3> next;
      for (const Vec3& p : points) {
        next.push_back(p + gk);
        next.push_back(p - gk);
      }
      z = cvms::convex_hull_set(next);
      points = z.vertices();
    }
    benchmark::DoNotOptimize(z);
  }
  report(state, z);
}
BENCHMARK(BM_ZonotopeHullFold)->Arg(10)->Arg(20)->Arg(50)->Unit(benchmark::kMillisecond);

void BM_SumOfTenRandomHulls(benchmark::State& state) {
  std::vector<ConvexSet> hulls;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) hulls.emplace_back(cvms::shapes::random_hull(seed, 30));
  ConvexSet sum;
  for (auto _ : state) benchmark::DoNotOptimize(sum = cvms::minkowski_sum(hulls));
  report(state, sum);
}
BENCHMARK(BM_SumOfTenRandomHulls)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
