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
// Everything is exact: each visibility is the sign of orient3d, filtered on
// the face's approximate plane (kept with the face, so a test is a dot
// product with its running error, sees()) and exact when the filter cannot
// tell; a face's plane and squared distance from the origin are exact (in
// scaled integers, plane()), computed when the EPA loop or an exact
// visibility test needs them, and bounded in doubles before.
#include "expanding_polytope.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "common_denominator.hpp"
#include "dyadic_orient.hpp"
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
  const bool positive =
      orient3d(ref(points_[0]), ref(points_[1]), ref(points_[2]), ref(points_[3])) == Sign::positive;
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
  f.normal_filter = {nx, ny, nz};
  f.offset_filter = c;
  f.distance_low = d.low;
  f.distance_high = d.high;
  faces_.push_back(std::move(f));
}

PolytopePoint polytope_point(VertexId vertex_a, VertexId vertex_b, Vec3 c) {
  PolytopePoint p{vertex_a, vertex_b, std::move(c), {}, {}, {}};
  p.approx = ApproxVec3::of(p.c);
  const Rational* const values[3] = {&p.c.x, &p.c.y, &p.c.z};
  p.scale = scale_to_common_denominator(values, 3, p.scaled.data());
  return p;
}

int compare_distances(const FacePlane& a, const FacePlane& b) {
  return cmp(a.distance_num * b.distance_den, b.distance_num * a.distance_den);
}

namespace {

using Int3 = std::array<mpz_class, 3>;

// out = s * x - t * y, coordinatewise, in place (no temporaries).
void scaled_difference(Int3& out, const mpz_class& s, const Int3& x, const mpz_class& t, const Int3& y) {
  for (int i = 0; i < 3; ++i) {
    mpz_mul(out[i].get_mpz_t(), s.get_mpz_t(), x[i].get_mpz_t());
    mpz_submul(out[i].get_mpz_t(), t.get_mpz_t(), y[i].get_mpz_t());
  }
}

// out = <x, y>, in place.
void dot_into(mpz_class& out, const Int3& x, const Int3& y) {
  mpz_mul(out.get_mpz_t(), x[0].get_mpz_t(), y[0].get_mpz_t());
  mpz_addmul(out.get_mpz_t(), x[1].get_mpz_t(), y[1].get_mpz_t());
  mpz_addmul(out.get_mpz_t(), x[2].get_mpz_t(), y[2].get_mpz_t());
}

}  // namespace

// In integers: with p = P / d_p (and q, r alike), q - p = (d_p Q - d_q P) /
// (d_p d_q) and r - p = (d_p R - d_r P) / (d_p d_r), so n = cross(d_p Q -
// d_q P, d_p R - d_r P) is cross(q - p, r - p) times d_p^2 d_q d_r > 0; the
// plane is <n, x> = <n, P> / d_p, at squared distance <n, P>^2 / (d_p^2
// |n|^2) from the origin. No gcd anywhere, and the intermediate integers
// live in per-thread scratch (GMP keeps their storage between calls).
const FacePlane& ExpandingPolytope::plane(PolytopeFace& f) {
  if (f.plane != PolytopeFace::no_plane) return planes_[f.plane];
  const PolytopePoint& p = points_[f.v[0]];
  const PolytopePoint& q = points_[f.v[1]];
  const PolytopePoint& r = points_[f.v[2]];
  thread_local Int3 u, v, n;
  scaled_difference(u, p.scale, q.scaled, q.scale, p.scaled);
  scaled_difference(v, p.scale, r.scaled, r.scale, p.scaled);
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    mpz_mul(n[i].get_mpz_t(), u[j].get_mpz_t(), v[k].get_mpz_t());
    mpz_submul(n[i].get_mpz_t(), u[k].get_mpz_t(), v[j].get_mpz_t());
  }
  FacePlane& e = planes_.emplace_back();
  e.normal = Vec3{Rational(n[0]), Rational(n[1]), Rational(n[2])};
  e.normal_approx = ApproxVec3::of(e.normal);
  dot_into(e.offset, n, p.scaled);
  e.offset_scale = p.scale;
  mpz_mul(e.distance_num.get_mpz_t(), e.offset.get_mpz_t(), e.offset.get_mpz_t());
  dot_into(e.distance_den, n, n);
  e.distance_den *= p.scale;
  e.distance_den *= p.scale;
  f.plane = static_cast<std::uint32_t>(planes_.size() - 1);
  return e;
}

bool ExpandingPolytope::sees(PolytopeFace& f, const PolytopePoint& x) {
  using filtered::add;
  using filtered::mul;
  using filtered::sub;
  const ApproxVec3& n = f.normal_filter;
  const Approx s = sub(add(add(mul(n.x, x.approx.x), mul(n.y, x.approx.y)), mul(n.z, x.approx.z)), f.offset_filter);
  if (filtered::certain(s)) return filtered::sign(s) == Sign::positive;
  if (f.plane == PolytopeFace::no_plane) {
    const std::optional<Sign> d = dyadic_orient3d(points_[f.v[0]].c, points_[f.v[1]].c, points_[f.v[2]].c, x.c);
    if (d) return *d == Sign::positive;
  }
  const FacePlane& e = plane(f);
  thread_local mpz_class lhs, rhs;
  mpz_mul(lhs.get_mpz_t(), e.normal.x.get_num_mpz_t(), x.scaled[0].get_mpz_t());
  mpz_addmul(lhs.get_mpz_t(), e.normal.y.get_num_mpz_t(), x.scaled[1].get_mpz_t());
  mpz_addmul(lhs.get_mpz_t(), e.normal.z.get_num_mpz_t(), x.scaled[2].get_mpz_t());
  lhs *= e.offset_scale;
  mpz_mul(rhs.get_mpz_t(), e.offset.get_mpz_t(), x.scale.get_mpz_t());
  return cmp(lhs, rhs) > 0;
}

bool ExpandingPolytope::add(PolytopePoint x) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>>& visible_edges = visible_edges_;
  std::vector<char>& visible = visible_;
  visible_edges.clear();
  visible.assign(faces_.size(), 0);
  for (std::size_t i = 0; i < faces_.size(); ++i) {
    if (!sees(faces_[i], x)) continue;
    visible[i] = 1;
    for (int e = 0; e < 3; ++e) visible_edges.emplace_back(faces_[i].v[e], faces_[i].v[(e + 1) % 3]);
  }
  if (visible_edges.empty()) return false;  // x is in P: P stays
  std::size_t kept = 0;
  for (std::size_t i = 0; i < faces_.size(); ++i)
    if (!visible[i]) faces_[kept++] = std::move(faces_[i]);
  faces_.resize(kept);
  const auto n = static_cast<std::uint32_t>(points_.size());
  points_.push_back(std::move(x));
  // A visible edge is on the horizon iff its twin is not visible too.
  for (const auto& [u, v] : visible_edges)
    if (std::find(visible_edges.begin(), visible_edges.end(), std::pair{v, u}) == visible_edges.end())
      add_face(u, v, n);
  return true;
}

}  // namespace cvms::detail
