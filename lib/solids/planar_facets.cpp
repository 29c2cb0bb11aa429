// SPDX-License-Identifier: MIT
// The facets of planar_facets.hpp: triangles joined through a sort of their
// edges, then each facet's boundary checked to be one simple closed polygon
// in a chart of its plane (plane_chart.hpp), its pairs of edges pruned by
// boxes (triangle_tree.hpp).
#include "planar_facets.hpp"

#include <algorithm>
#include <tuple>

#include "cvms/predicates.hpp"
#include "planar_tests.hpp"
#include "plane_chart.hpp"
#include "triangle_tree.hpp"
#include "union_find.hpp"

namespace cvms::detail {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

struct EdgeUse {
  std::uint32_t lo, hi, triangle, corner;  // the edge from corner to the next, ids lo < hi
};

std::uint32_t corner(const Triangle& t, std::uint32_t k) { return t[k % 3]; }

PlaneChart chart_of(std::span<const Vec3> p, const Triangle& t) {
  return PlaneChart(cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]));
}

// The edge uses of every triangle, sorted so that the uses of one edge are
// adjacent.
std::vector<EdgeUse> edge_uses(std::span<const Triangle> triangles) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t v = corner(triangles[t], k), w = corner(triangles[t], k + 1);
      uses.push_back({std::min(v, w), std::max(v, w), t, k});
    }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& a, const EdgeUse& b) {
    return std::tie(a.lo, a.hi, a.triangle, a.corner) < std::tie(b.lo, b.hi, b.triangle, b.corner);
  });
  return uses;
}

// Are the two uses of one edge joined (see the header): opposite directions,
// the far corners coplanar with the edge and on its two sides?
bool joins(std::span<const Vec3> p, std::span<const Triangle> triangles, const EdgeUse& e, const EdgeUse& f) {
  const Triangle& t = triangles[e.triangle];
  const Triangle& u = triangles[f.triangle];
  const std::uint32_t x = corner(t, e.corner), y = corner(t, e.corner + 1), a = corner(t, e.corner + 2);
  if (corner(u, f.corner) != y) return false;
  const std::uint32_t b = corner(u, f.corner + 2);
  if (orient3d(p[x], p[y], p[a], p[b]) != Sign::zero) return false;
  const PlaneChart chart = chart_of(p, t);
  return orient2(chart(p[x]), chart(p[y]), chart(p[a])) * orient2(chart(p[x]), chart(p[y]), chart(p[b])) < 0;
}

// Is the directed boundary one simple closed polygon? Each vertex must start
// and end one edge, following the edges must visit all, and in a chart of
// the plane consecutive edges may not fold back onto each other and other
// edges may not meet.
bool simple_cycle(std::span<const Vec3> p, const PlaneChart& chart,
                  std::vector<std::array<std::uint32_t, 2>> boundary) {
  const std::size_t n = boundary.size();
  std::sort(boundary.begin(), boundary.end());
  std::vector<std::uint32_t> ends(n);
  for (std::size_t i = 0; i < n; ++i) ends[i] = boundary[i][1];
  std::sort(ends.begin(), ends.end());
  for (std::size_t i = 1; i < n; ++i)
    if (boundary[i][0] == boundary[i - 1][0] || ends[i] == ends[i - 1]) return false;
  std::vector<Vec2> cycle;
  cycle.reserve(n);
  std::uint32_t v = boundary[0][0];
  for (std::size_t i = 0; i < n; ++i) {
    cycle.push_back(chart(p[v]));
    const auto next = std::lower_bound(boundary.begin(), boundary.end(), std::array<std::uint32_t, 2>{v, 0});
    if (next == boundary.end() || (*next)[0] != v) return false;
    v = (*next)[1];
    if (v == boundary[0][0] && i + 1 < n) return false;  // a shorter cycle: several loops
  }
  std::vector<Box> boxes;
  boxes.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = cycle[i];
    const Vec2& b = cycle[(i + 1) % n];
    const Vec2& c = cycle[(i + 2) % n];
    if (orient2(a, b, c) == 0 && (between(a, b, c) || between(b, c, a))) return false;
    Box box = point_box({a.x, a.y, Rational(0)});
    extend(box, point_box({b.x, b.y, Rational(0)}));
    boxes.push_back(box);
  }
  bool meet = false;
  TriangleTree(std::move(boxes)).for_each_overlapping_pair([&](std::uint32_t i, std::uint32_t j) {
    if (j == i + 1 || (i == 0 && j + 1 == n)) return false;
    meet = segments_meet(cycle[i], cycle[(i + 1) % n], cycle[j], cycle[(j + 1) % n]);
    return meet;
  });
  return !meet;
}

}  // namespace

