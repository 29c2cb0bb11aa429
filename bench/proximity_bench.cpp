// SPDX-License-Identifier: MIT
// Exact proximity queries (cvms/proximity.hpp): squared_distance (exact GJK
// on support walks), intersects and penetration (the exact EPA on the same
// walks), on Cube/Cube, Sphere_k/rotated Sphere_k and Sphere_k/Cube for
// k = 3..5, each in three placements of B: overlapping, touching and
// separated. B is moved by lambda p, p the point of M = A + (-B) farthest in
// a fixed direction (a boundary point; the origin is inside M because both
// shapes are centred there): lambda = 1/2 overlaps, 1 touches, 3/2 separates.
// Penetration twice: the exact EPA (penetration) and its reference, the
// whole sum and a scan of its facets (BM_PenetrationBySum, the first
// version), so the speed-up is measured in one run.
// Also: a double-rotation Placement against materialising it with
// ConvexPolyhedron::transformed.
//
// Arguments: pair (0 Cube/Cube, 1..3 Sphere3..5/rotSphere3..5, 4..6
// Sphere3..5/Cube, 7 Sphere6/rotSphere6, 8 Sphere6/Cube, 9 and 10 the hulls
// of 1,000- and 5,000-point decimal clouds: proximity_operands.hpp),
// placement (0 overlapping, 1 touching, 2 separated). The whole-sum
// reference runs on pairs 0..6 only.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <string>

#include "cvms/proximity.hpp"
#include "cvms/shapes.hpp"
#include "filtered_predicates.hpp"
#include "penetration_by_sum.hpp"
#include "proximity_operands.hpp"

namespace {

using cvms::ConvexPolyhedron;
using cvms_bench::kPairs;
using cvms_bench::kPlacements;
using cvms_bench::operands;
using cvms_bench::Operands;

void label(benchmark::State& state) {
  const Operands& o = operands(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  state.SetLabel(o.label + " " + kPlacements[state.range(1)] + " (V " + std::to_string(o.a.num_vertices()) + "+" +
                 std::to_string(o.b.num_vertices()) + ")");
}

void exact_rate(benchmark::State& state, const cvms::PredicateCounters& before) {
  const cvms::PredicateCounters& now = cvms::predicate_counters();
  const double filtered = static_cast<double>(now.filtered - before.filtered);
  const double exact = static_cast<double>(now.exact - before.exact);
  state.counters["predicates"] = benchmark::Counter(filtered + exact, benchmark::Counter::kAvgIterations);
  state.counters["exact_rate"] = filtered + exact > 0 ? exact / (filtered + exact) : 0.0;
}

void BM_SquaredDistance(benchmark::State& state) {
  const Operands& o = operands(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  label(state);
  const cvms::PredicateCounters before = cvms::predicate_counters();
  int iterations = 0;
  for (auto _ : state) {
    cvms::DistanceResult d = cvms::squared_distance(o.a, o.b);
    iterations = d.iterations;
    benchmark::DoNotOptimize(d);
  }
  state.counters["gjk_iterations"] = iterations;
  exact_rate(state, before);
}

void BM_Intersects(benchmark::State& state) {
  const Operands& o = operands(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  label(state);
  for (auto _ : state) benchmark::DoNotOptimize(cvms::intersects(o.a, o.b));
}

void BM_Penetration(benchmark::State& state) {
  const Operands& o = operands(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  label(state);
  const cvms::PredicateCounters before = cvms::predicate_counters();
  for (auto _ : state) benchmark::DoNotOptimize(cvms::penetration(o.a, o.b));
  exact_rate(state, before);
}

void BM_PenetrationBySum(benchmark::State& state) {
  const Operands& o = operands(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  label(state);
  for (auto _ : state) benchmark::DoNotOptimize(cvms::detail::penetration_by_sum(o.a, o.b));
}

void all_rows(benchmark::internal::Benchmark* b) {
  for (int pair = 0; pair < kPairs; ++pair)
    for (int placement = 0; placement < 3; ++placement) b->Args({pair, placement});
}

BENCHMARK(BM_SquaredDistance)->Apply(all_rows)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Intersects)->Apply(all_rows)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Penetration)->Apply(all_rows)->Unit(benchmark::kMicrosecond);
void small_rows(benchmark::internal::Benchmark* b) {
  for (int pair = 0; pair < cvms_bench::kSmallPairs; ++pair)
    for (int placement = 0; placement < 3; ++placement) b->Args({pair, placement});
}

BENCHMARK(BM_PenetrationBySum)->Apply(small_rows)->Unit(benchmark::kMicrosecond);

// A rotation in doubles: applied lazily (Placement) or materialised first.
cvms::Placement rotation_placement() {
  const double c = std::cos(0.7), s = std::sin(0.7);
  cvms::Placement p;
  p.rotation = {{{c, -s, 0.0}, {s, c, 0.0}, {0.0, 0.0, 1.0}}};
  p.translation = {2.5, 0.25, 0.125};
  return p;
}

void BM_DistancePlacedSphere(benchmark::State& state) {
  const ConvexPolyhedron a = cvms::shapes::geodesic_sphere(static_cast<int>(state.range(0)));
  const ConvexPolyhedron b = cvms::shapes::geodesic_sphere(static_cast<int>(state.range(0)));
  const cvms::Placement placement = rotation_placement();
  state.SetLabel("Sphere" + std::to_string(state.range(0)) + " vs Sphere placed (double rotation), lazily");
  for (auto _ : state) benchmark::DoNotOptimize(cvms::squared_distance(a, cvms::PlacedPolyhedron(b, placement)));
}

void BM_DistanceTransformedSphere(benchmark::State& state) {
  const ConvexPolyhedron a = cvms::shapes::geodesic_sphere(static_cast<int>(state.range(0)));
  const ConvexPolyhedron b = cvms::shapes::geodesic_sphere(static_cast<int>(state.range(0)));
  const cvms::Placement placement = rotation_placement();
  state.SetLabel("Sphere" + std::to_string(state.range(0)) + " vs Sphere transformed() first, then distance");
  for (auto _ : state) {
    const ConvexPolyhedron moved = cvms::PlacedPolyhedron(b, placement).materialized();
    benchmark::DoNotOptimize(cvms::squared_distance(a, moved));
  }
}

BENCHMARK(BM_DistancePlacedSphere)->DenseRange(3, 5)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DistanceTransformedSphere)->DenseRange(3, 5)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
