// SPDX-License-Identifier: MIT
// The vertex set and the splitting of true_vertices.hpp.
//
// A vertex v lies in the relative interior of the segment [a, b] iff
// b - a and v - a are parallel and v is in the segment's bounding box and
// is neither end. Candidates come from three orders of the vertices, one
// per coordinate: the vertices whose coordinate k lies between a[k] and
// b[k] form one range of the order k, and the test scans the smallest of the
// three ranges (for an edge parallel to a coordinate plane, the vertices on
// that plane). Points of a line are ordered along it by the lexicographic
// order (the first nonzero coordinate of the direction decides it), so the
// hits sorted that way, reversed when b precedes a, are the pieces' order.
#include "true_vertices.hpp"

#include <algorithm>
#include <numeric>

#include "cvms/error.hpp"
#include "cvms/predicates.hpp"

namespace cvms::detail {

std::vector<Vec3> true_vertices(const std::vector<std::vector<DirectedSegment>>& segments_per_plane) {
  std::vector<Vec3> vertices;
  for (const auto& segments : segments_per_plane)
    for (const auto& s : segments) {
      vertices.push_back(s.from);
      vertices.push_back(s.to);
    }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

SegmentSplitter::SegmentSplitter(const std::vector<Vec3>& vertices) : vertices_(vertices) {
  for (int k = 0; k < 3; ++k) {
    auto& order = by_axis_[k];
    order.resize(vertices.size());
    std::iota(order.begin(), order.end(), std::uint32_t{0});
    // Stable: ties stay in vertex order, so the order is the same every run.
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t i, std::uint32_t j) { return vertices[i][k] < vertices[j][k]; });
  }
}

std::uint32_t SegmentSplitter::id(const Vec3& p) const {
  const auto it = std::lower_bound(vertices_.begin(), vertices_.end(), p);
  if (it == vertices_.end() || *it != p)
    throw Error(ErrorCategory::invalid_argument, "assemble_boundary: a segment end is not a vertex");
  return static_cast<std::uint32_t>(it - vertices_.begin());
}

void SegmentSplitter::split(const DirectedSegment& segment, std::vector<std::array<std::uint32_t, 2>>& edges) const {
  const Vec3& a = segment.from;
  const Vec3& b = segment.to;
  std::array<Rational, 3> lo, hi;
  for (int k = 0; k < 3; ++k) {
    lo[k] = a[k] < b[k] ? a[k] : b[k];
    hi[k] = a[k] < b[k] ? b[k] : a[k];
  }
  // The smallest of the three candidate ranges.
  std::span<const std::uint32_t> candidates;
  for (int k = 0; k < 3; ++k) {
    const auto& order = by_axis_[k];
    const auto less_value = [&](std::uint32_t i, const Rational& v) { return vertices_[i][k] < v; };
    const auto value_less = [&](const Rational& v, std::uint32_t i) { return v < vertices_[i][k]; };
    const auto first = std::lower_bound(order.begin(), order.end(), lo[k], less_value);
    const auto last = std::upper_bound(first, order.end(), hi[k], value_less);
    const std::span<const std::uint32_t> range(first, last);
    if (k == 0 || range.size() < candidates.size()) candidates = range;
  }
  const Vec3 ab = b - a;
  std::vector<std::uint32_t> inside;
  for (std::uint32_t v : candidates) {
    const Vec3& p = vertices_[v];
    if (p == a || p == b) continue;
    bool in_box = true;
    for (int k = 0; k < 3 && in_box; ++k) in_box = lo[k] <= p[k] && p[k] <= hi[k];
    if (in_box && is_parallel(ab, p - a)) inside.push_back(v);
  }
  // Vertex ids follow the lexicographic order.
  std::sort(inside.begin(), inside.end());
  if (b < a) std::reverse(inside.begin(), inside.end());
  std::uint32_t from = id(a);
  for (std::uint32_t v : inside) {
    edges.push_back({from, v});
    from = v;
  }
  edges.push_back({from, id(b)});
}

}  // namespace cvms::detail
