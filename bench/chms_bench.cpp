// SPDX-License-Identifier: MIT
// CHMS on the paper's Table 1 pairs Cube + Sphere1..Sphere6 (paper Section
// 6.3): the exact hull of all pairwise vertex sums. Reports the sum's V/E/F
// and the predicate filter's fallback rate.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "cvms/minkowski.hpp"
#include "cvms/predicates.hpp"
#include "cvms/quickhull.hpp"

namespace {

using cvms::Rational;
using cvms::Vec3;

// The vertices of an icosahedron subdivided k-1 times, projected to the unit
// sphere and rounded to double (the paper's Sphere_k).
std::vector<Vec3> geodesic_sphere_points(int k) {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<std::array<double, 3>> p;
  for (double a : {-1.0, 1.0})
    for (double b : {-phi, phi}) {
      p.push_back({0, a, b});
      p.push_back({a, b, 0});
      p.push_back({b, 0, a});
    }
  auto dist2 = [&](std::size_t i, std::size_t j) {
    double s = 0;
    for (int c = 0; c < 3; ++c) s += (p[i][c] - p[j][c]) * (p[i][c] - p[j][c]);
    return s;
  };
  std::vector<std::array<std::size_t, 3>> tris;  // icosahedron: triples at mutual distance 2
  for (std::size_t i = 0; i < 12; ++i)
    for (std::size_t j = i + 1; j < 12; ++j)
      for (std::size_t l = j + 1; l < 12; ++l)
        if (std::abs(dist2(i, j) - 4) < 1e-9 && std::abs(dist2(j, l) - 4) < 1e-9 &&
            std::abs(dist2(i, l) - 4) < 1e-9)
          tris.push_back({i, j, l});
  auto normalise = [](std::array<double, 3> v) {
    double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return std::array<double, 3>{v[0] / n, v[1] / n, v[2] / n};
  };
  for (auto& v : p) v = normalise(v);
  for (int level = 1; level < k; ++level) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> mid;
    auto midpoint = [&](std::size_t a, std::size_t b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      p.push_back(normalise({p[a][0] + p[b][0], p[a][1] + p[b][1], p[a][2] + p[b][2]}));
      return mid[key] = p.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> next;
    for (auto [a, b, c] : tris) {
      std::size_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      next.push_back({a, ab, ca});
      next.push_back({b, bc, ab});
      next.push_back({c, ca, bc});
      next.push_back({ab, bc, ca});
    }
    tris = std::move(next);
  }
  std::vector<Vec3> out;
  for (const auto& v : p) out.push_back({Rational(v[0]), Rational(v[1]), Rational(v[2])});
  return out;
}

cvms::ConvexPolyhedron cube() {
  std::vector<Vec3> pts;
  for (int c = 0; c < 8; ++c) pts.push_back({c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1});
  return cvms::convex_hull(pts);
}

void cube_plus_sphere(benchmark::State& state) {
  const cvms::ConvexPolyhedron a = cube();
  const cvms::ConvexPolyhedron b =
      cvms::convex_hull(geodesic_sphere_points(static_cast<int>(state.range(0))));
  cvms::predicate_counters() = {};
  cvms::ConvexPolyhedron sum;
  for (auto _ : state) sum = cvms::chms(a, b);
  const auto& c = cvms::predicate_counters();
  state.counters["sphere_F"] = b.num_facets();
  state.counters["sum_V"] = sum.num_vertices();
  state.counters["sum_E"] = sum.num_edges();
  state.counters["sum_F"] = sum.num_facets();
  state.counters["facets_per_second"] =
      benchmark::Counter(static_cast<double>(sum.num_facets()) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
  state.counters["exact_rate"] =
      c.filtered + c.exact == 0 ? 0.0
                                : static_cast<double>(c.exact) / static_cast<double>(c.filtered + c.exact);
}

BENCHMARK(cube_plus_sphere)->Name("chms/cube+sphere")->DenseRange(1, 6)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
