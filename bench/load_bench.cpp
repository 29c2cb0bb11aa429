// SPDX-License-Identifier: MIT
// What a user waits for before any sum (issue 14): loading a polyhedron,
// i.e. parsing its exact OFF text and validating it (ConvexPolyhedron::
// from_soup: convexity, merging, planes). Two inputs: Sphere6 (20,480
// triangles, double coordinates written as their exact decimal expansions)
// and the hull of 35,000 random points with 6-digit decimal coordinates
// (like scanned meshes exported by Meshlab: every coordinate inexact in
// binary). The texts are made before the timed loop.
//
// Rows: load/<input> (parse + validate, what read_polyhedron does),
// parse/<input> (read_off alone) and validate/<input> (from_soup of the
// parsed soup, copied before each run outside the timing).
//
// And what a user waits for after a sum: write/<input> writes the exact OFF
// of Sphere6 and of Sphere6 + rotated Sphere6 (a 60,000-facet result) to
// memory, next to sum/Sphere6+rotated_Sphere6, the in-process sum it is
// the output of (issue 14: writing costs a small fraction of computing).
#include <benchmark/benchmark.h>

#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/io.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/shapes.hpp"
#include "decimal_point.hpp"

namespace {

using cvms::ConvexPolyhedron;
using cvms::PolygonSoup;

std::string off_text(const ConvexPolyhedron& p) {
  std::ostringstream out;
  cvms::write_off(out, p.to_soup());
  return out.str();
}

// Random points in the unit ball, each coordinate written with 6 decimals.
std::string decimal_hull_text(int n) {
  std::mt19937_64 rng(35000);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::string text;
  std::vector<cvms::Vec3> points;
  while (static_cast<int>(points.size()) < n) {
    const double x = unit(rng), y = unit(rng), z = unit(rng);
    if (x * x + y * y + z * z > 1.0) continue;
    points.push_back(cvms_bench::six_decimal_point(x, y, z));
  }
  return off_text(cvms::convex_hull(points));
}

const std::string& input(int which) {
  static const std::string sphere6 = off_text(cvms::shapes::geodesic_sphere(6));
  static const std::string decimal = decimal_hull_text(35000);
  return which == 0 ? sphere6 : decimal;
}

const char* name(int which) { return which == 0 ? "Sphere6" : "decimal_hull_35000"; }

PolygonSoup parse(int which) {
  std::istringstream in(input(which));
  return cvms::read_off(in, name(which));
}

void BM_load(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  (void)input(which);
  for (auto _ : state) {
    std::istringstream in(input(which));
    ConvexPolyhedron p = cvms::to_polyhedron(cvms::read_off(in, name(which)), name(which));
    benchmark::DoNotOptimize(p.num_facets());
  }
  state.SetLabel(name(which));
}
BENCHMARK(BM_load)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_parse(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  (void)input(which);
  for (auto _ : state) {
    PolygonSoup soup = parse(which);
    benchmark::DoNotOptimize(soup.points.size());
  }
  state.SetLabel(name(which));
}
BENCHMARK(BM_parse)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_validate(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  const PolygonSoup soup = parse(which);
  for (auto _ : state) {
    state.PauseTiming();
    PolygonSoup copy = soup;
    state.ResumeTiming();
    ConvexPolyhedron p = ConvexPolyhedron::from_soup(std::move(copy));
    benchmark::DoNotOptimize(p.num_facets());
  }
  state.SetLabel(name(which));
}
BENCHMARK(BM_validate)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

const ConvexPolyhedron& written(int which) {
  static const ConvexPolyhedron sphere6 = cvms::shapes::geodesic_sphere(6);
  static const ConvexPolyhedron sum =
      cvms::minkowski_sum(sphere6, cvms::shapes::rotated_geodesic_sphere(6)).polyhedron;
  return which == 0 ? sphere6 : sum;
}

const char* written_name(int which) { return which == 0 ? "Sphere6" : "Sphere6+rotated_Sphere6"; }

void BM_write(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  const PolygonSoup soup = written(which).to_soup();
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::ostringstream out;
    cvms::write_off(out, soup);
    bytes = out.str().size();
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["bytes"] = static_cast<double>(bytes);
  state.counters["facets"] = static_cast<double>(written(which).num_facets());
  state.SetLabel(written_name(which));
}
BENCHMARK(BM_write)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_sum(benchmark::State& state) {
  const ConvexPolyhedron& a = written(0);
  const ConvexPolyhedron b = cvms::shapes::rotated_geodesic_sphere(6);
  for (auto _ : state) {
    ConvexPolyhedron sum = cvms::minkowski_sum(a, b).polyhedron;
    benchmark::DoNotOptimize(sum.num_facets());
  }
  state.SetLabel(written_name(1));
}
BENCHMARK(BM_sum)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