PlanarFacets::PlanarFacets(std::span<const Vec3> points, std::span<const Triangle> triangles)
    : points_(points), triangles_(triangles) {
  const std::vector<EdgeUse> uses = edge_uses(triangles);
  std::vector<bool> joined(uses.size(), false);
  UnionFind classes(triangles.size());
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
    if (j == i + 2 && (joins(points, triangles, uses[i], uses[i + 1]))) {
      joined[i] = joined[i + 1] = true;
      classes.join(uses[i].triangle, uses[i + 1].triangle);
    }
    i = j;
  }
  std::uint32_t count = 0;
  of_triangle_ = classes.numbering(count);
  first_triangle_.assign(count, 0);
  size_.assign(count, 0);
  for (std::uint32_t t = static_cast<std::uint32_t>(triangles.size()); t-- > 0;) {
    first_triangle_[of_triangle_[t]] = t;
    ++size_[of_triangle_[t]];
  }
  std::vector<std::vector<std::array<std::uint32_t, 2>>> boundary(count);
  for (std::size_t i = 0; i < uses.size(); ++i) {
    const std::uint32_t f = of_triangle_[uses[i].triangle];
    edges_.push_back({f, uses[i].lo, uses[i].hi});
    const Triangle& t = triangles[uses[i].triangle];
    vertices_.push_back({f, corner(t, uses[i].corner)});
    if (!joined[i] && size_[f] > 1)
      boundary[f].push_back({corner(t, uses[i].corner), corner(t, uses[i].corner + 1)});
  }
  std::sort(edges_.begin(), edges_.end());
  edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
  std::sort(vertices_.begin(), vertices_.end());
  vertices_.erase(std::unique(vertices_.begin(), vertices_.end()), vertices_.end());
  certified_.assign(count, true);
  for (std::uint32_t f = 0; f < count; ++f)
    if (size_[f] > 1)
      certified_[f] =
          simple_cycle(points, chart_of(points, triangles[first_triangle_[f]]), std::move(boundary[f]));
}

bool PlanarFacets::has_vertex(std::uint32_t f, std::uint32_t v) const {
  return std::binary_search(vertices_.begin(), vertices_.end(), std::array<std::uint32_t, 2>{f, v});
}

bool PlanarFacets::has_edge(std::uint32_t f, std::uint32_t v, std::uint32_t w) const {
  return std::binary_search(edges_.begin(), edges_.end(),
                            std::array<std::uint32_t, 3>{f, std::min(v, w), std::max(v, w)});
}

bool PlanarFacets::clears(std::uint32_t f, std::uint32_t t) const {
  if (!certified_[f]) return false;
  const Triangle& plane = triangles_[first_triangle_[f]];
  std::array<std::uint32_t, 3> on{};
  std::size_t on_count = 0;
  bool above = false, below = false;
  for (const std::uint32_t v : triangles_[t]) {
    const Sign s = orient3d(points_[plane[0]], points_[plane[1]], points_[plane[2]], points_[v]);
    above = above || s == Sign::positive;
    below = below || s == Sign::negative;
    if (s == Sign::zero) on[on_count++] = v;
  }
  if ((above && below) || on_count == 3) return false;
  if (on_count == 0) return true;
  if (on_count == 1) return has_vertex(f, on[0]);
  return has_edge(f, on[0], on[1]);
}

}  // namespace cvms::detail
