// SPDX-License-Identifier: MIT
// The tracing and grouping of region_loops.hpp.
//
// Clockwise choice: arriving at v from u with the region on the left, the
// region's wedge at v next to that edge starts at the ray from v to u and
// turns clockwise until the next edge of the boundary, which leaves v (the
// region is on its left). Rays are ordered by their clockwise angle from the
// ray to u: first those strictly clockwise of it (angle in (0, pi)), then
// the opposite ray, then those strictly counterclockwise; within a half, r1
// comes before r2 when r2 is clockwise of r1. Every sign is an orient2d.
//
// Grouping: a loop's signed area is positive for an outer loop and negative
// for a hole. Loops do not cross, so the outer loops around a hole are
// nested and the smallest one (least area) is the one it belongs to. Whether
// a hole lies inside an outer loop is decided at the midpoint of one of its
// edges that is not on that loop (a hole's edge never lies along an outer
// loop's edge: they would have cancelled), by exact ray crossing, after the
// loops' bounding boxes (an outer loop around a hole contains its box).
#include "region_loops.hpp"

#include <algorithm>
#include <optional>

#include "cvms/error.hpp"
#include "cvms/predicates.hpp"
#include "planar_tests.hpp"

namespace cvms::detail {

namespace {

[[noreturn]] void open_boundary() {
  throw Error(ErrorCategory::invalid_argument, "assemble_boundary: the fragments of a plane do not close into loops");
}

// 0: strictly clockwise of r0, 1: opposite to r0, 2: strictly counterclockwise.
int half_of(const Vec2& r0, const Vec2& r) {
  const Sign s = sign_cross2(r0, r);
  if (s == Sign::negative) return 0;
  if (s == Sign::positive) return 2;
  return 1;
}

class LoopTracer {
 public:
  LoopTracer(std::span<const Vec2> points, std::span<const std::array<std::uint32_t, 2>> edges)
      : points_(points), edges_(edges.begin(), edges.end()), used_(edges.size(), false) {
    std::sort(edges_.begin(), edges_.end());
  }

  std::vector<std::vector<std::uint32_t>> trace() {
    std::vector<std::vector<std::uint32_t>> loops;
    for (std::size_t start = 0; start < edges_.size(); ++start) {
      if (used_[start]) continue;
      std::vector<std::uint32_t> loop;
      std::size_t e = start;
      do {
        if (used_[e]) open_boundary();
        used_[e] = true;
        loop.push_back(edges_[e][0]);
        e = next_edge(e);
      } while (e != start);
      loops.push_back(std::move(loop));
    }
    return loops;
  }

 private:
  std::size_t next_edge(std::size_t e) const {
    const std::uint32_t u = edges_[e][0];
    const std::uint32_t v = edges_[e][1];
    const auto first = std::lower_bound(edges_.begin(), edges_.end(), std::array<std::uint32_t, 2>{v, 0});
    auto last = first;
    while (last != edges_.end() && (*last)[0] == v) ++last;
    if (first == last) open_boundary();
    if (last - first == 1) return static_cast<std::size_t>(first - edges_.begin());
    const Vec2 r0 = points_[u] - points_[v];
    auto best = first;
    for (auto it = first + 1; it != last; ++it)
      if (clockwise_before(r0, points_[(*it)[1]] - points_[v], points_[(*best)[1]] - points_[v])) best = it;
    return static_cast<std::size_t>(best - edges_.begin());
  }

  static bool clockwise_before(const Vec2& r0, const Vec2& r1, const Vec2& r2) {
    const int h1 = half_of(r0, r1);
    const int h2 = half_of(r0, r2);
    if (h1 != h2) return h1 < h2;
    return sign_cross2(r1, r2) == Sign::negative;
  }

  std::span<const Vec2> points_;
  std::vector<std::array<std::uint32_t, 2>> edges_;
  std::vector<bool> used_;
};

Rational twice_area(std::span<const Vec2> points, const std::vector<std::uint32_t>& loop) {
  Rational sum;
  for (std::size_t i = 0; i < loop.size(); ++i) sum += cross(points[loop[i]], points[loop[(i + 1) % loop.size()]]);
  return sum;
}

// -1 outside, 0 on the loop, +1 inside (ray crossing towards +x).
int locate_in_loop(std::span<const Vec2> points, const std::vector<std::uint32_t>& loop, const Vec2& p) {
  bool inside = false;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec2& a = points[loop[i]];
    const Vec2& b = points[loop[(i + 1) % loop.size()]];
    const int o = orient2(a, b, p);
    if (o == 0 && between(a, b, p)) return 0;
    if ((a.y > p.y) != (b.y > p.y) && (b.y > a.y ? o > 0 : o < 0)) inside = !inside;
  }
  return inside ? 1 : -1;
}

struct Box {
  Vec2 low, high;
};

Box box_of(std::span<const Vec2> points, const std::vector<std::uint32_t>& loop) {
  Box b{points[loop[0]], points[loop[0]]};
  for (std::uint32_t i : loop) {
    const Vec2& p = points[i];
    if (p.x < b.low.x) b.low.x = p.x;
    if (p.y < b.low.y) b.low.y = p.y;
    if (b.high.x < p.x) b.high.x = p.x;
    if (b.high.y < p.y) b.high.y = p.y;
  }
  return b;
}

bool box_contains(const Box& outer, const Box& inner) {
  return outer.low.x <= inner.low.x && outer.low.y <= inner.low.y && inner.high.x <= outer.high.x &&
         inner.high.y <= outer.high.y;
}

bool hole_inside(std::span<const Vec2> points, const std::vector<std::uint32_t>& hole,
                 const std::vector<std::uint32_t>& outer) {
  for (std::size_t i = 0; i < hole.size(); ++i) {
    const Vec2 mid = Rational(1, 2) * (points[hole[i]] + points[hole[(i + 1) % hole.size()]]);
    const int where = locate_in_loop(points, outer, mid);
    if (where != 0) return where > 0;
  }
  return false;
}

}  // namespace

std::vector<RegionLoops> region_loops(std::span<const Vec2> points, std::span<const std::array<std::uint32_t, 2>> edges) {
  auto loops = LoopTracer(points, edges).trace();
  std::vector<Rational> areas;
  std::vector<Box> boxes;
  std::vector<RegionLoops> regions;
  std::vector<std::size_t> region_of_loop(loops.size(), 0);
  std::vector<std::size_t> holes;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    areas.push_back(twice_area(points, loops[l]));
    boxes.push_back(box_of(points, loops[l]));
    if (sgn(areas[l]) > 0) {
      region_of_loop[l] = regions.size();
      regions.push_back({std::move(loops[l]), {}});
    } else {
      holes.push_back(l);
    }
  }
  for (std::size_t h : holes) {
    std::optional<std::size_t> best;
    for (std::size_t l = 0; l < loops.size(); ++l) {
      if (sgn(areas[l]) <= 0) continue;
      if ((best && areas[l] >= areas[*best]) || !box_contains(boxes[l], boxes[h])) continue;
      if (hole_inside(points, loops[h], regions[region_of_loop[l]].outer)) best = l;
    }
    if (!best) throw Error(ErrorCategory::invalid_argument, "assemble_boundary: a hole of a plane region lies in no outer loop");
    regions[region_of_loop[*best]].holes.push_back(std::move(loops[h]));
  }
  return regions;
}

}  // namespace cvms::detail
