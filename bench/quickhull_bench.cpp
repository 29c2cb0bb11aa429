// SPDX-License-Identifier: MIT
// Exact quickhull on seeded random clouds of doubles (uniform in the unit
// ball and in the cube [-1, 1]^3), 10^3 .. 10^6 points. Reports points per
// second, hull size and the predicate filter's fallback rate.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "cvms/predicates.hpp"
#include "cvms/quickhull.hpp"
#include "quickhull.hpp"

namespace {

using cvms::Rational;
using cvms::Vec3;

std::vector<Vec3> cloud(std::size_t n, bool ball, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> pts;
  pts.reserve(n);
  while (pts.size() < n) {
    double x = u(rng), y = u(rng), z = u(rng);
    if (!ball || x * x + y * y + z * z <= 1.0) pts.push_back({Rational(x), Rational(y), Rational(z)});
  }
  return pts;
}

template <bool Ball, bool Polyhedron>
void hull(benchmark::State& state) {
  const auto pts = cloud(static_cast<std::size_t>(state.range(0)), Ball, 12345);
  cvms::predicate_counters() = {};
  std::size_t vertices = 0, facets = 0;
  for (auto _ : state) {
    if constexpr (Polyhedron) {
      cvms::ConvexPolyhedron p = cvms::convex_hull(pts);
      vertices = p.num_vertices();
      facets = p.num_facets();
    } else {
      cvms::PolygonSoup soup = cvms::hull_soup(pts);
      vertices = soup.points.size();
      facets = soup.num_faces();
    }
  }
  const auto& c = cvms::predicate_counters();
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
  state.counters["hull_V"] = static_cast<double>(vertices);
  state.counters["hull_F"] = static_cast<double>(facets);
  state.counters["predicates"] =
      benchmark::Counter(static_cast<double>(c.filtered + c.exact), benchmark::Counter::kAvgIterations);
  state.counters["exact_rate"] =
      c.filtered + c.exact == 0 ? 0.0
                                : static_cast<double>(c.exact) / static_cast<double>(c.filtered + c.exact);
}

void sizes(benchmark::internal::Benchmark* b) {
  b->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);
}

BENCHMARK(hull<true, false>)->Name("hull_soup/ball")->Apply(sizes);
BENCHMARK(hull<false, false>)->Name("hull_soup/cube")->Apply(sizes);
BENCHMARK(hull<true, true>)->Name("convex_hull/ball")->Apply(sizes);
BENCHMARK(hull<false, true>)->Name("convex_hull/cube")->Apply(sizes);

}  // namespace

BENCHMARK_MAIN();
