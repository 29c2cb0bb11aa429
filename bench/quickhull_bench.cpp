// SPDX-License-Identifier: MIT
// Exact quickhull on seeded random clouds of doubles (uniform in the unit
// ball and in the cube [-1, 1]^3), 10^3 .. 10^6 points, given as rationals
// (hull_soup, convex_hull) or as doubles (from_doubles: convex_hull of
// std::array<double, 3>), and on the pairwise vertex sums of Cube + Sphere6
// (the CHMS input of the paper's largest Table 1 row). Reports points per
// second, hull size and the predicate filters' fallback rate.
#include <benchmark/benchmark.h>

#include <array>
#include <random>
#include <vector>

#include "filtered_predicates.hpp"
#include "cvms/convex_hull.hpp"
#include "cvms/shapes.hpp"
#include "hull_soup.hpp"

namespace {

using cvms::Rational;
using cvms::Vec3;

using Doubles = std::array<double, 3>;

std::vector<Doubles> double_cloud(std::size_t n, bool ball, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Doubles> pts;
  pts.reserve(n);
  while (pts.size() < n) {
    double x = u(rng), y = u(rng), z = u(rng);
    if (!ball || x * x + y * y + z * z <= 1.0) pts.push_back({x, y, z});
  }
  return pts;
}

std::vector<Vec3> cloud(std::size_t n, bool ball, std::uint64_t seed) {
  std::vector<Vec3> pts;
  pts.reserve(n);
  for (const Doubles& p : double_cloud(n, ball, seed))
    pts.push_back({Rational(p[0]), Rational(p[1]), Rational(p[2])});
  return pts;
}

std::vector<Vec3> cube_sphere6_sums() {
  const cvms::ConvexPolyhedron a = cvms::shapes::cube(), b = cvms::shapes::geodesic_sphere(6);
  std::vector<Vec3> sums;
  for (cvms::VertexId i : a.mesh().vertices())
    for (cvms::VertexId j : b.mesh().vertices()) sums.push_back(a.vertex(i) + b.vertex(j));
  return sums;
}

enum class Entry { soup, polyhedron, doubles };

template <class Points>
void run_hull(benchmark::State& state, const Points& pts, Entry entry) {
  cvms::predicate_counters() = {};
  std::size_t vertices = 0, facets = 0;
  for (auto _ : state) {
    if (entry == Entry::soup) {
      cvms::PolygonSoup soup = cvms::hull_soup(pts);
      vertices = soup.points.size();
      facets = soup.num_faces();
    } else {
      cvms::ConvexPolyhedron p = cvms::convex_hull(pts);
      vertices = p.num_vertices();
      facets = p.num_facets();
    }
  }
  const auto& c = cvms::predicate_counters();
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(pts.size()));
  state.counters["hull_V"] = static_cast<double>(vertices);
  state.counters["hull_F"] = static_cast<double>(facets);
  state.counters["predicates"] =
      benchmark::Counter(static_cast<double>(c.filtered + c.exact), benchmark::Counter::kAvgIterations);
  state.counters["exact_rate"] =
      c.filtered + c.exact == 0 ? 0.0
                                : static_cast<double>(c.exact) / static_cast<double>(c.filtered + c.exact);
}

template <bool Ball, Entry E>
void hull(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  if constexpr (E == Entry::doubles)
    run_hull(state, double_cloud(n, Ball, 12345), E);
  else
    run_hull(state, cloud(n, Ball, 12345), E);
}

void hull_sums(benchmark::State& state) { run_hull(state, cube_sphere6_sums(), Entry::soup); }

void sizes(benchmark::internal::Benchmark* b) {
  b->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);
}

BENCHMARK(hull<true, Entry::soup>)->Name("hull_soup/ball")->Apply(sizes);
BENCHMARK(hull<false, Entry::soup>)->Name("hull_soup/cube")->Apply(sizes);
BENCHMARK(hull<true, Entry::polyhedron>)->Name("convex_hull/ball")->Apply(sizes);
BENCHMARK(hull<false, Entry::polyhedron>)->Name("convex_hull/cube")->Apply(sizes);
BENCHMARK(hull<true, Entry::doubles>)->Name("from_doubles/ball")->Apply(sizes);
BENCHMARK(hull<false, Entry::doubles>)->Name("from_doubles/cube")->Apply(sizes);
BENCHMARK(hull_sums)->Name("hull_soup/cube_sphere6_sums")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
