// SPDX-License-Identifier: MIT
// The hierarchy's ray search (TriangleTree::for_each_on_ray) against an
// exact oracle written here: for each box, the parameters s >= 0 at which
// p + s d lies in each slab, intersected as rational intervals. The search
// filters boxes in doubles, so it may visit a box the ray only grazes
// within rounding, but it must never skip one the ray meets: rays start on
// box faces, edges and corners, run along faces, have zero direction
// coordinates, and start beyond the doubles' range (the exact path).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "triangle_tree.hpp"

namespace {

using cvms::Rational;
using cvms::Vec3;
using cvms::detail::Box;
using cvms::detail::TriangleTree;

// Whether some s >= 0 puts p + s d in the closed box (infinite bounds
// constrain nothing), by intersecting the allowed ranges of s.
bool oracle_meets(const Vec3& p, const Vec3& d, const Box& box) {
  std::optional<Rational> low = Rational(0), high;  // s in [low, high]; no high: unbounded
  for (int k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const bool has_lo = std::isfinite(box.lo[i]), has_hi = std::isfinite(box.hi[i]);
    if (d[k] == 0) {
      if ((has_lo && p[k] < Rational(box.lo[i])) || (has_hi && p[k] > Rational(box.hi[i]))) return false;
      continue;
    }
    for (int side = 0; side < 2; ++side) {
      const bool finite = side == 0 ? has_lo : has_hi;
      if (!finite) continue;
      const Rational s = (Rational(side == 0 ? box.lo[i] : box.hi[i]) - p[k]) / d[k];
      // The bound limits s from below when the ray moves towards it.
      const bool from_below = (side == 0) == (d[k] > 0);
      if (from_below && s > *low) low = s;
      if (!from_below && (!high || s < *high)) high = s;
    }
  }
  return !high || *low <= *high;
}

std::set<std::uint32_t> visited(const TriangleTree& tree, const Vec3& p, const Vec3& d) {
  std::set<std::uint32_t> out;
  tree.for_each_on_ray(p, d, [&out](std::uint32_t t) {
    out.insert(t);
    return false;
  });
  return out;
}

void expect_no_box_skipped(const std::vector<Box>& boxes, const Vec3& p, const Vec3& d, unsigned seed) {
  const TriangleTree tree(boxes);
  const std::set<std::uint32_t> seen = visited(tree, p, d);
  for (std::uint32_t b = 0; b < boxes.size(); ++b) {
    if (oracle_meets(p, d, boxes[b])) {
      EXPECT_TRUE(seen.contains(b)) << "seed " << seed << ", box " << b;
    }
  }
}

Box box_of(double x0, double y0, double z0, double x1, double y1, double z1) {
  return Box{{x0, y0, z0}, {x1, y1, z1}};
}

TEST(TriangleTreeRay, TouchingFacesEdgesAndCorners) {
  const std::vector<Box> boxes = {box_of(0, 0, 0, 1, 1, 1), box_of(2, 0, 0, 3, 1, 1), box_of(0, 2, 0, 1, 3, 1),
                                  box_of(5, 5, 5, 6, 6, 6)};
  // Along the x axis through the first two boxes' shared face plane y = 0.
  expect_no_box_skipped(boxes, {-1, 0, 0}, {1, 0, 0}, 0);
  // From a corner of the first box away from everything but that corner.
  expect_no_box_skipped(boxes, {1, 1, 1}, {1, 1, 1}, 0);
  // Grazing the edge x = 1, y = 2 of the third box.
  expect_no_box_skipped(boxes, {0, 1, {1, 2}}, {1, 1, 0}, 0);
  const std::set<std::uint32_t> along_x = visited(TriangleTree(boxes), {-1, {1, 2}, {1, 2}}, {1, 0, 0});
  EXPECT_EQ(along_x, (std::set<std::uint32_t>{0, 1}));  // far boxes are pruned
}

TEST(TriangleTreeRay, BeyondTheDoubles) {
  const Rational huge = Rational(mpz_class("1" + std::string(400, '0')));
  const std::vector<Box> boxes = {box_of(0, 0, 0, 1, 1, 1), box_of(-INFINITY, -1, -1, INFINITY, 1, 1)};
  expect_no_box_skipped(boxes, {-huge, 0, 0}, {1, 0, 0}, 0);
  expect_no_box_skipped(boxes, {{1, 2}, {1, 2}, {1, 2}}, {huge, 1, 0}, 0);
  expect_no_box_skipped(boxes, {{1, 2}, {1, 2}, {1, 2}}, {Rational(1) / huge, 1, 0}, 0);
}

// Random boxes on a small grid (so rays often start on their faces and run
// along them) and rays from grid points and halves in small integer
// directions.
// A fan of long boxes sharing one end (the caps of a comb prism) among short
// ones, and boxes with equal centres: the area split gathers the long boxes,
// the median fallback takes the equal ones; no box the ray meets is lost.
TEST(TriangleTreeRay, FanOfLongBoxesAmongShortOnes) {
  std::vector<Box> boxes;
  for (int i = 0; i < 64; ++i) {
    boxes.push_back(box_of(i, 0, 1, 64, 1, 1));                // long and flat, one end at x = 64
    boxes.push_back(box_of(i, 1, 0, i, 4, 1));                 // a short wall
    boxes.push_back(box_of(i + 0.5, 1.5, 0.25, i + 0.5, 3, 0.75));  // inside the teeth region
  }
  for (int i = 0; i < 9; ++i) boxes.push_back(box_of(3, 3, 3, 5, 5, 5));  // equal centres
  const unsigned seed = 77;
  std::mt19937 rng(seed);
  auto coordinate = [&rng](int range) { return Rational(static_cast<int>(rng() % (4 * range)) - 4, 4); };
  for (int r = 0; r < 300; ++r) {
    const Vec3 p{coordinate(66), coordinate(6), coordinate(6)};
    Vec3 d{static_cast<int>(rng() % 7) - 3, static_cast<int>(rng() % 7) - 3, static_cast<int>(rng() % 7) - 3};
    if (d == Vec3{}) d.z = 1;
    expect_no_box_skipped(boxes, p, d, seed);
  }
}

TEST(TriangleTreeRay, RandomAgainstOracle) {
  for (unsigned seed = 1; seed <= 60; ++seed) {
    std::mt19937 rng(seed);
    auto coordinate = [&rng] { return static_cast<int>(rng() % 9) - 4; };
    std::vector<Box> boxes;
    for (int b = 0; b < 40; ++b) {
      Box box;
      for (std::size_t k = 0; k < 3; ++k) {
        const int a = coordinate(), c = coordinate();
        box.lo[k] = std::min(a, c) / 2.0;
        box.hi[k] = std::max(a, c) / 2.0;
      }
      boxes.push_back(box);
    }
    for (int r = 0; r < 30; ++r) {
      const Vec3 p{Rational(coordinate()) / 2, Rational(coordinate()) / 2, Rational(coordinate()) / 3};
      Vec3 d{coordinate(), coordinate(), coordinate()};
      if (d == Vec3{}) d.x = 1;
      expect_no_box_skipped(boxes, p, d, seed);
    }
  }
}

}  // namespace
