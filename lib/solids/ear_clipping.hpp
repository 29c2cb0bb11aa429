// SPDX-License-Identifier: MIT
// Ear clipping of a weakly simple polygon in a plane: a closed polygon that
// may pass through a point more than once (a region touching itself there,
// or a hole joined to its outer boundary by a bridge walked both ways), each
// passage bounding its own wedge of the inside, the wedges disjoint. A simple
// polygon is the case of no repeated point. No vertex is added and no
// triangle has zero area.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "cvms/vec.hpp"

namespace cvms::detail {

class EarClipper {
 public:
  /// The polygon `corners` (indices into `points`, in order; equal indices
  /// are the same point passed again, and only equal indices may name
  /// equal points), turning as `turn` says (+1 counterclockwise, -1
  /// clockwise).
  EarClipper(std::span<const Vec2> points, std::vector<std::uint32_t> corners, int turn);

  /// Appends the triangles, as indices into the points, each turning as the
  /// polygon does; false if no ear is left (never for a weakly simple
  /// polygon), with the triangles found so far appended.
  bool run(std::vector<std::array<std::uint32_t, 3>>& out);

 private:
  [[nodiscard]] const Vec2& at(std::size_t i) const { return points_[corners_[i]]; }
  std::optional<std::size_t> find_ear(std::size_t cur, std::size_t remaining);
  [[nodiscard]] bool passage_enters(std::size_t j, const Vec2& c, const Vec2& x, const Vec2& y) const;
  [[nodiscard]] bool is_convex(std::size_t i) const;
  [[nodiscard]] bool is_ear(std::size_t i) const;

  std::span<const Vec2> points_;
  std::vector<std::uint32_t> corners_;
  int turn_;
  std::vector<std::size_t> prev_, next_;
  std::vector<bool> convex_;  // turns strictly as the polygon does
  std::vector<bool> ear_;
  // Each corner's point enclosed in doubles (x low, x high, y low, y high,
  // rounded outward): a corner outside a triangle's enclosing box is not in
  // the triangle, decided without exact arithmetic.
  std::vector<std::array<double, 4>> box_;
};

}  // namespace cvms::detail
