// SPDX-License-Identifier: MIT
// Soak run of the allocation-failure sweep (label soak): larger operands
// than allocation_failure_test.cpp's, so that the sums take their longer
// paths (several arcs per vertex, ties, bigger outputs), 200 seeded sums of
// hulls on a small grid (the degenerate paths), every algorithm, the sums
// on two threads, and each sweep again with the failure
// persistent (every call from the k-th on fails, as when memory stays
// exhausted, so that the unwinding code itself meets failures). Same
// checks: a cvms::Error or std::bad_alloc at every k, operands unchanged,
// the reference result at the end, no leak under the asan preset.
#include <gtest/gtest.h>

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cvms/cvms.hpp"
#include "support/allocation_sweep.hpp"

namespace cvms::test {
namespace {

// Each test ends with a leak check (a no-op without AddressSanitizer).
class AllocationFailureSoak : public ::testing::Test {
 protected:
  void TearDown() override {
    EXPECT_FALSE(unreachable_blocks()) << "LeakSanitizer found blocks left behind (above)";
  }
};

// Both modes of failure, one sweep each.
template <class Run>
void expect_sweeps(const std::string& name, Run run, const std::function<std::string()>& operands) {
  for (const bool persistent : {false, true}) {
    SweepOptions options;
    options.persistent = persistent;
    const std::string label = name + (persistent ? ", persistent" : "");
    std::cout << summary(label, sweep_allocation_failures(label, run, operands, options)) << '\n';
  }
}

TEST_F(AllocationFailureSoak, SumsWithEveryAlgorithmOnOneAndTwoThreads) {
  const ConvexPolyhedron a = shapes::random_hull(7, 120, 1000);
  const ConvexPolyhedron b = shapes::geodesic_sphere(2);
  const auto operands = [&] { return fingerprint(a) + fingerprint(b); };
  for (const Algorithm algorithm : {Algorithm::cvms, Algorithm::essdms, Algorithm::chms})
    for (const unsigned threads : {1u, 2u}) {
      Options options;
      options.algorithm = algorithm;
      options.threads = threads;
      expect_sweeps(
          std::string("minkowski_sum ") + to_string(algorithm) + " threads " + std::to_string(threads),
          [&] { return minkowski_sum(a, b, options).polyhedron; }, operands);
    }
}

TEST_F(AllocationFailureSoak, SumsOfSeededHullsOnASmallGrid) {
  // Points on a small grid: coplanar facets, parallel edges and ties in
  // the contributing vertices, the sums' degenerate paths.
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const ConvexPolyhedron a = shapes::random_hull(seed, 16, 3);
    const ConvexPolyhedron b = shapes::random_hull(seed + 1000, 12, 2);
    Options options;
    options.algorithm = seed % 2 == 0 ? Algorithm::cvms : Algorithm::essdms;
    options.threads = seed % 3 == 0 ? 2 : 1;
    expect_sweeps(
        "minkowski_sum, seed " + std::to_string(seed) + ", " + to_string(options.algorithm) + ", threads " +
            std::to_string(options.threads),
        [&] { return minkowski_sum(a, b, options).polyhedron; },
        [&] { return fingerprint(a) + fingerprint(b); });
  }
}

TEST_F(AllocationFailureSoak, SumOfManyAndOfUnions) {
  const std::vector<ConvexSet> operands{
      ConvexSet(shapes::random_hull(3, 60, 100)), ConvexSet::segment(Vec3{0, 0, 0}, Vec3{1, 2, 3}),
      ConvexSet(shapes::octahedron()), ConvexSet(shapes::prism(24, Rational(2)))};
  const auto fingerprints = [&] {
    std::string text;
    for (const ConvexSet& s : operands) text += fingerprint(s);
    return text;
  };
  expect_sweeps(
      "n-ary minkowski_sum", [&] { return minkowski_sum(std::span<const ConvexSet>(operands)); },
      fingerprints);
  const ConvexUnion u(std::vector<ConvexPolyhedron>{shapes::cube(), shapes::random_hull(5, 40, 20),
                                                    shapes::octahedron().translated(Vec3{4, 0, 0})});
  for (const unsigned threads : {1u, 2u}) {
    Options options;
    options.threads = threads;
    expect_sweeps(
        "minkowski_sum of unions, threads " + std::to_string(threads),
        [&] { return minkowski_sum(u, u, options); }, [&] { return fingerprint(u); });
  }
}

TEST_F(AllocationFailureSoak, HullHalfspacesDifferenceProximity) {
  const std::vector<Vec3> points = shapes::random_points(11, 1000, 1000);
  expect_sweeps(
      "convex_hull", [&] { return convex_hull(points); }, [&] { return fingerprint(points); });
  const ConvexSet sphere = shapes::geodesic_sphere(3);
  const HalfspaceSystem rows = to_halfspaces(sphere);
  expect_sweeps(
      "from_halfspaces", [&] { return from_halfspaces(rows); }, [&] { return fingerprint(rows); });
  const ConvexSet small = shapes::tetrahedron();
  expect_sweeps(
      "pontryagin_difference", [&] { return pontryagin_difference(sphere, small); },
      [&] { return fingerprint(sphere) + fingerprint(small); });
  const ConvexPolyhedron a = shapes::random_hull(13, 200, 1000);
  const ConvexPolyhedron b = shapes::random_hull(17, 200, 1000).translated(Vec3{2500, 100, 0});
  expect_sweeps(
      "squared_distance", [&] { return squared_distance(a, b); },
      [&] { return fingerprint(a) + fingerprint(b); });
  const ConvexPolyhedron c = shapes::random_hull(19, 200, 1000);
  expect_sweeps(
      "penetration", [&] { return penetration(a, c); }, [&] { return fingerprint(a) + fingerprint(c); });
}

TEST_F(AllocationFailureSoak, SolidsReadAndWrite) {
  const Solid solid = read_solid(std::filesystem::path(CVMS_TEST_DATA_DIR) / "solids/box_with_hole.off");
  expect_sweeps(
      "convex_decomposition", [&] { return convex_decomposition(solid); },
      [&] { return fingerprint(solid); });
  const ConvexPolyhedron p = shapes::geodesic_sphere(3);
  std::ostringstream text;
  write(text, p, FileFormat::off);
  const std::string off = text.str();
  expect_sweeps(
      "read off",
      [&] {
        TextBuffer buffer(off);
        std::istream in(&buffer);
        return to_polyhedron(read_off(in, "sphere"), "sphere");
      },
      [] { return std::string(); });
  expect_sweeps(
      "write off",
      [&] {
        std::ostringstream out;
        write(out, p, FileFormat::off, Coordinates::double_outer, VertexOrder::canonical);
        return out.str();
      },
      [&] { return fingerprint(p); });
}

TEST_F(AllocationFailureSoak, SumsOfSolidsAsOneSolid) {
  const Solid ring = read_solid(std::filesystem::path(CVMS_TEST_DATA_DIR) / "solids/box_with_hole.off");
  const Solid l_block = read_solid(std::filesystem::path(CVMS_TEST_DATA_DIR) / "solids/l_block.off");
  for (const unsigned threads : {1U, 2U}) {
    Options options;
    options.threads = threads;
    const std::string on = " on " + std::to_string(threads) + " thread(s)";
    expect_sweeps(
        "minkowski_sum(Solid, Solid)" + on, [&] { return minkowski_sum(l_block, ring, options); },
        [&] { return fingerprint(l_block) + fingerprint(ring); });
    expect_sweeps(
        "minkowski_sum(Solid, convex Solid)" + on,
        [&] { return minkowski_sum(ring, Solid::from_polyhedron(shapes::geodesic_sphere(1)), options); },
        [&] { return fingerprint(ring); });
  }
}

}  // namespace
}  // namespace cvms::test
