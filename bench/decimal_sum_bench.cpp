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
//
// And the scaling families of cvms_minkowski_bench at k = 6 (Sphere6 +
// rotated Sphere6, Cube + Sphere6: every coordinate a double) with both
// operands written as text in three forms (decimal_point.hpp): the exact
// binary expansions of the doubles, the shortest round-trip decimals of the
// same doubles, and 6 decimals. Rows <Family>/<k>/<form> (form 0 dyadic,
// 1 shortest, 2 six digits): the same sum side by side, each operand read
// from its text (read_off from a string stream, then from_soup) outside the
// timing with their facet planes, so that only the representation of the
// numbers differs.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <sstream>
#include <tuple>
#include <random>
#include <vector>

#include "bench_operands.hpp"
#include "cvms/convex_hull.hpp"
#include "cvms/io.hpp"
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

using cvms_bench::Family;
using cvms_bench::TextForm;

// p written in `form` and read back, its facet planes made (a loaded
// polyhedron makes them on first use, which the first sum would pay inside
// the timing: the load rows of cvms_load_bench time that).
ConvexPolyhedron read_back(const ConvexPolyhedron& p, TextForm form) {
  std::istringstream in(cvms_bench::off_text(p.to_soup(), form));
  ConvexPolyhedron q = cvms::to_polyhedron(cvms::read_off(in, "operand"), "operand");
  benchmark::DoNotOptimize(&q.normal(cvms::FaceId(0)));
  return q;
}

// The family member's operands, written in `form` and read back (once per process).
const cvms_bench::Pair& written_pair(Family family, int k, TextForm form) {
  static std::map<std::tuple<Family, int, TextForm>, cvms_bench::Pair> cache;
  const auto key = std::make_tuple(family, k, form);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  const cvms_bench::Pair& exact = cvms_bench::family_pair(family, k);
  cvms_bench::Pair p{read_back(exact.a, form), read_back(exact.b, form)};
  return cache.emplace(key, std::move(p)).first->second;
}

// The share of predicate calls that exact arithmetic decided, from one sum
// outside the timing (diagnostics cost a little inside it).
double exact_share(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  cvms::SumDiagnostics diagnostics;
  cvms::Options options;
  options.diagnostics = &diagnostics;
  (void)cvms::minkowski_sum(a, b, options);
  const double total = static_cast<double>(diagnostics.predicate_filtered + diagnostics.predicate_exact);
  return total > 0 ? static_cast<double>(diagnostics.predicate_exact) / total : 0.0;
}

void run_written(benchmark::State& state, Family family) {
  const int k = static_cast<int>(state.range(0));
  const auto form = static_cast<TextForm>(state.range(1));
  const cvms_bench::Pair& p = written_pair(family, k, form);
  run(state, p.a, p.b);
  state.counters["exact_share"] = exact_share(p.a, p.b);
  state.SetLabel(cvms_bench::family_label(family, k) + " " + cvms_bench::text_form_name(form));
}

void BM_Written_SphereRot(benchmark::State& state) { run_written(state, Family::sphere_rotated); }
void BM_Written_CubeSphere(benchmark::State& state) { run_written(state, Family::cube_sphere); }

void written_args(benchmark::internal::Benchmark* b) {
  b->ArgsProduct({{6}, {0, 1, 2}})->Unit(benchmark::kMillisecond);
}
BENCHMARK(BM_Written_SphereRot)->Apply(written_args);
BENCHMARK(BM_Written_CubeSphere)->Apply(written_args);

}  // namespace

BENCHMARK_MAIN();
