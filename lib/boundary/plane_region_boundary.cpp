// SPDX-License-Identifier: MIT
// The cancellation of plane_region_boundary.hpp, line by line.
//
// In an exact chart of the plane (plane_chart.hpp, orientation kept), every
// fragment edge lies on a line; lines are keyed by their primitive integer
// direction (first nonzero coordinate positive) and the offset cross(d, a),
// and a point of the line by its parameter t = dot(d, a). An edge whose
// parameter grows from its start to its end counts +1 on its interval (the
// fragment on the left of d), one whose parameter decreases counts -1 (the
// fragment on the right). Interior-disjoint fragments put at most one
// fragment on each side of the line at any point, so the sum over the edges
// is -1, 0 or +1 on every interval between consecutive ends: 0 where
// fragments lie on both sides (the line runs through the region) or on
// neither, +1 or -1 where the region is on one side only, i.e. exactly on
// the region's boundary, with the region on the left of d for +1. A maximal
// run of one nonzero value is a maximal straight piece of the boundary: its
// ends are where the region stops lying on that side of the line, so the
// boundary turns there (or the region touches itself there, where the value
// jumps from +1 to -1, and the two runs stay separate segments).
//
// No edge needs splitting at another fragment's corners first, and no
// corner that only the fragments' cutting made survives.
#include "plane_region_boundary.hpp"

#include <algorithm>
#include <utility>

#include "cvms/error.hpp"
#include "cvms/predicates.hpp"
#include "plane_chart.hpp"

