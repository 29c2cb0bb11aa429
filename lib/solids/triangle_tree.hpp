// SPDX-License-Identifier: MIT
// A bounding-volume hierarchy over a solid's triangles: axis-aligned boxes
// in doubles, each rounded outward from the exact coordinates, so a box
// always contains its triangles and pruning by boxes never loses a pair or
// a hit. Built top-down, each node's boxes split by their centres where the
// children's areas weighted by their sizes are least (a surface-area
// heuristic over binned centres), each child keeping at least an eighth of
// the boxes, or else at the median centre along the longest axis; so its
// depth is O(log n) whatever the input (at most log_{8/7} n), and the pair
// search of
// the self-intersection test meets only pairs whose boxes overlap: O(n)
// pairs on a mesh whose triangles are small beside the whole, O(n log n)
// node visits to find them.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "cvms/vec.hpp"

namespace cvms::detail {

struct Box {
  std::array<double, 3> lo, hi;
};

/// A double no greater than x, and one no less than x (one step beyond the
/// nearest double, so whatever the rounding of the conversion).
double double_below(const Rational& x);
double double_above(const Rational& x);

/// The box of one point, rounded outward.
Box point_box(const Vec3& p);
/// Grows b to contain other.
void extend(Box& b, const Box& other);

class TriangleTree {
 public:
  TriangleTree(std::span<const Vec3> vertices, std::span<const std::array<std::uint32_t, 3>> triangles);
  /// A tree over any boxes (of shells, say): the searches below then report
  /// indices into `boxes` where they say triangles.
  explicit TriangleTree(std::vector<Box> boxes);

  /// Calls visit(i, j), i < j, for every pair of triangles whose boxes
  /// overlap, until visit returns true. Returns the number of pairs visited.
  std::uint64_t for_each_overlapping_pair(
      const std::function<bool(std::uint32_t, std::uint32_t)>& visit) const;
  /// Calls visit(t) for every triangle whose box overlaps `box`.
  void for_each_overlapping(const Box& box, const std::function<void(std::uint32_t)>& visit) const;
  /// Calls visit(t) for every triangle whose box the ray {p + s d : s >= 0}
  /// meets, until visit returns true. It may also call it for a triangle
  /// whose box the ray only passes within rounding of (the boxes are
  /// filtered in doubles, outward-rounded): the caller's exact test of the
  /// triangle decides; no box the ray meets is ever skipped.
  void for_each_on_ray(const Vec3& p, const Vec3& d, const std::function<bool(std::uint32_t)>& visit) const;
  /// A box containing every triangle (every box); nullptr for an empty tree.
  [[nodiscard]] const Box* bounds() const noexcept { return nodes_.empty() ? nullptr : &nodes_.front().box; }

 private:
  struct Node {
    Box box;
    std::uint32_t begin, end;  // triangles order_[begin, end)
    std::uint32_t right;       // second child (the first is the next node); 0 for a leaf
  };
  void build_all();
  std::uint32_t build(std::uint32_t begin, std::uint32_t end, std::span<const std::array<double, 3>> centres);
  std::uint32_t area_split(std::uint32_t begin, std::uint32_t end, std::span<const std::array<double, 3>> centres);
  std::uint32_t median_split(std::uint32_t begin, std::uint32_t end, const Box& box,
                             std::span<const std::array<double, 3>> centres);
  [[nodiscard]] bool is_leaf(const Node& n) const noexcept { return n.right == 0; }

  std::vector<Box> boxes_;  // per triangle
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace cvms::detail
