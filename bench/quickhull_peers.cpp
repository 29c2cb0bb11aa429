// SPDX-License-Identifier: MIT
// Peer rows of cvms_quickhull_bench (built only with CVMS_BENCH_PEERS and a
// found qhull): qhull on the identical seeded clouds as the hull_soup/...
// rows of quickhull_bench.cpp, and on the pairwise vertex sums of
// Cube + Sphere6 next to our exact quickhull on the same sums.
//
// The cloud generator repeats quickhull_bench.cpp's (same engine, same
// distribution, same rejection for the ball, same seed 12345): that file
// keeps its own copy, so a change to one must be made to the other.
#include <benchmark/benchmark.h>

#ifdef CVMS_BENCH_HAVE_QHULL

#include <cstdint>
#include <random>
#include <vector>

#include "cvms/shapes.hpp"
#include "peer_qhull.hpp"
#include "hull_soup.hpp"

namespace {

// x y z per point, exactly the doubles that quickhull_bench.cpp's cloud()
// turns into rationals.
std::vector<double> cloud_xyz(std::size_t n, bool ball, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> xyz;
  xyz.reserve(3 * n);
  while (xyz.size() < 3 * n) {
    double x = u(rng), y = u(rng), z = u(rng);
    if (!ball || x * x + y * y + z * z <= 1.0) xyz.insert(xyz.end(), {x, y, z});
  }
  return xyz;
}

void report(benchmark::State& state, const cvms_bench::QhullHull& hull, std::size_t points) {
  if (hull.facets == 0) state.SkipWithError("qhull failed");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * points));
  state.counters["hull_V"] = static_cast<double>(hull.vertices);
  state.counters["hull_F"] = static_cast<double>(hull.facets);
}

template <bool Ball>
void qhull_cloud(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::vector<double> xyz = cloud_xyz(n, Ball, 12345);
  cvms_bench::QhullHull hull;
  for (auto _ : state) {
    hull = cvms_bench::qhull_hull(xyz);
    benchmark::DoNotOptimize(hull);
  }
  report(state, hull, n);
}

BENCHMARK(qhull_cloud<true>)
    ->Name("qhull/ball")
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(qhull_cloud<false>)
    ->Name("qhull/cube")
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMillisecond);

// The 8 * 10,242 pairwise vertex sums of Cube + Sphere6: exact for our
// quickhull, the (correctly rounded) double sums for qhull.
std::vector<cvms::Vec3> cube_sphere6_sums() {
  const cvms::ConvexPolyhedron a = cvms::shapes::cube(), b = cvms::shapes::geodesic_sphere(6);
  std::vector<cvms::Vec3> sums;
  sums.reserve(std::size_t{a.num_vertices()} * b.num_vertices());
  for (cvms::VertexId u : a.mesh().vertices())
    for (cvms::VertexId v : b.mesh().vertices()) sums.push_back(a.vertex(u) + b.vertex(v));
  return sums;
}

void qhull_cube_sphere6_sums(benchmark::State& state) {
  std::vector<double> xyz;
  const std::vector<cvms::Vec3> sums = cube_sphere6_sums();
  for (const cvms::Vec3& p : sums) xyz.insert(xyz.end(), {p.x.get_d(), p.y.get_d(), p.z.get_d()});
  cvms_bench::QhullHull hull;
  for (auto _ : state) {
    hull = cvms_bench::qhull_hull(xyz);
    benchmark::DoNotOptimize(hull);
  }
  report(state, hull, sums.size());
}

void quickhull_cube_sphere6_sums(benchmark::State& state) {
  const std::vector<cvms::Vec3> sums = cube_sphere6_sums();
  std::size_t vertices = 0, facets = 0;
  for (auto _ : state) {
    cvms::PolygonSoup soup = cvms::hull_soup(sums);
    vertices = soup.points.size();
    facets = soup.num_faces();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * sums.size()));
  state.counters["hull_V"] = static_cast<double>(vertices);
  state.counters["hull_F"] = static_cast<double>(facets);
}

BENCHMARK(qhull_cube_sphere6_sums)->Name("qhull/cube_sphere6_sums")->Unit(benchmark::kMillisecond);
// Side-by-side partner of the row above (exact hull_soup, as in hull_soup/...).
BENCHMARK(quickhull_cube_sphere6_sums)
    ->Name("hull_soup_peer/cube_sphere6_sums")
    ->Unit(benchmark::kMillisecond);

}  // namespace

#endif  // CVMS_BENCH_HAVE_QHULL
