// SPDX-License-Identifier: MIT
// Example: the Minkowski sum of two convex polygons in the plane.
//
// planar_sum merges the two edge sequences by direction (exactly, without
// angles), so the sum of an m-gon and an n-gon costs O(m + n). Parallel edges
// are merged, so the result has only true corners.
#include <cvms/planar_sum.hpp>
#include <cvms/rational.hpp>
#include <cvms/vec.hpp>
#include <iostream>
#include <vector>

namespace {

// cvms::to_string prints exact decimals ("1.1") where they exist, else p/q.
void print(const cvms::Vec2& p) {
  std::cout << '(' << cvms::to_string(p.x) << ", " << cvms::to_string(p.y) << ')';
}

}  // namespace

int main() {
  const cvms::Rational tenth = cvms::parse_rational("0.1");  // exactly 1/10

  // Both polygons counterclockwise, without repeated or collinear vertices.
  const std::vector<cvms::Vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<cvms::Vec2> triangle{{0, 0}, {tenth, 0}, {0, tenth}};

  // The sum as points, counterclockwise from the lowest (then leftmost) one.
  const std::vector<cvms::Vec2> sum = cvms::planar_sum(square, triangle);
  std::cout << "square + triangle has " << sum.size() << " vertices:\n";
  for (const cvms::Vec2& p : sum) {
    std::cout << "  ";
    print(p);
    std::cout << '\n';
  }

  // The same sum as index pairs: vertex k is square[i] + triangle[j]. This is
  // how the 3D algorithms identify the vertices of a sum.
  std::cout << "as index pairs (square, triangle):";
  for (auto [i, j] : cvms::planar_sum_indices(square, triangle)) std::cout << " (" << i << ", " << j << ")";
  std::cout << '\n';

  // Degenerate operands are fine: a segment sweeps the square into a longer box.
  const std::vector<cvms::Vec2> segment{{0, 0}, {2, 0}};
  std::cout << "square + segment:";
  for (const cvms::Vec2& p : cvms::planar_sum(square, segment)) {
    std::cout << ' ';
    print(p);
  }
  std::cout << '\n';
  return 0;
}
