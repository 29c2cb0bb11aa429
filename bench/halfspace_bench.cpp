// SPDX-License-Identifier: MIT
// Half-spaces: exact from_halfspaces on the facet planes of
// Sphere4..Sphere6 (1,280 .. 20,480 rows, none redundant) and on random
// redundant systems (halfspace_operands.hpp), the Pontryagin difference of
// Sphere_k and a small cube and of two random hulls of realistic size.
// With CVMS_BENCH_PEERS and qhull found, halfspace_peers.cpp adds qhull's
// half-space intersection ('H', interior point given) on the same rows.
#include <benchmark/benchmark.h>

#include <cstdint>

#include "cvms/halfspaces.hpp"
#include "cvms/shapes.hpp"
#include "halfspace_operands.hpp"

namespace {

using cvms::ConvexSet;
using cvms::Rational;
using cvms::Vec3;

void report(benchmark::State& state, std::size_t rows, const ConvexSet& s) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rows));
  state.counters["rows"] = static_cast<double>(rows);
  state.counters["V"] = static_cast<double>(s.num_vertices());
  state.counters["F"] = s.dimension() == 3 ? static_cast<double>(s.polyhedron().num_facets()) : 0.0;
}

void intersect(benchmark::State& state, const cvms_bench::HalfspaceOperands& in) {
  ConvexSet s;
  for (auto _ : state) benchmark::DoNotOptimize(s = cvms::from_halfspaces(in.rows));
  report(state, in.rows.size(), s);
}

void BM_FromHalfspaces_Sphere(benchmark::State& state) {
  intersect(state, cvms_bench::sphere_rows(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_FromHalfspaces_Sphere)->DenseRange(4, 6)->Unit(benchmark::kMillisecond);

void BM_FromHalfspaces_Redundant(benchmark::State& state) {
  intersect(state, cvms_bench::redundant_rows(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_FromHalfspaces_Redundant)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

void difference(benchmark::State& state, const ConvexSet& a, const ConvexSet& b) {
  ConvexSet d;
  for (auto _ : state) benchmark::DoNotOptimize(d = cvms::pontryagin_difference(a, b));
  report(state, a.dimension() == 3 ? a.polyhedron().num_facets() : 0, d);
}

// Sphere_k (radius 1) ⊖ [−1/10, 1/10]^3.
void BM_Pontryagin_SphereCube(benchmark::State& state) {
  const Rational t(1, 10);
  difference(state, ConvexSet(cvms::shapes::geodesic_sphere(static_cast<int>(state.range(0)))),
             ConvexSet(cvms::shapes::box(Vec3{-t, -t, -t}, Vec3{t, t, t})));
}
BENCHMARK(BM_Pontryagin_SphereCube)->DenseRange(4, 6)->Unit(benchmark::kMillisecond);

// The hull of 100,000 random points in the ball of radius 1000 ⊖ the hull of
// 1,000 others shrunk to radius 100.
void BM_Pontryagin_RandomHulls(benchmark::State& state) {
  const Rational tenth(1, 10);
  const ConvexSet a(cvms_bench::ball_hull(91, 100000));
  const ConvexSet b(cvms_bench::ball_hull(92, 1000).transformed(cvms::shapes::scaling(tenth, tenth, tenth), {}));
  difference(state, a, b);
}
BENCHMARK(BM_Pontryagin_RandomHulls)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
