// SPDX-License-Identifier: MIT
// The ear clipping of ear_clipping.hpp.
//
// A corner i with neighbours a and b is an ear when it turns strictly as
// the polygon does (so the triangle has positive area), no other corner lies
// in the closed triangle (a, i, b) unless it is another passage through a,
// i or b, and no such passage has an edge that leaves its point strictly
// into the triangle's angle there. An edge that meets the triangle's inside
// enters it either at a corner strictly inside (excluded) or through the
// side (a, b) from outside, and then it must leave through a point of the
// triangle (it cannot cross the polygon's edges (a, i) and (i, b)), i.e. end
// at a corner in it or run to a, i or b, which the passages' test excludes.
// So the triangle lies in the polygon, and clipping it leaves a weakly
// simple polygon of the same turning (for a simple polygon: no edge can
// enter the triangle without a corner inside it, since its other two sides
// are edges of the polygon). Only corners that do not turn strictly as the
// polygon does need the triangle test: a chain of edges that enters the
// triangle through (a, b) and leaves through it again has a corner farthest
// from (a, b) inside it, where the chain turns back with the triangle's part
// of the inside around it, so that corner is reflex or straight. Only the
// two neighbours of a clipped ear change status (convexity and ear); the
// others are re-examined before giving up, so a polygon is never rejected
// for a stale status. Quadratic in the polygon's size; the point-in-triangle
// tests are first filtered by outward-rounded double boxes, which never
// exclude a point that the exact test would find in the triangle.
#include "ear_clipping.hpp"

#include <algorithm>

#include "planar_tests.hpp"
#include "triangle_tree.hpp"

namespace cvms::detail {

EarClipper::EarClipper(std::span<const Vec2> points, std::vector<std::uint32_t> corners, int turn)
    : points_(points), corners_(std::move(corners)), turn_(turn), prev_(corners_.size()), next_(corners_.size()),
      convex_(corners_.size()), ear_(corners_.size()) {
  const std::size_t k = corners_.size();
  box_.reserve(k);
  for (std::size_t i = 0; i < k; ++i)
    box_.push_back({double_below(at(i).x), double_above(at(i).x), double_below(at(i).y), double_above(at(i).y)});
  for (std::size_t i = 0; i < k; ++i) {
    prev_[i] = (i + k - 1) % k;
    next_[i] = (i + 1) % k;
  }
  for (std::size_t i = 0; i < k; ++i) convex_[i] = is_convex(i);
  for (std::size_t i = 0; i < k; ++i) ear_[i] = is_ear(i);
}

bool EarClipper::is_convex(std::size_t i) const { return orient2(at(prev_[i]), at(i), at(next_[i])) == turn_; }

bool EarClipper::run(std::vector<std::array<std::uint32_t, 3>>& out) {
  std::size_t remaining = corners_.size();
  std::size_t cur = 0;
  while (remaining > 3) {
    const auto ear = find_ear(cur, remaining);
    if (!ear) return false;
    const std::size_t i = *ear;
    const std::size_t a = prev_[i];
    const std::size_t b = next_[i];
    out.push_back({corners_[a], corners_[i], corners_[b]});
    next_[a] = b;
    prev_[b] = a;
    --remaining;
    convex_[a] = is_convex(a);
    convex_[b] = is_convex(b);
    ear_[a] = is_ear(a);
    ear_[b] = is_ear(b);
    cur = b;
  }
  if (orient2(at(prev_[cur]), at(cur), at(next_[cur])) != turn_) return false;
  out.push_back({corners_[prev_[cur]], corners_[cur], corners_[next_[cur]]});
  return true;
}

std::optional<std::size_t> EarClipper::find_ear(std::size_t cur, std::size_t remaining) {
  for (int pass = 0; pass < 2; ++pass) {
    std::size_t i = cur;
    for (std::size_t step = 0; step < remaining; ++step, i = next_[i]) {
      if (pass == 1) ear_[i] = is_ear(i);
      if (ear_[i]) return i;
    }
  }
  return std::nullopt;
}

// Does an edge of corner j (a passage through c, whose triangle angle is
// spanned by the rays to x and y) leave c strictly into that angle?
bool EarClipper::passage_enters(std::size_t j, const Vec2& c, const Vec2& x, const Vec2& y) const {
  const int side_x = orient2(c, x, y);
  const int side_y = orient2(c, y, x);
  for (std::size_t n : {prev_[j], next_[j]}) {
    const Vec2& q = at(n);
    if (orient2(c, x, q) == side_x && orient2(c, y, q) == side_y) return true;
  }
  return false;
}

bool EarClipper::is_ear(std::size_t i) const {
  const std::size_t a = prev_[i];
  const std::size_t b = next_[i];
  const Vec2& pa = at(a);
  const Vec2& pi = at(i);
  const Vec2& pb = at(b);
  if (!convex_[i]) return false;
  std::array<double, 4> around = box_[i];
  for (std::size_t k : {a, b}) {
    around[0] = std::min(around[0], box_[k][0]);
    around[1] = std::max(around[1], box_[k][1]);
    around[2] = std::min(around[2], box_[k][2]);
    around[3] = std::max(around[3], box_[k][3]);
  }
  auto may_lie_in = [&](std::size_t j) {
    const std::array<double, 4>& p = box_[j];
    return p[1] >= around[0] && p[0] <= around[1] && p[3] >= around[2] && p[2] <= around[3];
  };
  for (std::size_t j = next_[b]; j != a; j = next_[j]) {
    const std::uint32_t c = corners_[j];
    if (c == corners_[a]) {
      if (passage_enters(j, pa, pi, pb)) return false;
    } else if (c == corners_[i]) {
      if (passage_enters(j, pi, pa, pb)) return false;
    } else if (c == corners_[b]) {
      if (passage_enters(j, pb, pa, pi)) return false;
    } else if (!convex_[j] && may_lie_in(j) && point_in_triangle(at(j), pa, pi, pb)) {
      return false;
    }
  }
  return true;
}

}  // namespace cvms::detail
