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
#include <benchmark/benchmark.h>

#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/io.hpp"
#include "cvms/shapes.hpp"

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
    cvms::Vec3 p;
    const double c[3] = {x, y, z};
    for (int i = 0; i < 3; ++i) {
      char digits[32];
      std::snprintf(digits, sizeof digits, "%.6f", c[i]);
      p[i] = cvms::parse_rational(digits);
    }
    points.push_back(p);
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

}  // namespace

BENCHMARK_MAIN();
