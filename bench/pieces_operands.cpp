// SPDX-License-Identifier: MIT
#include "pieces_operands.hpp"

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/decomposition.hpp"
#include "cvms/shapes.hpp"

namespace cvms_bench {
namespace {

// The fixtures' directory, set by bench/CMakeLists.txt.
const std::string kDataDir = CVMS_BENCH_SOLIDS_DIR;

cvms::Solid scaled(const cvms::Solid& solid, const cvms::Rational& factor) {
  cvms::PolygonSoup soup = solid.to_soup();
  for (cvms::Vec3& p : soup.points) p = factor * p;
  return cvms::Solid::from_soup(std::move(soup));
}

cvms::Solid small_icosphere() {
  std::vector<cvms::Vec3> points = cvms::shapes::geodesic_sphere_points(2);
  for (cvms::Vec3& p : points) p = cvms::Rational(1, 20) * p;
  return cvms::Solid::from_polyhedron(cvms::convex_hull(points));
}

cvms::Solid load(std::string_view name) {
  if (name == "icosphere") return small_icosphere();
  if (name == "l_block_small") return scaled(bench_solid("l_block"), cvms::Rational(1, 10));
  const std::string file = name == "spot" ? "spot.obj" : std::string(name) + ".off";
  return cvms::read_solid(kDataDir + "/" + file);
}

std::map<std::string, cvms::Solid, std::less<>>& solids() {
  static std::map<std::string, cvms::Solid, std::less<>> cache;
  return cache;
}

std::map<std::string, cvms::ConvexUnion, std::less<>>& decompositions() {
  static std::map<std::string, cvms::ConvexUnion, std::less<>> cache;
  return cache;
}

}  // namespace

const cvms::Solid& bench_solid(std::string_view name) {
  auto it = solids().find(name);
  if (it == solids().end()) it = solids().emplace(std::string(name), load(name)).first;
  return it->second;
}

const cvms::ConvexUnion& bench_pieces(std::string_view name) {
  auto it = decompositions().find(name);
  if (it == decompositions().end())
    it = decompositions().emplace(std::string(name), cvms::convex_decomposition(bench_solid(name))).first;
  return it->second;
}

void remember_pieces(std::string_view name, const cvms::ConvexUnion& pieces) {
  decompositions().insert_or_assign(std::string(name), pieces);
}

void register_pair_rows(const char* prefix, PairRow row) {
  for (const SumPair& pair : kSumPairs)
    for (unsigned threads : {1U, 2U}) {
      const std::string name = std::string(prefix) + "/" + pair.name + "/" + std::to_string(threads);
      auto* registered = benchmark::RegisterBenchmark(name.c_str(), row, pair, threads);
      registered->Unit(benchmark::kMillisecond);
      if (threads > 1) registered->UseRealTime();
    }
}

}  // namespace cvms_bench
