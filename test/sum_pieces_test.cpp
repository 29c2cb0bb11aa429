// SPDX-License-Identifier: MIT
// Sums of solids as unions of the pairwise sums of their convex pieces
// (minkowski_sum_pieces), against independent oracles:
//  - each piece of the sum has the vertices of the exact hull of the
//    pairwise vertex sums of its two operand pieces;
//  - for solids made of grid cells, A + B is the union of the sums of the
//    cells, box + box = [lo_a + lo_b, hi_a + hi_b]; random exact points (a
//    fixed seed, printed on failure) lie in that union of boxes iff they lie
//    in some piece of the sum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/decomposition.hpp"
#include "cvms/predicates.hpp"
#include "decomposition_fixtures.hpp"

namespace cvms {
namespace {

using test::GridSolid;
using test::unit_grid;

std::vector<Vec3> sorted_vertices(const ConvexPolyhedron& p) {
  std::vector<Vec3> v = p.mesh().positions();
  std::sort(v.begin(), v.end());
  return v;
}

bool in_some_box(const std::vector<std::pair<Vec3, Vec3>>& boxes, const Vec3& p) {
  for (const auto& [lo, hi] : boxes) {
    bool in = true;
    for (int a = 0; a < 3; ++a) in = in && lo[a] <= p[a] && p[a] <= hi[a];
    if (in) return true;
  }
  return false;
}

bool in_some_piece(const ConvexUnion& u, const Vec3& p) {
  for (const ConvexPolyhedron& piece : u.pieces()) {
    bool in = true;
    for (FaceId f : piece.mesh().faces())
      in = in && side_of_plane(p, piece.normal(f), piece.plane_offset(f)) != Sign::positive;
    if (in) return true;
  }
  return false;
}

void check_sum(const GridSolid& a, const GridSolid& b, std::uint64_t seed) {
  Solid sa = a.solid(), sb = b.solid();
  ConvexUnion sum = minkowski_sum_pieces(sa, sb);
  ConvexUnion pa = convex_decomposition(sa), pb = convex_decomposition(sb);
  ASSERT_EQ(sum.size(), pa.size() * pb.size());
  for (std::size_t i = 0; i < pa.size(); ++i)
    for (std::size_t j = 0; j < pb.size(); ++j) {
      std::vector<Vec3> sums;
      for (const Vec3& x : pa.pieces()[i].mesh().positions())
        for (const Vec3& y : pb.pieces()[j].mesh().positions()) sums.push_back(x + y);
      EXPECT_EQ(sorted_vertices(sum.pieces()[i * pb.size() + j]), sorted_vertices(convex_hull(sums)))
          << "pair (" << i << ", " << j << ")";
    }

  std::vector<std::pair<Vec3, Vec3>> boxes;
  for (const auto& [la, ha] : a.boxes())
    for (const auto& [lb, hb] : b.boxes()) boxes.emplace_back(la + lb, ha + hb);
  Vec3 lo = boxes[0].first, hi = boxes[0].second;
  for (const auto& [l, h] : boxes)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], l[k]);
      hi[k] = std::max(hi[k], h[k]);
    }
  std::mt19937_64 rng(seed);
  for (int n = 0; n < 400; ++n) {
    Vec3 p;
    for (int k = 0; k < 3; ++k) {
      Rational t(static_cast<long>(rng() % 1201) - 100, 1000);
      p[k] = rng() % 4 == 0 ? boxes[rng() % boxes.size()].first[k] : lo[k] + t * (hi[k] - lo[k]);
    }
    ASSERT_EQ(in_some_box(boxes, p), in_some_piece(sum, p))
        << "seed " << seed << ", point " << n << " (" << to_string(p.x) << ", " << to_string(p.y) << ", "
        << to_string(p.z) << ")";
  }
}

TEST(MinkowskiSumPieces, LBlockPlusUBlock) {
  auto l = unit_grid(2, 2, 1, [](int i, int j, int) { return i == 0 || j == 0; });
  auto u = unit_grid(3, 1, 2, [](int i, int, int k) { return k == 0 || i != 1; });
  check_sum(l, u, 4901);
}

TEST(MinkowskiSumPieces, CavityFilledByACube) {
  auto cavity = unit_grid(3, 3, 3, [](int i, int j, int k) { return !(i == 1 && j == 1 && k == 1); });
  auto cube = unit_grid(1, 1, 1, [](int, int, int) { return true; });
  check_sum(cavity, cube, 4902);
}

TEST(MinkowskiSumPieces, RingPlusStaircase) {
  auto ring = unit_grid(3, 3, 1, [](int i, int j, int) { return !(i == 1 && j == 1); });
  auto stairs = unit_grid(3, 1, 3, [](int i, int, int k) { return k <= i; });
  check_sum(ring, stairs, 4903);
}

}  // namespace
}  // namespace cvms
