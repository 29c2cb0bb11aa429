// SPDX-License-Identifier: MIT
// The beneath-beyond step of the exact EPA: conv(P + {x}) for a convex
// polytope P, triangulated, and a point x outside it.
//
// A face is visible from x iff x is strictly beyond its plane (orient3d,
// filtered). Coplanar triangles of one facet of P share its plane, so
// visibility is decided per facet, and the facets visible from a point
// outside a convex polytope form a topological disc whose boundary (the
// horizon) is one cycle of edges. The boundary of conv(P + {x}) is the
// union of the faces not visible (x is beneath or on their planes, so they
// still support the new polytope) and the triangles joining x to the
// horizon edges. A horizon edge (u, v) bounds a visible face, whose plane
// holds u and v and has x strictly beyond it, so x is not on the line uv:
// each new triangle is proper. Orienting it (u, v, x), with (u, v) in the
// order of the visible face it replaces, keeps it counterclockwise from
// outside. A face with x on its plane stays: its new neighbour may be
// coplanar with it, which P allows (its faces are triangles, not facets).
//
// Everything is exact: each visibility is a filtered sign on the points; a
// face's plane and squared distance from the origin are rationals, computed
// when the EPA loop needs them (plane()), and bounded in doubles before.
#include "expanding_polytope.hpp"

#include <algorithm>
#include <utility>

#include "error_bounds.hpp"
#include "filtered_arithmetic.hpp"
#include "filtered_predicates.hpp"

namespace cvms::detail {
namespace {

Vec3Ref ref(const PolytopePoint& p) { return {p.c, p.approx}; }

}  // namespace

ExpandingPolytope::ExpandingPolytope(std::array<PolytopePoint, 4> points) {
  points_.assign(std::make_move_iterator(points.begin()), std::make_move_iterator(points.end()));
  // Each triangle is oriented away from the fourth point.
  const bool positive = orient3d(ref(points_[0]), ref(points_[1]), ref(points_[2]), ref(points_[3])) == Sign::positive;
  const std::uint32_t a = positive ? 1 : 2;
  const std::uint32_t b = positive ? 2 : 1;
  add_face(0, b, a);
  add_face(0, 3, b);
  add_face(0, a, 3);
  add_face(a, b, 3);
}

// The bounds of the squared distance, offset^2 / |normal|^2, by the running
// error analysis (filtered_arithmetic.hpp, error_bounds.hpp): most faces are
// never near the origin, and the bounds alone show it.
void ExpandingPolytope::add_face(std::uint32_t i, std::uint32_t j, std::uint32_t k) {
  using filtered::add;
  using filtered::mul;
  using filtered::sub;
  const ApproxVec3& p = points_[i].approx;
  const ApproxVec3& q = points_[j].approx;
  const ApproxVec3& r = points_[k].approx;
  const Approx ux = sub(q.x, p.x), uy = sub(q.y, p.y), uz = sub(q.z, p.z);
  const Approx vx = sub(r.x, p.x), vy = sub(r.y, p.y), vz = sub(r.z, p.z);
  const Approx nx = sub(mul(uy, vz), mul(uz, vy));
  const Approx ny = sub(mul(uz, vx), mul(ux, vz));
  const Approx nz = sub(mul(ux, vy), mul(uy, vx));
  const Approx c = add(add(mul(nx, p.x), mul(ny, p.y)), mul(nz, p.z));
  const Approx n2 = add(add(mul(nx, nx), mul(ny, ny)), mul(nz, nz));
  const filtered::QuotientBounds d = filtered::quotient_bounds(mul(c, c), n2);
  PolytopeFace f;
  f.v = {i, j, k};
  f.distance_low = d.low;
  f.distance_high = d.high;
  faces_.push_back(std::move(f));
}

const FacePlane& ExpandingPolytope::plane(PolytopeFace& f) {
  if (f.plane != PolytopeFace::no_plane) return planes_[f.plane];
  FacePlane& e = planes_.emplace_back();
  const Vec3& p = points_[f.v[0]].c;
  e.normal = cross(points_[f.v[1]].c - p, points_[f.v[2]].c - p);
  e.normal_approx = ApproxVec3::of(e.normal);
  e.offset = dot(e.normal, p);
  e.squared_distance = e.offset * e.offset / dot(e.normal, e.normal);
  f.plane = static_cast<std::uint32_t>(planes_.size() - 1);
  return e;
}

bool ExpandingPolytope::sees(const PolytopeFace& f, const PolytopePoint& x) const {
  return orient3d(ref(points_[f.v[0]]), ref(points_[f.v[1]]), ref(points_[f.v[2]]), ref(x)) == Sign::positive;
}

void ExpandingPolytope::add(PolytopePoint x) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> visible_edges;
  std::vector<PolytopeFace> kept;
  kept.reserve(faces_.size() + 8);
  for (PolytopeFace& f : faces_) {
    if (!sees(f, x)) {
      kept.push_back(std::move(f));
      continue;
    }
    for (int e = 0; e < 3; ++e) visible_edges.emplace_back(f.v[e], f.v[(e + 1) % 3]);
  }
  faces_ = std::move(kept);
  const auto n = static_cast<std::uint32_t>(points_.size());
  points_.push_back(std::move(x));
  // A visible edge is on the horizon iff its twin is not visible too.
  for (const auto& [u, v] : visible_edges)
    if (std::find(visible_edges.begin(), visible_edges.end(), std::pair{v, u}) == visible_edges.end())
      add_face(u, v, n);
}

}  // namespace cvms::detail
