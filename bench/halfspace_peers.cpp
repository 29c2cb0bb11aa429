// SPDX-License-Identifier: MIT
// Peer rows of cvms_halfspace_bench (built only with CVMS_BENCH_PEERS, each
// peer when found): qhull's half-space intersection and CGAL's exact
// halfspace_intersection_3 on the same rows as the BM_FromHalfspaces_* rows
// (halfspace_operands.hpp), with the same interior point given. For qhull
// the exact rows are rounded to the nearest doubles before the timed loop:
// the sphere planes have primitive integer normals of about 100 bits, so
// qhull intersects planes within rounding of ours, in floating point, and
// its vertex count may differ from the exact one. CGAL takes them exactly.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <vector>

#include "halfspace_operands.hpp"
#include "peer_cgal.hpp"
#include "peer_qhalf.hpp"

#ifdef CVMS_BENCH_HAVE_CGAL
namespace {

// CGAL goes through the convex hull of the planes' dual points about the
// interior point, as from_halfspaces does, in its exact-constructions
// kernel (Epeck: interval filters, lazy exact numbers).
void cgal_halfspaces(benchmark::State& state, const cvms_bench::HalfspaceOperands& in) {
  const cvms_bench::CgalExactPlanes planes(in.rows, in.interior);
  cvms_bench::CgalIntersection r;
  for (auto _ : state) {
    r = planes.intersect();
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * in.rows.size()));
  state.counters["rows"] = static_cast<double>(in.rows.size());
  state.counters["V"] = static_cast<double>(r.vertices);
}

void BM_CgalHalfspaces_Sphere(benchmark::State& state) {
  cgal_halfspaces(state, cvms_bench::sphere_rows(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_CgalHalfspaces_Sphere)->DenseRange(4, 6)->Unit(benchmark::kMillisecond);

void BM_CgalHalfspaces_Redundant(benchmark::State& state) {
  cgal_halfspaces(state, cvms_bench::redundant_rows(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_CgalHalfspaces_Redundant)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace

#endif  // CVMS_BENCH_HAVE_CGAL

#ifdef CVMS_BENCH_HAVE_QHULL

namespace {

// a·x <= b becomes qhull's a·x − b <= 0.
std::vector<double> qhull_rows(const std::vector<cvms::HalfspaceRow>& rows) {
  std::vector<double> out;
  out.reserve(4 * rows.size());
  for (const cvms::HalfspaceRow& r : rows)
    out.insert(out.end(), {r.normal.x.get_d(), r.normal.y.get_d(), r.normal.z.get_d(), -r.offset.get_d()});
  return out;
}

void qhalf(benchmark::State& state, const cvms_bench::HalfspaceOperands& in) {
  const std::vector<double> rows = qhull_rows(in.rows);
  const std::array<double, 3> interior = {in.interior.x.get_d(), in.interior.y.get_d(), in.interior.z.get_d()};
  cvms_bench::QhalfResult r;
  for (auto _ : state) {
    r = cvms_bench::qhull_halfspaces(rows, interior);
    benchmark::DoNotOptimize(r);
  }
  if (r.vertices == 0) state.SkipWithError("qhull failed");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * in.rows.size()));
  state.counters["rows"] = static_cast<double>(in.rows.size());
  state.counters["V"] = static_cast<double>(r.vertices);
  state.counters["irredundant"] = static_cast<double>(r.rows);
}

void BM_Qhalf_Sphere(benchmark::State& state) { qhalf(state, cvms_bench::sphere_rows(static_cast<int>(state.range(0)))); }
BENCHMARK(BM_Qhalf_Sphere)->DenseRange(4, 6)->Unit(benchmark::kMillisecond);

void BM_Qhalf_Redundant(benchmark::State& state) {
  qhalf(state, cvms_bench::redundant_rows(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_Qhalf_Redundant)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace

#endif  // CVMS_BENCH_HAVE_QHULL
