// SPDX-License-Identifier: MIT
// minkowski_sum of convex sets: the dispatch by dimension (the constructions
// are in set_sum_parts.hpp), sums of many and zonotopes.
//
// Order of a sum of many: the result is exact, so any order gives the same
// set; the order only changes the cost. Points fold into one translation.
// The rest are summed smallest two first (by vertex count, ties by position
// in the list): summing operands of similar size keeps each intermediate
// sum as small as it can be for its operands (for n segments: zonotopes of
// 2, 4, 8, ... generators, O(n^2 log n) work instead of O(n^3) folding one
// segment at a time).
#include "cvms/set_sum.hpp"

#include <queue>
#include <utility>
#include <vector>

#include "cvms/predicates.hpp"
#include "set_sum_parts.hpp"

namespace cvms {

namespace {

ConvexSet segment_segment_sum(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  const Vec3 da = a[1] - a[0], db = b[1] - b[0];
  if (!is_parallel(da, db)) return detail::coplanar_sum(a, b, cross(da, db));
  // Collinear directions: the sum is the segment between the extreme sums.
  const bool b_along = sign_dot(db, da) == Sign::positive;
  return ConvexSet::segment(a[0] + (b_along ? b[0] : b[1]), a[1] + (b_along ? b[1] : b[0]));
}

ConvexSet segment_polygon_sum(const std::vector<Vec3>& s, const ConvexSet& q) {
  const Vec3 d = s[1] - s[0];
  if (sign_dot(d, q.normal()) == Sign::zero) return detail::coplanar_sum(s, q.vertices(), q.normal());
  return ConvexSet(detail::prism(q, s[0], d));
}

ConvexSet polygon_polygon_sum(const ConvexSet& a, const ConvexSet& b) {
  if (a.normal() == b.normal()) return detail::coplanar_sum(a.vertices(), b.vertices(), a.normal());
  // Not parallel: a + b = (a + prism of b) less b's sweep.
  const ConvexPolyhedron swept = detail::prism(b, Vec3{0, 0, 0}, b.normal());
  return detail::unswept(detail::polygon_polyhedron_sum(a, swept).polyhedron(), b.normal());
}

}  // namespace

ConvexSet minkowski_sum(const ConvexSet& a, const ConvexSet& b, const Options& options) {
  if (a.empty() || b.empty()) return {};
  if (a.dimension() > b.dimension()) return minkowski_sum(b, a, options);
  const std::vector<Vec3> low = a.dimension() < 3 ? a.vertices() : std::vector<Vec3>{};
  switch (a.dimension()) {
    case 0:
      return b.translated(low[0]);
    case 1:
      if (b.dimension() == 1) return segment_segment_sum(low, b.vertices());
      if (b.dimension() == 2) return segment_polygon_sum(low, b);
      return detail::segment_polyhedron_sum(low[0], low[1] - low[0], b.polyhedron());
    case 2:
      if (b.dimension() == 2) return polygon_polygon_sum(a, b);
      return detail::polygon_polyhedron_sum(a, b.polyhedron());
    default:
      return ConvexSet(minkowski_sum(a.polyhedron(), b.polyhedron(), options).polyhedron);
  }
}

ConvexSet minkowski_sum(std::span<const ConvexSet> operands, const Options& options) {
  Vec3 offset{0, 0, 0};
  // (vertex count, list position) -> operand: the smallest two first.
  using Entry = std::pair<std::pair<std::size_t, std::size_t>, ConvexSet>;
  auto larger = [](const Entry& x, const Entry& y) { return x.first > y.first; };
  std::priority_queue<Entry, std::vector<Entry>, decltype(larger)> queue(larger);
  std::size_t position = 0;
  for (const ConvexSet& s : operands) {
    if (s.empty()) return {};
    if (s.dimension() == 0)
      offset += s.vertices()[0];
    else
      queue.push({{s.num_vertices(), position++}, s});
  }
  if (queue.empty()) return ConvexSet::point(offset);
  while (queue.size() > 1) {
    ConvexSet x = queue.top().second;
    queue.pop();
    ConvexSet y = queue.top().second;
    queue.pop();
    ConvexSet sum = minkowski_sum(x, y, options);
    queue.push({{sum.num_vertices(), position++}, std::move(sum)});
  }
  return queue.top().second.translated(offset);
}

ConvexSet zonotope(const Vec3& center, std::span<const Vec3> generators) {
  std::vector<ConvexSet> segments{ConvexSet::point(center)};
  for (const Vec3& g : generators)
    if (!is_zero(g)) segments.push_back(ConvexSet::segment(-g, g));
  return minkowski_sum(segments);
}

}  // namespace cvms
