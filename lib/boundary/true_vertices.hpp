// SPDX-License-Identifier: MIT
// The vertices of the assembled boundary and its edges: the ends of every
// plane region's boundary segments are its true vertices (corners of a
// maximal planar region), and a true vertex that lies inside another
// segment (a T-junction: a corner of one region on a straight edge of
// another, or a point where two parts of the set touch) splits that segment,
// so that no edge of the mesh has a vertex in its interior.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "cvms/vec.hpp"
#include "plane_region_boundary.hpp"

namespace cvms::detail {

/// The true vertices, sorted lexicographically and without repetition.
std::vector<Vec3> true_vertices(const std::vector<std::vector<DirectedSegment>>& segments_per_plane);

/// The segments as directed edges between consecutive vertices of
/// `vertices` (sorted as true_vertices gives them) along each segment, in
/// the segment's order. Each segment's ends must be in `vertices`.
class SegmentSplitter {
 public:
  explicit SegmentSplitter(const std::vector<Vec3>& vertices);

  /// Appends the edges of `segment` to `edges`.
  void split(const DirectedSegment& segment, std::vector<std::array<std::uint32_t, 2>>& edges) const;

 private:
  // A segment [a, b] with its box [lo, hi], each coordinate also as its
  // nearest double.
  struct Query {
    const Vec3& a;
    const Vec3& b;
    std::array<const Rational*, 3> lo, hi;
    std::array<double, 3> near_a, near_lo, near_hi;
  };
  [[nodiscard]] std::uint32_t id(const Vec3& p) const;
  // The vertices of order k that may lie on the segment.
  [[nodiscard]] std::span<const std::uint32_t> candidates(int k, const Query& q) const;
  // Sign of vertex i's coordinate k minus x (whose nearest double is near_x).
  [[nodiscard]] int compare(std::uint32_t i, int k, const Rational& x, double near_x) const;
  const std::vector<Vec3>& vertices_;
  std::vector<std::array<double, 3>> near_;            // each vertex's coordinates as nearest doubles
  std::array<std::vector<std::uint32_t>, 3> by_axis_;  // vertex ids by coordinates (k, k + 1, k + 2)
  std::vector<std::uint32_t> by_representation_;       // vertex ids in the representation order
};

}  // namespace cvms::detail