namespace cvms::detail {

namespace {

// A fragment edge on its line: the line's key (dx, dy, offset), the
// parameters of its lower and upper ends, whether it runs up (+1) or down
// (-1), and its ends in 3D, lower first. The values are pointers into the
// charted corners, two constants or the plane's pool, so that sorting moves
// no number and an edge parallel to a chart axis allocates at most one.
struct LineEdge {
  const Rational* dx = nullptr;
  const Rational* dy = nullptr;
  const Rational* offset = nullptr;
  const Rational* t_low = nullptr;
  const Rational* t_high = nullptr;
  int along = 0;
  const Vec3* low = nullptr;
  const Vec3* high = nullptr;
};

// One end of an edge: its parameter, the count it adds to the intervals
// after it, and its point.
struct LineEvent {
  const Rational* t;
  int step;
  const Vec3* point;
};

int compare_lines(const LineEdge& a, const LineEdge& b) {
  if (int c = cmp(*a.dx, *b.dx); c != 0) return c;
  if (int c = cmp(*a.dy, *b.dy); c != 0) return c;
  return cmp(*a.offset, *b.offset);
}

// The values edges point to: a pool that never moves them (reserved for
// the plane's five values per edge) and the constants of the axis
// directions.
struct LineValues {
  explicit LineValues(std::size_t edges) { pool.reserve(5 * edges); }
  const Rational* add(Rational value) { return &pool.emplace_back(std::move(value)); }
  std::vector<Rational> pool;
  const Rational zero{0};
  const Rational one{1};
};

// The edge from a to b, charted as pa and pb. An edge parallel to a chart
// axis has the primitive direction (1, 0) or (0, 1), whose offset and
// parameters are coordinates (the offset of (0, 1) negated): no product
// and no gcd. The key is the same either way.
LineEdge line_edge(const Vec2& pa, const Vec2& pb, const Vec3& a, const Vec3& b, LineValues& values) {
  LineEdge e;
  const Rational* ta = nullptr;
  const Rational* tb = nullptr;
  if (const int sx = cmp(pb.x, pa.x), sy = cmp(pb.y, pa.y); sy == 0) {
    // (1, 0): offset cross((1, 0), pa) = pa.y, parameter x.
    e.dx = &values.one;
    e.dy = &values.zero;
    e.offset = &pa.y;
    ta = &pa.x;
    tb = &pb.x;
    e.along = sx > 0 ? 1 : -1;
  } else if (sx == 0) {
    // (0, 1): offset cross((0, 1), pa) = -pa.x, parameter y.
    e.dx = &values.zero;
    e.dy = &values.one;
    e.offset = values.add(-pa.x);
    ta = &pa.y;
    tb = &pb.y;
    e.along = sy > 0 ? 1 : -1;
  } else {
    const Vec2 d = pb - pa;
    const Vec3 dir3 = canonical_normal(Vec3{d.x, d.y, 0});
    const Vec2 dir{dir3.x, dir3.y};
    e.dx = values.add(dir.x);
    e.dy = values.add(dir.y);
    e.offset = values.add(cross(dir, pa));
    ta = values.add(dot(dir, pa));
    tb = values.add(dot(dir, pb));
    e.along = sign_dot(dir, d) == Sign::positive ? 1 : -1;
  }
  e.t_low = e.along > 0 ? ta : tb;
  e.t_high = e.along > 0 ? tb : ta;
  e.low = e.along > 0 ? &a : &b;
  e.high = e.along > 0 ? &b : &a;
  return e;
}

// The runs of the events of one line, sorted by parameter.
void line_runs(std::span<const LineEvent> events, std::vector<DirectedSegment>& out) {
  int value = 0;
  const Vec3* run_start = nullptr;
  for (std::size_t k = 0; k < events.size();) {
    const int before = value;
    std::size_t e = k;
    for (; e < events.size() && cmp(*events[e].t, *events[k].t) == 0; ++e) value += events[e].step;
    if (value < -1 || value > 1)
      throw Error(ErrorCategory::invalid_argument,
                  "assemble_boundary: two fragments on one side of a line overlap (their interiors are not disjoint)");
    const Vec3* here = events[k].point;
    if (before != value) {
      if (before > 0) out.push_back({*run_start, *here});
      if (before < 0) out.push_back({*here, *run_start});
      if (value != 0) run_start = here;
    }
    k = e;
  }
}

// One convex fragment is its own region: its edges, joined across corners
// where it does not turn (none, when it keeps the contract).
std::vector<DirectedSegment> single_fragment_boundary(const PlaneChart& chart, const std::vector<Vec3>& corners) {
  const std::size_t k = corners.size();
  std::vector<Vec2> p;
  p.reserve(k);
  for (const Vec3& c : corners) p.push_back(chart(c));
  std::vector<std::size_t> turning;
  for (std::size_t i = 0; i < k; ++i)
    if (orient2d(p[(i + k - 1) % k], p[i], p[(i + 1) % k]) != Sign::zero) turning.push_back(i);
  std::vector<DirectedSegment> out;
  for (std::size_t j = 0; j < turning.size(); ++j)
    out.push_back({corners[turning[j]], corners[turning[(j + 1) % turning.size()]]});
  return out;
}

}  // namespace

std::vector<DirectedSegment> plane_region_boundary(const BoundaryFragments& fragments,
                                                   std::span<const std::uint32_t> on_plane, const Vec3& normal) {
  std::vector<DirectedSegment> out;
  const PlaneChart chart(normal);
  if (on_plane.size() == 1) return single_fragment_boundary(chart, fragments.fragments[on_plane[0]].corners);
  // Every corner charted once, into storage that stays put while edges
  // point into it.
  std::size_t corners_on_plane = 0;
  for (std::uint32_t f : on_plane) corners_on_plane += fragments.fragments[f].corners.size();
  std::vector<Vec2> charted;
  charted.reserve(corners_on_plane);
  LineValues values(corners_on_plane);
  std::vector<LineEdge> edges;
  edges.reserve(corners_on_plane);
  for (std::uint32_t f : on_plane) {
    const auto& corners = fragments.fragments[f].corners;
    const std::size_t first = charted.size();
    for (const Vec3& c : corners) charted.push_back(chart(c));
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const std::size_t j = (i + 1) % corners.size();
      edges.push_back(line_edge(charted[first + i], charted[first + j], corners[i], corners[j], values));
    }
  }
  std::sort(edges.begin(), edges.end(),
            [](const LineEdge& a, const LineEdge& b) { return compare_lines(a, b) < 0; });
  std::vector<LineEvent> events;
  for (std::size_t k = 0; k < edges.size();) {
    std::size_t e = k;
    events.clear();
    for (; e < edges.size() && compare_lines(edges[e], edges[k]) == 0; ++e) {
      events.push_back({edges[e].t_low, edges[e].along, edges[e].low});
      events.push_back({edges[e].t_high, -edges[e].along, edges[e].high});
    }
    std::sort(events.begin(), events.end(), [](const LineEvent& a, const LineEvent& b) { return cmp(*a.t, *b.t) < 0; });
    line_runs(events, out);
    k = e;
  }
  return out;
}

}  // namespace cvms::detail
