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

#include <algorithm>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include "cvms/predicates.hpp"
#include "output_budget.hpp"
#include "progress_reporter.hpp"
#include "representation_order.hpp"
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

ConvexSet segment_polygon_sum(const std::vector<Vec3>& s, const ConvexSet& q, const detail::OutputBudget& budget) {
  const Vec3 d = s[1] - s[0];
  if (sign_dot(d, q.normal()) == Sign::zero) return detail::coplanar_sum(s, q.vertices(), q.normal());
  const std::uint64_t facets = q.num_vertices() + 2;
  budget.check_count(facets, "minkowski_sum (segment + polygon): the sum has " + std::to_string(facets) + " facets");
  return ConvexSet(detail::prism(q, s[0], d));
}

ConvexSet polygon_polygon_sum(const ConvexSet& a, const ConvexSet& b, const detail::OutputBudget& budget) {
  if (a.normal() == b.normal()) return detail::coplanar_sum(a.vertices(), b.vertices(), a.normal());
  // Not parallel: a + b = (a + prism of b) less b's sweep. The limit is
  // checked on the facets of a + prism, which has those of a + b and its
  // silhouette along the sweep (at most |a| + |b| more).
  const ConvexPolyhedron swept = detail::prism(b, Vec3{0, 0, 0}, b.normal());
  return detail::unswept(
      detail::polygon_polyhedron_sum(a, swept, budget, "polygon + polygon, through the second one's prism"),
      b.normal());
}

// The zonotope of segments along `directions` (nonzero) has at most
// d (d - 1) facets for d distinct directions up to sign (exactly that many
// when no three are coplanar): each facet is spanned by two directions and
// comes with its opposite. Checked before any sum is made, and by zonotope()
// before any segment is built, so that a zonotope of 100,000 generators
// (10^10 facets) is refused at once (O(d log d): the directions are
// deduplicated by sorting, never hashed).
void check_zonotope(std::vector<Vec3> directions, const detail::OutputBudget& budget) {
  const std::size_t segments = directions.size();
  for (Vec3& d : directions) {
    d = primitive_direction(d);
    // One direction up to sign: the first nonzero coordinate positive.
    const Rational& first = sgn(d.x) != 0 ? d.x : (sgn(d.y) != 0 ? d.y : d.z);
    if (sgn(first) < 0) d = -d;
  }
  std::sort(directions.begin(), directions.end(), detail::RepresentationLess{});
  const auto distinct = static_cast<std::uint64_t>(
      std::unique(directions.begin(), directions.end()) - directions.begin());
  if (distinct < 3) return;  // a segment or a polygon
  const std::uint64_t facets = detail::saturating_product(distinct, distinct - 1);
  budget.check_count(facets, "minkowski_sum (zonotope of " + std::to_string(segments) + " segments in " +
                                 std::to_string(distinct) + " directions): the sum has up to " +
                                 std::to_string(facets) + " facets");
}

}  // namespace

ConvexSet minkowski_sum(const ConvexSet& a, const ConvexSet& b, const Options& options) {
  if (a.empty() || b.empty()) return {};
  if (a.dimension() > b.dimension()) return minkowski_sum(b, a, options);
  const std::vector<Vec3> low = a.dimension() < 3 ? a.vertices() : std::vector<Vec3>{};
  const detail::OutputBudget budget(options.limits, "sets");
  switch (a.dimension()) {
    case 0:
      return b.translated(low[0]);
    case 1:
      if (b.dimension() == 1) return segment_segment_sum(low, b.vertices());
      if (b.dimension() == 2) return segment_polygon_sum(low, b, budget);
      return detail::segment_polyhedron_sum(low[0], low[1] - low[0], b.polyhedron(), budget);
    case 2:
      if (b.dimension() == 2) return polygon_polygon_sum(a, b, budget);
      return ConvexSet(detail::polygon_polyhedron_sum(a, b.polyhedron(), budget, "polygon + polyhedron"));
    default:
      return ConvexSet(minkowski_sum(a.polyhedron(), b.polyhedron(), options).polyhedron);
  }
}

namespace {

// The operands of positive dimension summed smallest two first (by vertex
// count, ties by position), the result translated by `offset`.
ConvexSet fold_smallest_first(std::span<const ConvexSet> operands, const Vec3& offset, const Options& options) {
  using Entry = std::pair<std::pair<std::size_t, std::size_t>, ConvexSet>;
  auto larger = [](const Entry& x, const Entry& y) { return x.first > y.first; };
  std::priority_queue<Entry, std::vector<Entry>, decltype(larger)> queue(larger);
  std::size_t position = 0;
  for (const ConvexSet& s : operands)
    if (s.dimension() > 0) queue.push({{s.num_vertices(), position++}, s});
  if (queue.empty()) return ConvexSet::point(offset);
  // The stage "sums", in sums of two done; each sum of two reports its own
  // stages in between, to the same callback.
  detail::ProgressReporter progress(detail::callback_of(options.progress));
  progress.begin("sums", queue.size() - 1);
  while (queue.size() > 1) {
    ConvexSet x = queue.top().second;
    queue.pop();
    ConvexSet y = queue.top().second;
    queue.pop();
    ConvexSet sum = minkowski_sum(x, y, options);
    queue.push({{sum.num_vertices(), position++}, std::move(sum)});
    progress.advance(1);
  }
  progress.end();
  return queue.top().second.translated(offset);
}

}  // namespace

ConvexSet minkowski_sum(std::span<const ConvexSet> operands, const Options& options) {
  Vec3 offset{0, 0, 0};
  std::vector<Vec3> segment_directions;
  bool only_segments = true;
  for (const ConvexSet& s : operands) {
    if (s.empty()) return {};
    if (s.dimension() == 0) {
      offset += s.vertices()[0];
      continue;
    }
    if (s.dimension() == 1) segment_directions.push_back(s.vertices()[1] - s.vertices()[0]);
    only_segments = only_segments && s.dimension() == 1;
  }
  // Each sum of two checks its own output; a zonotope is also bounded as a
  // whole first (check_zonotope). Other sums of many are checked step by
  // step: a sum has at least the facets of each partial sum, so a step
  // beyond the limits means the whole is too.
  if (only_segments) check_zonotope(std::move(segment_directions), detail::OutputBudget(options.limits, "sets"));
  return fold_smallest_first(operands, offset, options);
}

ConvexSet zonotope(const Vec3& center, std::span<const Vec3> generators, const SumLimits& limits) {
  std::vector<Vec3> directions;
  directions.reserve(generators.size());
  for (const Vec3& g : generators)
    if (!is_zero(g)) directions.push_back(g);
  // Bounded once, from the generators, before any segment is built.
  check_zonotope(directions, detail::OutputBudget(limits, "sets"));
  std::vector<ConvexSet> segments;
  segments.reserve(directions.size());
  for (const Vec3& g : directions) segments.push_back(ConvexSet::segment(-g, g));
  Options options;
  options.limits = limits;
  return fold_smallest_first(segments, center, options);
}

}  // namespace cvms
