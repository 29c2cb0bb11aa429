// SPDX-License-Identifier: MIT
// Sums of hulls of decimal point clouds: the coordinates of scanned meshes
// are short decimals, none of them a double, so every exact
// value has a denominator 10^6 and nothing is dyadic. Two rows of the same
// size:
//
//  - general/<n>: A and B are the hulls of two independent clouds, so their
//    Gaussian maps are in general position (almost every output facet an
//    edge facet).
//  - self/<n>: A + A. Every facet of A has a parallel twin in the other
//    operand and every contributing-vertex decision is an exact tie, which no
//    floating-point filter can prove: the worst case for the filters. The
//    target is at most 2x the general row's time per output facet.
//
// The clouds: n points spread in a thin shell (radius 0.994..1) of the unit
// ball, coordinates rounded to 6 decimals, so that about a quarter of them
// are hull vertices (n = 20,000 gives a hull of about 4,500 vertices).
// Built once, outside the timing; counters give the
// output facets and the time per output facet.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/minkowski.hpp"
#include "decimal_point.hpp"

namespace {

using cvms::ConvexPolyhedron;

ConvexPolyhedron decimal_shell_hull(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> shell(0.994, 1.0);
  std::vector<cvms::Vec3> points;
  points.reserve(static_cast<std::size_t>(n));
  while (static_cast<int>(points.size()) < n) {
    const double x = gauss(rng), y = gauss(rng), z = gauss(rng);
    const double norm = std::sqrt(x * x + y * y + z * z);
    if (norm == 0.0) continue;
    const double r = shell(rng) / norm;
    points.push_back(cvms_bench::six_decimal_point(x * r, y * r, z * r));
  }
  return cvms::convex_hull(points);
}

const ConvexPolyhedron& cloud_hull(int n, int which) {
  static const ConvexPolyhedron a = decimal_shell_hull(n, 20000);
  static const ConvexPolyhedron b = decimal_shell_hull(n, 20001);
  return which == 0 ? a : b;
}

void run(benchmark::State& state, const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  std::size_t facets = 0;
  for (auto _ : state) {
    cvms::MinkowskiResult result = cvms::minkowski_sum(a, b);
    facets = result.polyhedron.num_facets();
    benchmark::DoNotOptimize(facets);
  }
  state.counters["vertices_A"] = static_cast<double>(a.num_vertices());
  state.counters["vertices_B"] = static_cast<double>(b.num_vertices());
  state.counters["out_facets"] = static_cast<double>(facets);
  state.counters["s_per_out_facet"] =
      benchmark::Counter(static_cast<double>(facets), benchmark::Counter::kIsIterationInvariantRate |
                                                          benchmark::Counter::kInvert);
}

void BM_DecimalSum_general(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  run(state, cloud_hull(n, 0), cloud_hull(n, 1));
}
void BM_DecimalSum_self(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  run(state, cloud_hull(n, 0), cloud_hull(n, 0));
}
BENCHMARK(BM_DecimalSum_general)->Arg(20000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecimalSum_self)->Arg(20000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
