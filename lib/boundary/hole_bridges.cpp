// SPDX-License-Identifier: MIT
// The bridges of hole_bridges.hpp.
//
// Holes are joined in decreasing lexicographic order of their greatest
// corner h, each from h to a corner p of the polygon built so far. A bridge
// must leave p and h into the region's inside (the wedges of polygon_wedge.hpp
// at those corners) and meet no edge of the polygon or of a hole not yet
// joined other than at its own ends, and then it lies in the region: it
// starts inside and crosses no boundary. Such a p exists: the corner of the
// polygon built so far nearest to h among those it sees. Candidates are
// tried nearest first, which is almost always the first.
//
// Splicing: ..., p, h, (the hole from h round to h), h, p, ... keeps the
// inside on the left on both sides of the bridge.
#include "hole_bridges.hpp"

#include <algorithm>
#include <numeric>

#include "cvms/error.hpp"
#include "planar_tests.hpp"
#include "polygon_wedge.hpp"

namespace cvms::detail {

namespace {

using Loop = std::vector<std::uint32_t>;

std::size_t greatest_corner(std::span<const Vec2> points, const Loop& loop) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < loop.size(); ++i)
    if (points[loop[best]] < points[loop[i]]) best = i;
  return best;
}

// Does the edge [a, b] keep clear of the bridge [h, p] except at the bridge's ends?
bool edge_clear(const Vec2& a, const Vec2& b, const Vec2& h, const Vec2& p) {
  const bool a_end = a == h || a == p;
  const bool b_end = b == h || b == p;
  if (a_end && b_end) return false;
  if (!a_end && !b_end) return !segments_meet(a, b, h, p);
  // One end shared: only a collinear overlap meets the bridge elsewhere.
  const Vec2& other = a_end ? b : a;
  const Vec2& shared = a_end ? a : b;
  const Vec2& far = shared == h ? p : h;
  if (orient2(h, p, other) != 0) return true;
  return !(between(h, p, other) || between(a, b, far));
}

class Bridger {
 public:
  Bridger(std::span<const Vec2> points, const RegionLoops& region) : points_(points), polygon_(region.outer) {
    std::vector<std::pair<const Vec2*, const Loop*>> keyed;
    for (const Loop& hole : region.holes) keyed.emplace_back(&points_[hole[greatest_corner(points_, hole)]], &hole);
    std::stable_sort(keyed.begin(), keyed.end(), [](const auto& x, const auto& y) { return *y.first < *x.first; });
    for (const auto& [corner, hole] : keyed) pending_.push_back(hole);
  }

  Loop run() {
    for (std::size_t k = 0; k < pending_.size(); ++k) join(k);
    return std::move(polygon_);
  }

 private:
  void join(std::size_t k) {
    const Loop& hole = *pending_[k];
    const std::size_t hi = greatest_corner(points_, hole);
    const Vec2& h = points_[hole[hi]];
    const Vec2& h_prev = points_[hole[(hi + hole.size() - 1) % hole.size()]];
    const Vec2& h_next = points_[hole[(hi + 1) % hole.size()]];
    std::vector<std::size_t> order(polygon_.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::vector<Rational> distance(polygon_.size());
    for (std::size_t q = 0; q < polygon_.size(); ++q) {
      const Vec2 d = points_[polygon_[q]] - h;
      distance[q] = dot(d, d);
    }
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return distance[x] < distance[y]; });
    for (std::size_t q : order) {
      const Vec2& p = points_[polygon_[q]];
      if (p == h || !into_wedge(h_prev, h, h_next, p)) continue;
      if (!into_wedge(points_[polygon_[(q + polygon_.size() - 1) % polygon_.size()]], p,
                      points_[polygon_[(q + 1) % polygon_.size()]], h))
        continue;
      if (!clear(h, p, k)) continue;
      splice(q, hole, hi);
      return;
    }
    throw Error(ErrorCategory::invalid_argument, "assemble_boundary: a hole of a plane region cannot be bridged");
  }

  bool clear(const Vec2& h, const Vec2& p, std::size_t k) const {
    if (!loop_clear(polygon_, h, p)) return false;
    for (std::size_t j = k; j < pending_.size(); ++j)
      if (!loop_clear(*pending_[j], h, p)) return false;
    return true;
  }

  bool loop_clear(const Loop& loop, const Vec2& h, const Vec2& p) const {
    for (std::size_t i = 0; i < loop.size(); ++i)
      if (!edge_clear(points_[loop[i]], points_[loop[(i + 1) % loop.size()]], h, p)) return false;
    return true;
  }

  void splice(std::size_t q, const Loop& hole, std::size_t hi) {
    Loop out;
    out.reserve(polygon_.size() + hole.size() + 2);
    out.insert(out.end(), polygon_.begin(), polygon_.begin() + static_cast<std::ptrdiff_t>(q) + 1);
    for (std::size_t i = 0; i <= hole.size(); ++i) out.push_back(hole[(hi + i) % hole.size()]);
    out.insert(out.end(), polygon_.begin() + static_cast<std::ptrdiff_t>(q), polygon_.end());
    polygon_ = std::move(out);
  }

  std::span<const Vec2> points_;
  Loop polygon_;
  std::vector<const Loop*> pending_;
};

}  // namespace

std::vector<std::uint32_t> bridge_holes(std::span<const Vec2> points, const RegionLoops& region) {
  if (region.holes.empty()) return region.outer;
  return Bridger(points, region).run();
}

}  // namespace cvms::detail
