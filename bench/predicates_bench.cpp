// SPDX-License-Identifier: MIT
// Throughput of the filtered predicates (cached approximations, and on-the-fly
// approximations) against the exact-only evaluation, on random doubles, on
// random decimals (inexact leaves) and on a near-degenerate set (points
// coplanar up to the last bit), with the fallback rate as a counter.
//
// Argument: 0 = random doubles in [-1, 1], 1 = random 6-digit decimals,
// 2 = near-degenerate (fourth point an affine combination rounded to double).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "filtered_predicates.hpp"
#include "predicates_exact.hpp"

namespace {

using cvms::ApproxVec3;
using cvms::Rational;
using cvms::Vec3;
using cvms::Vec3Ref;

constexpr std::size_t points_per_set = 4096;  // a multiple of 4: quadruples (4k, 4k+1, 4k+2, 4k+3)

struct PointSet {
  std::vector<Vec3> exact;
  std::vector<ApproxVec3> approx;
  [[nodiscard]] Vec3Ref ref(std::size_t i) const { return {exact[i], approx[i]}; }
};

PointSet make_points(int kind) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto decimal = [&] {
    std::string s = (rng() & 1) ? "-0." : "0.";
    return cvms::parse_rational(s + std::to_string(100000 + rng() % 900000));
  };
  PointSet set;
  while (set.exact.size() < points_per_set) {
    if (kind == 0) {
      set.exact.push_back(Vec3{Rational(unit(rng)), Rational(unit(rng)), Rational(unit(rng))});
    } else if (kind == 1) {
      set.exact.push_back(Vec3{decimal(), decimal(), decimal()});
    } else {
      Vec3 a{Rational(unit(rng)), Rational(unit(rng)), Rational(unit(rng))};
      Vec3 b{Rational(unit(rng)), Rational(unit(rng)), Rational(unit(rng))};
      Vec3 c{Rational(unit(rng)), Rational(unit(rng)), Rational(unit(rng))};
      Rational s(unit(rng)), t(unit(rng));
      Vec3 d = a + s * (b - a) + t * (c - a);
      for (int k = 0; k < 3; ++k) d[k] = Rational(cvms::to_double_nearest(d[k]));
      for (const Vec3& p : {a, b, c, d}) set.exact.push_back(p);
    }
  }
  for (const Vec3& p : set.exact) set.approx.push_back(ApproxVec3::of(p));
  return set;
}

const PointSet& points(int kind) {
  static const PointSet sets[3] = {make_points(0), make_points(1), make_points(2)};
  return sets[kind];
}

void report(benchmark::State& state, const cvms::PredicateCounters& before) {
  const cvms::PredicateCounters& now = cvms::predicate_counters();
  double filtered = static_cast<double>(now.filtered - before.filtered);
  double exact = static_cast<double>(now.exact - before.exact);
  state.SetItemsProcessed(state.iterations());
  state.counters["fallback_rate"] = filtered + exact > 0 ? exact / (filtered + exact) : 0.0;
}

void BM_orient3d_filtered(benchmark::State& state) {
  const PointSet& set = points(static_cast<int>(state.range(0)));
  cvms::PredicateCounters before = cvms::predicate_counters();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(cvms::orient3d(set.ref(i), set.ref(i + 1), set.ref(i + 2), set.ref(i + 3)));
    i = (i + 4) % points_per_set;
  }
  report(state, before);
}
BENCHMARK(BM_orient3d_filtered)->Arg(0)->Arg(1)->Arg(2);

void BM_orient3d_on_the_fly(benchmark::State& state) {
  const PointSet& set = points(static_cast<int>(state.range(0)));
  cvms::PredicateCounters before = cvms::predicate_counters();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        cvms::orient3d(set.exact[i], set.exact[i + 1], set.exact[i + 2], set.exact[i + 3]));
    i = (i + 4) % points_per_set;
  }
  report(state, before);
}
BENCHMARK(BM_orient3d_on_the_fly)->Arg(0)->Arg(1)->Arg(2);

void BM_orient3d_exact_only(benchmark::State& state) {
  const PointSet& set = points(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        cvms::exact::orient3d(set.exact[i], set.exact[i + 1], set.exact[i + 2], set.exact[i + 3]));
    i = (i + 4) % points_per_set;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_orient3d_exact_only)->Arg(0)->Arg(1)->Arg(2);

// compare_dot(v, w, n) with consecutive points; on the near-degenerate set
// the same quadruples are used, which are not degenerate for this predicate.
void BM_compare_dot_filtered(benchmark::State& state) {
  const PointSet& set = points(static_cast<int>(state.range(0)));
  cvms::PredicateCounters before = cvms::predicate_counters();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(cvms::compare_dot(set.ref(i), set.ref(i + 1), set.ref(i + 2)));
    i = (i + 4) % points_per_set;
  }
  report(state, before);
}
BENCHMARK(BM_compare_dot_filtered)->Arg(0)->Arg(1);

void BM_compare_dot_exact_only(benchmark::State& state) {
  const PointSet& set = points(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(cvms::exact::compare_dot(set.exact[i], set.exact[i + 1], set.exact[i + 2]));
    i = (i + 4) % points_per_set;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_compare_dot_exact_only)->Arg(0)->Arg(1);

// compare_dot where v and w are equally far along n up to the last bit:
// w = v + (a rounded vector perpendicular to n).
void BM_compare_dot_near_degenerate(benchmark::State& state) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> exact;
  for (std::size_t k = 0; k < points_per_set / 4; ++k) {
    Vec3 v{Rational(unit(rng)), Rational(unit(rng)), Rational(unit(rng))};
    Vec3 n{Rational(unit(rng)), Rational(unit(rng)), Rational(unit(rng))};
    Vec3 r{Rational(unit(rng)), Rational(unit(rng)), Rational(unit(rng))};
    Vec3 w = v + cvms::cross(n, r);
    for (int c = 0; c < 3; ++c) w[c] = Rational(cvms::to_double_nearest(w[c]));
    for (const Vec3& p : {v, w, n, n}) exact.push_back(p);
  }
  std::vector<ApproxVec3> approx;
  for (const Vec3& p : exact) approx.push_back(ApproxVec3::of(p));
  cvms::PredicateCounters before = cvms::predicate_counters();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(cvms::compare_dot(Vec3Ref{exact[i], approx[i]},
                                               Vec3Ref{exact[i + 1], approx[i + 1]},
                                               Vec3Ref{exact[i + 2], approx[i + 2]}));
    i = (i + 4) % points_per_set;
  }
  report(state, before);
}
BENCHMARK(BM_compare_dot_near_degenerate);

}  // namespace

BENCHMARK_MAIN();
