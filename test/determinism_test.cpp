// SPDX-License-Identifier: MIT
// Determinism: the same inputs give byte-identical output files, whatever the
// heap layout, the thread and the number of earlier runs (no pointer-keyed
// or hash-ordered iteration leaking into output order). Across builds (static
// and shared, separate processes) scripts/check-determinism.sh compares the
// CLI's output files.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/io.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/convex_hull.hpp"
#include "support/hand_solids.hpp"

namespace {

using cvms::Algorithm;
using cvms::ConvexPolyhedron;
using cvms::Rational;
using cvms::Vec3;

// Rational points in a small box, many ties: drawn with rng() % n only, so the
// sequence is the same with every standard library.
std::vector<Vec3> cloud(std::uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> points;
  for (int i = 0; i < n; ++i) {
    Vec3 p;
    for (int c = 0; c < 3; ++c) {
      Rational r(static_cast<long>(rng() % 21) - 10, static_cast<long>(1 + rng() % 3));
      r.canonicalize();
      p[c] = r;
    }
    points.push_back(p);
  }
  return points;
}

std::string all_formats(const ConvexPolyhedron& p) {
  const cvms::PolygonSoup soup = p.to_soup();
  std::ostringstream out;
  cvms::write_off(out, soup);
  cvms::write_obj(out, soup);
  cvms::write_off(out, soup, cvms::Coordinates::double_);
  cvms::write_stl(out, soup);
  return out.str();
}

// The whole pipeline: text input read back, hull, polyhedron from a soup,
// sums by every available algorithm, written in every format.
std::string run_pipeline() {
  std::ostringstream cube_text;
  cvms::write_off(cube_text, cvms::test::cube_triangles());
  std::istringstream cube_in(cube_text.str());
  const ConvexPolyhedron cube = ConvexPolyhedron::from_soup(cvms::read_off(cube_in, "cube"));
  const ConvexPolyhedron a = cvms::convex_hull(cloud(2026, 60));
  const ConvexPolyhedron b = cvms::convex_hull(cloud(7, 25));
  std::string out = all_formats(cube) + all_formats(a) + all_formats(b);
  for (Algorithm algorithm : {Algorithm::cvms, Algorithm::chms}) {
    cvms::Options options;
    options.algorithm = algorithm;
    out += all_formats(cvms::minkowski_sum(a, b, options).polyhedron);
    out += all_formats(cvms::minkowski_sum(cube, a, options).polyhedron);
  }
  return out;
}

TEST(Determinism, WritingTheSamePolyhedronTwiceGivesIdenticalBytes) {
  const ConvexPolyhedron p = cvms::convex_hull(cloud(11, 40));
  const std::string first = all_formats(p);
  const std::string second = all_formats(p);
  ASSERT_FALSE(first.empty());
  EXPECT_EQ(first, second);
}

TEST(Determinism, RepeatedRunsGiveIdenticalBytes) {
  const std::string first = run_pipeline();
  // Disturb the heap so that any order derived from addresses changes.
  std::vector<std::unique_ptr<char[]>> clutter;
  for (std::size_t i = 1; i < 2000; ++i) clutter.emplace_back(new char[(i * 7919) % 1021 + 1]);
  for (std::size_t i = 0; i < clutter.size(); i += 2) clutter[i].reset();
  const std::string second = run_pipeline();
  EXPECT_EQ(first.size(), second.size());
  EXPECT_TRUE(first == second) << "the second run wrote different bytes";
}

TEST(Determinism, AnotherThreadGivesIdenticalBytes) {
  const std::string here = run_pipeline();
  std::string there;
  std::thread worker([&there] { there = run_pipeline(); });
  worker.join();
  EXPECT_TRUE(here == there) << "a run on another thread wrote different bytes";
}

}  // namespace
