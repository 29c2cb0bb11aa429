// SPDX-License-Identifier: MIT
// Peer rows of cvms_minkowski_bench (built only with CVMS_BENCH_PEERS, each
// peer only when found): the convex hull of all pairwise vertex sums a + b,
// which is A + B, by qhull (floating point, on the correctly rounded double
// sums) and by CGAL::convex_hull_3 (Epeck, on the exact sums). The sums are
// formed before the timed loop: only the hull is timed. Same row numbers as
// BM_CVMS (Table 1) and the same families and k as BM_CVMS_SphereRot /
// BM_CVMS_CubeSphere, capped where V_A * V_B points stop fitting the time
// and memory budget (< ~10 s per row, < 4 GB).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "bench_operands.hpp"
#include "cvms/shapes.hpp"
#include "heap_counter.hpp"
#ifdef CVMS_BENCH_HAVE_QHULL
#include "peer_qhull.hpp"
#endif
#ifdef CVMS_BENCH_HAVE_CGAL
#include "peer_cgal.hpp"
#endif

namespace {

using cvms_bench::Family;

void table_args(benchmark::internal::Benchmark* b) {
  for (int row = 0; row < static_cast<int>(cvms_bench::kTableRows.size()); ++row) b->Arg(row);
  b->Unit(benchmark::kMillisecond);
  cvms_bench::report_minimum(b);
}

// k from 3 to `largest` (capped at the families' largest k of this run).
void family_ks(benchmark::internal::Benchmark* b, int largest) {
  for (int k = 3; k <= std::min(largest, cvms_bench::largest_family_k()); ++k) b->Arg(k);
  b->Unit(benchmark::kMillisecond);
  cvms_bench::report_minimum(b);
}

// Sphere_k + rotated Sphere_k has (10 * 4^(k-1) + 2)^2 sums: 6.6 M at k = 5
// (qhull: a few seconds), 105 M at k = 6 (2.5 GB of doubles: out of budget).
// CGAL holds each exact point at a few hundred bytes: k = 4 (0.4 M points).
// Cube + Sphere_k has 8 * (10 * 4^(k-1) + 2) sums: 0.33 M at k = 7, 1.3 M at 8.
void qhull_sphere_rot_ks(benchmark::internal::Benchmark* b) { family_ks(b, 5); }
void cgal_sphere_rot_ks(benchmark::internal::Benchmark* b) { family_ks(b, 4); }
void cube_sphere_ks(benchmark::internal::Benchmark* b) { family_ks(b, 8); }

void operand_counters(benchmark::State& state, const cvms::ConvexPolyhedron& a,
                      const cvms::ConvexPolyhedron& b) {
  state.counters["input_facets"] = static_cast<double>(a.num_facets() + b.num_facets());
  state.counters["points"] = static_cast<double>(a.num_vertices()) * b.num_vertices();
}

#ifdef CVMS_BENCH_HAVE_QHULL
void run_qhull(benchmark::State& state, const cvms::ConvexPolyhedron& a, const cvms::ConvexPolyhedron& b,
               const std::string& label) {
  const std::vector<double> sums = cvms_bench::pairwise_sums_double(a, b);
  cvms_bench::QhullHull hull;
  std::size_t qhull_peak = 0;
  cvms_bench::reset_heap_peak();
  for (auto _ : state) {
    hull = cvms_bench::qhull_hull(sums);
    qhull_peak = std::max(qhull_peak, hull.peak_bytes);
    benchmark::DoNotOptimize(hull);
  }
  // qhull allocates with malloc, unseen by the counter: add its own peak.
  state.counters["peak_heap_bytes"] = static_cast<double>(cvms_bench::peak_heap_bytes() + qhull_peak);
  if (hull.facets == 0) {
    state.SkipWithError("qhull failed");
    return;
  }
  state.SetLabel(label);
  operand_counters(state, a, b);
  state.counters["peer_facets"] = static_cast<double>(hull.facets);
  state.counters["peer_vertices"] = static_cast<double>(hull.vertices);
}

void BM_Qhull_PairwiseSums(benchmark::State& state) {
  const int row = static_cast<int>(state.range(0));
  run_qhull(state, cvms::shapes::cube(), cvms_bench::table_operand(row),
            std::string("Cube+") + cvms_bench::kTableRows[static_cast<std::size_t>(row)]);
}
void run_qhull_family(benchmark::State& state, Family family) {
  const int k = static_cast<int>(state.range(0));
  const cvms_bench::Pair& p = cvms_bench::family_pair(family, k);
  run_qhull(state, p.a, p.b, cvms_bench::family_label(family, k));
}
void BM_Qhull_SphereRot(benchmark::State& state) { run_qhull_family(state, Family::sphere_rotated); }
void BM_Qhull_CubeSphere(benchmark::State& state) { run_qhull_family(state, Family::cube_sphere); }
BENCHMARK(BM_Qhull_PairwiseSums)->Apply(table_args);
BENCHMARK(BM_Qhull_SphereRot)->Apply(qhull_sphere_rot_ks);
BENCHMARK(BM_Qhull_CubeSphere)->Apply(cube_sphere_ks);
#endif

#ifdef CVMS_BENCH_HAVE_CGAL
void run_cgal(benchmark::State& state, const cvms::ConvexPolyhedron& a, const cvms::ConvexPolyhedron& b,
              const std::string& label) {
  const std::vector<cvms::Vec3> va = cvms_bench::vertex_points(a), vb = cvms_bench::vertex_points(b);
  const cvms_bench::CgalExactPoints sums(va, vb);
  cvms_bench::CgalHull hull;
  cvms_bench::reset_heap_peak();
  for (auto _ : state) {
    hull = sums.convex_hull();
    benchmark::DoNotOptimize(hull);
  }
  state.counters["peak_heap_bytes"] = static_cast<double>(cvms_bench::peak_heap_bytes());
  state.SetLabel(label);
  operand_counters(state, a, b);
  state.counters["peer_triangles"] = static_cast<double>(hull.triangles);
  state.counters["peer_vertices"] = static_cast<double>(hull.vertices);
}

void BM_CGAL_PairwiseSums(benchmark::State& state) {
  const int row = static_cast<int>(state.range(0));
  run_cgal(state, cvms::shapes::cube(), cvms_bench::table_operand(row),
           std::string("Cube+") + cvms_bench::kTableRows[static_cast<std::size_t>(row)]);
}
void run_cgal_family(benchmark::State& state, Family family) {
  const int k = static_cast<int>(state.range(0));
  const cvms_bench::Pair& p = cvms_bench::family_pair(family, k);
  run_cgal(state, p.a, p.b, cvms_bench::family_label(family, k));
}
void BM_CGAL_SphereRot(benchmark::State& state) { run_cgal_family(state, Family::sphere_rotated); }
void BM_CGAL_CubeSphere(benchmark::State& state) { run_cgal_family(state, Family::cube_sphere); }
BENCHMARK(BM_CGAL_PairwiseSums)->Apply(table_args);
BENCHMARK(BM_CGAL_SphereRot)->Apply(cgal_sphere_rot_ks);
BENCHMARK(BM_CGAL_CubeSphere)->Apply(cube_sphere_ks);
#endif

}  // namespace
