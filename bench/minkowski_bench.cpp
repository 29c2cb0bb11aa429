// SPDX-License-Identifier: MIT
// The paper's Table 1 family: Cube + {Tetra, Hedra, Truncated cube,
// Sphere1..Sphere6} for each algorithm, measured side by side in one run.
// bench/table.py turns the JSON output into the README table.
#include <benchmark/benchmark.h>

#include <array>
#include <map>
#include <string>

#include "cvms/error.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/shapes.hpp"

namespace {

using cvms::Algorithm;
using cvms::ConvexPolyhedron;

// Operand B of each Table 1 row, in the paper's order.
constexpr std::array<const char*, 9> kRows = {"Tetra",   "Hedra",   "TruncatedCube", "Sphere1", "Sphere2",
                                              "Sphere3", "Sphere4", "Sphere5",       "Sphere6"};

const ConvexPolyhedron& operand(int row) {
  // Built once per process (not per benchmark iteration); benchmarks are single-threaded.
  static std::map<int, ConvexPolyhedron> cache;
  auto it = cache.find(row);
  if (it != cache.end()) return it->second;
  ConvexPolyhedron p;
  switch (row) {
    case 0:
      p = cvms::shapes::tetrahedron();
      break;
    case 1:
      p = cvms::shapes::octahedron();
      break;
    case 2:
      p = cvms::shapes::truncated_cube();
      break;
    default:
      p = cvms::shapes::geodesic_sphere(row - 2);
      break;
  }
  return cache.emplace(row, std::move(p)).first->second;
}

void run_sum(benchmark::State& state, Algorithm algorithm) {
  const int row = static_cast<int>(state.range(0));
  const ConvexPolyhedron cube = cvms::shapes::cube();
  const ConvexPolyhedron& b = operand(row);
  cvms::Options options;
  options.algorithm = algorithm;
  std::uint32_t facets = 0;
  cvms::Stats stats;
  for (auto _ : state) {
    try {
      cvms::MinkowskiResult r = cvms::minkowski_sum(cube, b, options);
      facets = r.polyhedron.num_facets();
      stats = r.stats;
      benchmark::DoNotOptimize(facets);
    } catch (const cvms::Error& e) {
      state.SkipWithError(e.what());
      return;
    }
  }
  state.SetLabel(std::string("Cube+") + kRows[static_cast<std::size_t>(row)]);
  state.counters["input_facets"] = static_cast<double>(cube.num_facets() + b.num_facets());
  state.counters["output_facets"] = facets;
  state.counters["facets_per_second"] =
      benchmark::Counter(static_cast<double>(facets), benchmark::Counter::kIsIterationInvariantRate);
  const double predicates = static_cast<double>(stats.predicate_filtered + stats.predicate_exact);
  if (predicates > 0)
    state.counters["exact_fallback_rate"] = static_cast<double>(stats.predicate_exact) / predicates;
}

void table_args(benchmark::internal::Benchmark* b) {
  for (int row = 0; row < static_cast<int>(kRows.size()); ++row) b->Arg(row);
  b->Unit(benchmark::kMillisecond);
}

void BM_CHMS(benchmark::State& state) { run_sum(state, Algorithm::chms); }
void BM_CVMS(benchmark::State& state) { run_sum(state, Algorithm::cvms); }
void BM_ESSDMS(benchmark::State& state) { run_sum(state, Algorithm::essdms); }
BENCHMARK(BM_CHMS)->Apply(table_args);
BENCHMARK(BM_ESSDMS)->Apply(table_args);
BENCHMARK(BM_CVMS)->Apply(table_args);

}  // namespace

BENCHMARK_MAIN();
