// SPDX-License-Identifier: MIT
// The paper's Table 1 family: Cube + {Tetra, Hedra, Truncated cube,
// Sphere1..Sphere6} for each algorithm (CHMS, ESSDMS, paper-faithful CVMS,
// output-sensitive CVMS), measured side by side in one run; the scaling
// families Sphere_k + rotated Sphere_k and Cube + Sphere_k with the time per
// output facet; and the limit: building the output alone from the final
// facet vertex-pair lists. bench/table.py turns the JSON output into the
// table of docs/performance.md. Every row reports peak_heap_bytes: the peak of live heap
// bytes (C++ and GMP) during the timed loop above what existed before it
// (inputs excluded), see heap_counter.hpp.
#include <benchmark/benchmark.h>

#include <string>

#include "bench_operands.hpp"
#include "cvms_algorithm.hpp"
#include "cvms/error.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/shapes.hpp"
#include "heap_counter.hpp"
#include "stitch.hpp"

namespace {

using cvms::Algorithm;
using cvms::ConvexPolyhedron;

using cvms_bench::Family;
using cvms_bench::family_label;
using cvms_bench::family_pair;
using cvms_bench::Pair;
constexpr const auto& kRows = cvms_bench::kTableRows;
const ConvexPolyhedron& operand(int row) { return cvms_bench::table_operand(row); }

// The default CVMS with Options::threads = n (workers inside the call).
// Timed in real time: the CPU time of the calling thread alone would flatter
// it. It reports no peak_heap_bytes: the counters are per thread and would
// miss the workers' allocations.
cvms::Options with_threads(unsigned n) {
  cvms::Options o;
  o.threads = n;
  return o;
}

cvms::Options with_algorithm(Algorithm algorithm) {
  cvms::Options o;
  o.algorithm = algorithm;
  return o;
}

// research: the paper-faithful rows pass cvms::detail::paper_search().
void run_sum(benchmark::State& state, const cvms::Options& options, const cvms::detail::ResearchOptions& research = {}) {
  const int row = static_cast<int>(state.range(0));
  const ConvexPolyhedron cube = cvms::shapes::cube();
  const ConvexPolyhedron& b = operand(row);
  std::uint32_t facets = 0;
  cvms::SumDiagnostics diagnostics;
  cvms::Options counted = options;
  counted.diagnostics = &diagnostics;
  cvms_bench::reset_heap_peak();
  for (auto _ : state) {
    try {
      cvms::MinkowskiResult r = cvms::detail::minkowski_sum(cube, b, counted, research);
      facets = r.polyhedron.num_facets();
      benchmark::DoNotOptimize(facets);
    } catch (const cvms::Error& e) {
      state.SkipWithError(e.what());
      return;
    }
  }
  if (options.threads <= 1)
    state.counters["peak_heap_bytes"] = static_cast<double>(cvms_bench::peak_heap_bytes());
  state.SetLabel(std::string("Cube+") + kRows[static_cast<std::size_t>(row)]);
  state.counters["input_facets"] = static_cast<double>(cube.num_facets() + b.num_facets());
  state.counters["output_facets"] = facets;
  state.counters["facets_per_second"] =
      benchmark::Counter(static_cast<double>(facets), benchmark::Counter::kIsIterationInvariantRate);
  const double predicates = static_cast<double>(diagnostics.predicate_filtered + diagnostics.predicate_exact);
  if (predicates > 0)
    state.counters["exact_fallback_rate"] = static_cast<double>(diagnostics.predicate_exact) / predicates;
}

void table_args(benchmark::internal::Benchmark* b) {
  for (int row = 0; row < static_cast<int>(kRows.size()); ++row) b->Arg(row);
  b->Unit(benchmark::kMillisecond);
  cvms_bench::report_minimum(b);
}

void BM_CHMS(benchmark::State& state) { run_sum(state, with_algorithm(Algorithm::chms)); }
void BM_ESSDMS(benchmark::State& state) { run_sum(state, with_algorithm(Algorithm::essdms)); }
void BM_CVMS_paper(benchmark::State& state) { run_sum(state, {}, cvms::detail::paper_search()); }
void BM_CVMS(benchmark::State& state) { run_sum(state, with_algorithm(Algorithm::cvms)); }
BENCHMARK(BM_CHMS)->Apply(table_args);
BENCHMARK(BM_ESSDMS)->Apply(table_args);
BENCHMARK(BM_CVMS_paper)->Apply(table_args);
BENCHMARK(BM_CVMS)->Apply(table_args);
void BM_CVMS_2threads(benchmark::State& state) { run_sum(state, with_threads(2)); }
BENCHMARK(BM_CVMS_2threads)->Apply(table_args)->UseRealTime();

// --- Scaling families (bench_operands.hpp): Sphere_k + rotated Sphere_k and Cube + Sphere_k.

void per_facet_counters(benchmark::State& state, const Pair& p, double facets) {
  state.counters["input_facets"] = static_cast<double>(p.a.num_facets() + p.b.num_facets());
  state.counters["output_facets"] = facets;
  // Seconds per output facet (Google Benchmark prints it in the time unit of the counter: s).
  state.counters["time_per_output_facet"] =
      benchmark::Counter(facets, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void run_family(benchmark::State& state, Family family, const cvms::Options& options,
                const cvms::detail::ResearchOptions& research = {}) {
  const int k = static_cast<int>(state.range(0));
  const Pair& p = family_pair(family, k);
  std::uint32_t facets = 0;
  cvms::Stats stats;
  cvms::SumDiagnostics diagnostics;
  cvms::Options counted = options;
  counted.diagnostics = &diagnostics;
  cvms_bench::reset_heap_peak();
  for (auto _ : state) {
    cvms::MinkowskiResult r = cvms::detail::minkowski_sum(p.a, p.b, counted, research);
    facets = r.polyhedron.num_facets();
    stats = r.stats;
    benchmark::DoNotOptimize(facets);
  }
  if (options.threads <= 1)
    state.counters["peak_heap_bytes"] = static_cast<double>(cvms_bench::peak_heap_bytes());
  state.SetLabel(family_label(family, k));
  per_facet_counters(state, p, facets);
  state.counters["edge_facets"] = static_cast<double>(stats.edge_facets);
  const double predicates = static_cast<double>(diagnostics.predicate_filtered + diagnostics.predicate_exact);
  if (predicates > 0)
    state.counters["exact_fallback_rate"] = static_cast<double>(diagnostics.predicate_exact) / predicates;
}

// The limit: only the output construction, from the final facet vertex-pair
// lists that CVMS computed once before timing. `full` is all of what CVMS
// does after finding the facets (SumFacetBuilder::build: the mesh, its packed
// exact points and their approximations, the facet normals); otherwise only
// the mesh and its exact points, made the same way (build_mesh).
void run_output_only(benchmark::State& state, Family family, bool full) {
  const int k = static_cast<int>(state.range(0));
  const Pair& p = family_pair(family, k);
  cvms::detail::SumCounters stats;
  const cvms::detail::SumFacetBuilder facets = cvms::detail::cvms_facets(p.a, p.b, cvms::Options{}, {}, stats);
  cvms_bench::reset_heap_peak();
  for (auto _ : state) {
    if (full) {
      ConvexPolyhedron s = facets.build();
      benchmark::DoNotOptimize(s);
    } else {
      cvms::Mesh m = facets.build_mesh();
      benchmark::DoNotOptimize(m);
    }
  }
  state.counters["peak_heap_bytes"] = static_cast<double>(cvms_bench::peak_heap_bytes());
  state.SetLabel(family_label(family, k));
  per_facet_counters(state, p, static_cast<double>(facets.num_facets()));
}

// k = 3..7 (Sphere7 + rotated Sphere7: 81,920 + 81,920 facets); k = 8
// (327,680 + 327,680 facets) only with CVMS_BENCH_LARGE=1, which keeps the
// default run short (bench_operands.hpp: largest_family_k).
void family_args(benchmark::internal::Benchmark* b) {
  for (int k = 3; k <= cvms_bench::largest_family_k(); ++k) b->Arg(k);
  b->Unit(benchmark::kMillisecond);
  cvms_bench::report_minimum(b);
}
void small_family_args(benchmark::internal::Benchmark* b) {
  for (int k = 3; k <= 5; ++k) b->Arg(k);
  b->Unit(benchmark::kMillisecond);
  cvms_bench::report_minimum(b);
}

void BM_CVMS_SphereRot(benchmark::State& state) { run_family(state, Family::sphere_rotated, {}); }
void BM_CVMS_paper_SphereRot(benchmark::State& state) {
  run_family(state, Family::sphere_rotated, {}, cvms::detail::paper_search());
}
void BM_CVMS_CubeSphere(benchmark::State& state) { run_family(state, Family::cube_sphere, {}); }
void BM_CVMS_2threads_SphereRot(benchmark::State& state) {
  run_family(state, Family::sphere_rotated, with_threads(2));
}
void BM_CVMS_2threads_CubeSphere(benchmark::State& state) {
  run_family(state, Family::cube_sphere, with_threads(2));
}
// Up to 4 threads, no more than the cores (on two cores the 2-thread path).
void BM_CVMS_4threads_SphereRot(benchmark::State& state) {
  run_family(state, Family::sphere_rotated, with_threads(4));
}
void BM_Limit_Mesh_SphereRot(benchmark::State& state) {
  run_output_only(state, Family::sphere_rotated, false);
}
void BM_Limit_Build_SphereRot(benchmark::State& state) {
  run_output_only(state, Family::sphere_rotated, true);
}
void BM_Limit_Mesh_CubeSphere(benchmark::State& state) { run_output_only(state, Family::cube_sphere, false); }
void BM_Limit_Build_CubeSphere(benchmark::State& state) { run_output_only(state, Family::cube_sphere, true); }
BENCHMARK(BM_CVMS_SphereRot)->Apply(family_args);
BENCHMARK(BM_Limit_Mesh_SphereRot)->Apply(family_args);
BENCHMARK(BM_Limit_Build_SphereRot)->Apply(family_args);
BENCHMARK(BM_CVMS_paper_SphereRot)->Apply(small_family_args);
BENCHMARK(BM_CVMS_CubeSphere)->Apply(family_args);
BENCHMARK(BM_CVMS_2threads_SphereRot)->Apply(family_args)->UseRealTime();
BENCHMARK(BM_CVMS_2threads_CubeSphere)->Apply(family_args)->UseRealTime();
BENCHMARK(BM_CVMS_4threads_SphereRot)->Apply(family_args)->UseRealTime();
BENCHMARK(BM_Limit_Mesh_CubeSphere)->Apply(family_args);
BENCHMARK(BM_Limit_Build_CubeSphere)->Apply(family_args);

}  // namespace

BENCHMARK_MAIN();
