// SPDX-License-Identifier: MIT
#include "bench_operands.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <map>
#include <utility>

#include "cvms/shapes.hpp"

namespace cvms_bench {

// The caches below are filled on first use; benchmarks are single-threaded.

const cvms::ConvexPolyhedron& table_operand(int row) {
  static std::map<int, cvms::ConvexPolyhedron> cache;
  auto it = cache.find(row);
  if (it != cache.end()) return it->second;
  cvms::ConvexPolyhedron p;
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

const Pair& family_pair(Family family, int k) {
  static std::map<std::pair<int, int>, Pair> cache;
  const std::pair<int, int> key{static_cast<int>(family), k};
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  Pair p;
  if (family == Family::sphere_rotated) {
    p.a = cvms::shapes::geodesic_sphere(k);
    p.b = cvms::shapes::rotated_geodesic_sphere(k);
  } else {
    p.a = cvms::shapes::cube();
    p.b = cvms::shapes::geodesic_sphere(k);
  }
  return cache.emplace(key, std::move(p)).first->second;
}

std::string family_label(Family family, int k) {
  return (family == Family::sphere_rotated ? "Sphere" + std::to_string(k) + "+rotSphere" : "Cube+Sphere") +
         std::to_string(k);
}

void report_minimum(benchmark::internal::Benchmark* b) {
  b->ComputeStatistics("min", +[](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); });
}

int largest_family_k() {
  const char* large = std::getenv("CVMS_BENCH_LARGE");
  return large != nullptr && std::strcmp(large, "1") == 0 ? 8 : 7;
}

std::vector<cvms::Vec3> vertex_points(const cvms::ConvexPolyhedron& p) {
  std::vector<cvms::Vec3> points;
  points.reserve(p.num_vertices());
  for (cvms::VertexId v : p.mesh().vertices()) points.push_back(p.vertex(v));
  return points;
}

std::vector<double> pairwise_sums_double(const cvms::ConvexPolyhedron& a, const cvms::ConvexPolyhedron& b) {
  std::vector<double> xyz;
  xyz.reserve(std::size_t{3} * a.num_vertices() * b.num_vertices());
  for (cvms::VertexId u : a.mesh().vertices()) {
    const cvms::Vec3& p = a.vertex(u);
    const double px = p.x.get_d(), py = p.y.get_d(), pz = p.z.get_d();
    for (cvms::VertexId v : b.mesh().vertices()) {
      const cvms::Vec3& q = b.vertex(v);
      xyz.push_back(px + q.x.get_d());
      xyz.push_back(py + q.y.get_d());
      xyz.push_back(pz + q.z.get_d());
    }
  }
  return xyz;
}

}  // namespace cvms_bench
