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

#include "cvms/error.hpp"
#include "cvms/predicates.hpp"
#include "plane_chart.hpp"

namespace cvms::detail {

namespace {

// One end of a fragment edge on its line: key (dx, dy, offset), parameter,
// the count it adds to the intervals after it, and the 3D point.
struct LineEvent {
  Vec3 line;
  Rational t;
  int step = 0;
  const Vec3* point = nullptr;
};

bool event_before(const LineEvent& a, const LineEvent& b) {
  if (a.line != b.line) return a.line < b.line;
  return a.t < b.t;
}

void add_edge(const PlaneChart& chart, const Vec3& a, const Vec3& b, std::vector<LineEvent>& events) {
  const Vec2 pa = chart(a);
  const Vec2 pb = chart(b);
  const Vec2 d = pb - pa;
  const Vec3 dir3 = canonical_normal(Vec3{d.x, d.y, 0});
  const Vec2 dir{dir3.x, dir3.y};
  const Vec3 line{dir.x, dir.y, cross(dir, pa)};
  Rational ta = dot(dir, pa);
  Rational tb = dot(dir, pb);
  const int along = sign_dot(dir, d) == Sign::positive ? 1 : -1;
  if (along > 0) {
    events.push_back({line, std::move(ta), along, &a});
    events.push_back({line, std::move(tb), -along, &b});
  } else {
    events.push_back({line, std::move(tb), along, &b});
    events.push_back({line, std::move(ta), -along, &a});
  }
}

// The runs of one line's events [first, last), sorted by parameter.
void line_runs(std::span<const LineEvent> events, std::vector<DirectedSegment>& out) {
  int value = 0;
  const Vec3* run_start = nullptr;
  for (std::size_t k = 0; k < events.size();) {
    const int before = value;
    std::size_t e = k;
    for (; e < events.size() && events[e].t == events[k].t; ++e) value += events[e].step;
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

}  // namespace

std::vector<DirectedSegment> plane_region_boundary(const BoundaryFragments& fragments,
                                                   std::span<const std::uint32_t> on_plane, const Vec3& normal) {
  const PlaneChart chart(normal);
  std::vector<LineEvent> events;
  for (std::uint32_t f : on_plane) {
    const auto& corners = fragments.fragments[f].corners;
    for (std::size_t i = 0; i < corners.size(); ++i)
      add_edge(chart, corners[i], corners[(i + 1) % corners.size()], events);
  }
  std::sort(events.begin(), events.end(), event_before);
  std::vector<DirectedSegment> out;
  for (std::size_t k = 0; k < events.size();) {
    std::size_t e = k;
    while (e < events.size() && events[e].line == events[k].line) ++e;
    line_runs(std::span<const LineEvent>(events).subspan(k, e - k), out);
    k = e;
  }
  return out;
}

}  // namespace cvms::detail
