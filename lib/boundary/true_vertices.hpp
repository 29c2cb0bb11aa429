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
  [[nodiscard]] std::uint32_t id(const Vec3& p) const;
  // The vertices of order k that may lie on the segment [a, b].
  [[nodiscard]] std::span<const std::uint32_t> candidates(int k, const Vec3& a, const Vec3& b) const;
  const std::vector<Vec3>& vertices_;
  std::array<std::vector<std::uint32_t>, 3> by_axis_;  // vertex ids by coordinates (k, k + 1, k + 2)
  std::vector<std::uint32_t> by_representation_;       // vertex ids in the representation order
};

}  // namespace cvms::detail
