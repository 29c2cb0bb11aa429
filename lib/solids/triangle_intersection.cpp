// SPDX-License-Identifier: MIT
// The exact triangle tests of triangle_intersection.hpp. The argument:
// the intersection I of two closed triangles is convex. If I is not empty
// (or, when they share a vertex v, not just {v}), a point s of I other than
// v that is extreme in I lies on the boundary of one of the triangles, so on
// one of its edges; hence the triangles meet (beyond v) iff an edge of one
// meets the other (beyond v). An edge opposite v does not contain v, so for
// it any common point counts. An edge [v, a] meets the other triangle beyond
// v only if a lies in that triangle's plane (otherwise the edge leaves the
// plane at v) and the direction a - v lies in the triangle's closed angle at
// v. Every decision is an orient3d or, inside a common plane, an orient2d in
// an exact chart of that plane (a coordinate projection).
#include "triangle_intersection.hpp"

#include <algorithm>

#include "cvms/predicates.hpp"
#include "planar_tests.hpp"

namespace cvms::detail {

namespace {

int sign(Sign s) { return static_cast<int>(s); }

int o3(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return sign(orient3d(a, b, c, d)); }
int o2(const Vec2& a, const Vec2& b, const Vec2& c) { return orient2(a, b, c); }

// A chart of the plane of the triangle (a, b, c) of positive area: drop a
// coordinate whose axis is not parallel to the plane, i.e. one in whose
// projection the triangle keeps a nonzero area (an exact orient2d). The tests
// below do not depend on the chart's orientation.
class Chart {
 public:
  Chart(const Vec3& a, const Vec3& b, const Vec3& c) {
    while (drop_ < 2 && orient2((*this)(a), (*this)(b), (*this)(c)) == 0) ++drop_;
  }
  Vec2 operator()(const Vec3& p) const { return {p[(drop_ + 1) % 3], p[(drop_ + 2) % 3]}; }

 private:
  int drop_ = 0;
};

bool segment_meets_triangle_2d(const Vec2& p, const Vec2& q, const Vec2& a, const Vec2& b, const Vec2& c) {
  return point_in_triangle(p, a, b, c) || point_in_triangle(q, a, b, c) || segments_meet(p, q, a, b) ||
         segments_meet(p, q, b, c) || segments_meet(p, q, c, a);
}

// The closed segment [p, q] and the closed triangle (a, b, c), given op,
// oq: the sides of p and q of the triangle's plane.
bool segment_crosses_triangle(const Vec3& p, const Vec3& q, int op, int oq, const Vec3& a, const Vec3& b,
                              const Vec3& c) {
  if (op * oq > 0) return false;
  if (op == 0 && oq == 0) {
    const Chart chart(a, b, c);
    return segment_meets_triangle_2d(chart(p), chart(q), chart(a), chart(b), chart(c));
  }
  // The segment meets the plane at one point: it is in the triangle iff the
  // line pq passes through the closed triangle, i.e. it turns the same way
  // (or not at all) around the three edges.
  const int s1 = o3(p, q, a, b);
  const int s2 = o3(p, q, b, c);
  const int s3 = o3(p, q, c, a);
  const bool positive = s1 > 0 || s2 > 0 || s3 > 0;
  const bool negative = s1 < 0 || s2 < 0 || s3 < 0;
  return !(positive && negative);
}

// Does the direction x - v lie in the closed angle at v spanned by c - v
// and d - v (less than a half-turn)?
bool in_angle(const Vec2& v, const Vec2& c, const Vec2& d, const Vec2& x) {
  const int s = o2(v, c, d);
  return o2(v, c, x) * s >= 0 && o2(v, x, d) * s >= 0;
}

// a lies in the plane of the triangle (v, c, d): does the direction a - v
// lie in the triangle's closed angle at v?
bool in_angle(const Vec3& v, const Vec3& c, const Vec3& d, const Vec3& a) {
  const Chart chart(v, c, d);
  return in_angle(chart(v), chart(c), chart(d), chart(a));
}

// Coplanar triangles (v, a, b) and (v, c, d) sharing only v meet beyond v
// iff their angles at v share a direction (a common point s != v puts the
// direction s - v in both, by convexity; a common direction puts a short
// segment from v in both). Two angles below a half-turn, arcs of the circle
// of directions, share one iff a side of one lies in the other.
bool overlap_at_vertex_coplanar(const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Chart chart(v, a, b);
  const Vec2 v2 = chart(v), a2 = chart(a), b2 = chart(b), c2 = chart(c), d2 = chart(d);
  return in_angle(v2, a2, b2, c2) || in_angle(v2, a2, b2, d2) || in_angle(v2, c2, d2, a2) ||
         in_angle(v2, c2, d2, b2);
}

// t = (v, a, b) and u = (v, c, d) share exactly the vertex v.
bool overlap_at_vertex(const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const int oc = o3(v, a, b, c);
  const int od = o3(v, a, b, d);
  if (oc * od > 0) return false;  // u meets t's plane only at v
  if (oc == 0 && od == 0) return overlap_at_vertex_coplanar(v, a, b, c, d);
  const int oa = o3(v, c, d, a);
  const int ob = o3(v, c, d, b);
  if (oa * ob > 0) return false;
  if (segment_crosses_triangle(a, b, oa, ob, v, c, d) || segment_crosses_triangle(c, d, oc, od, v, a, b))
    return true;
  return (oa == 0 && in_angle(v, c, d, a)) || (ob == 0 && in_angle(v, c, d, b)) ||
         (oc == 0 && in_angle(v, a, b, c)) || (od == 0 && in_angle(v, a, b, d));
}

// t = (u, v, a) and the other triangle (u, v, b) share the edge uv: they
// meet elsewhere iff coplanar with a and b on the same side of the edge.
bool overlap_at_edge(const Vec3& u, const Vec3& v, const Vec3& a, const Vec3& b) {
  if (o3(u, v, a, b) != 0) return false;
  const Chart chart(u, v, a);
  const Vec2 u2 = chart(u);
  const Vec2 v2 = chart(v);
  return o2(u2, v2, chart(a)) == o2(u2, v2, chart(b));
}

bool overlap_coplanar(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
                      const Vec3& f) {
  const Chart chart(a, b, c);
  const Vec2 a2 = chart(a), b2 = chart(b), c2 = chart(c), d2 = chart(d), e2 = chart(e), f2 = chart(f);
  return segment_meets_triangle_2d(a2, b2, d2, e2, f2) || segment_meets_triangle_2d(b2, c2, d2, e2, f2) ||
         segment_meets_triangle_2d(c2, a2, d2, e2, f2) || point_in_triangle(d2, a2, b2, c2);
}

bool overlap_disjoint_ids(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
                          const Vec3& f) {
  const int od = o3(a, b, c, d);
  const int oe = o3(a, b, c, e);
  const int of = o3(a, b, c, f);
  if ((od > 0 && oe > 0 && of > 0) || (od < 0 && oe < 0 && of < 0)) return false;
  if (od == 0 && oe == 0 && of == 0) return overlap_coplanar(a, b, c, d, e, f);
  const int oa = o3(d, e, f, a);
  const int ob = o3(d, e, f, b);
  const int oc = o3(d, e, f, c);
  if ((oa > 0 && ob > 0 && oc > 0) || (oa < 0 && ob < 0 && oc < 0)) return false;
  return segment_crosses_triangle(a, b, oa, ob, d, e, f) || segment_crosses_triangle(b, c, ob, oc, d, e, f) ||
         segment_crosses_triangle(c, a, oc, oa, d, e, f) || segment_crosses_triangle(d, e, od, oe, a, b, c) ||
         segment_crosses_triangle(e, f, oe, of, a, b, c) || segment_crosses_triangle(f, d, of, od, a, b, c);
}

}  // namespace

bool triangles_overlap(std::span<const Vec3> points, const Triangle& t, const Triangle& u) {
  int shared = 0;
  std::array<int, 3> in_u{-1, -1, -1};  // for each corner of t, its corner in u or -1
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (t[static_cast<std::size_t>(i)] == u[static_cast<std::size_t>(j)]) {
        in_u[static_cast<std::size_t>(i)] = j;
        ++shared;
      }
  auto P = [&](std::uint32_t id) -> const Vec3& { return points[id]; };
  auto at = [](const Triangle& tri, int k) { return tri[static_cast<std::size_t>(((k % 3) + 3) % 3)]; };
  if (shared == 3) return true;
  if (shared == 0) return overlap_disjoint_ids(P(t[0]), P(t[1]), P(t[2]), P(u[0]), P(u[1]), P(u[2]));
  if (shared == 1) {
    const int i =
        static_cast<int>(std::find_if(in_u.begin(), in_u.end(), [](int j) { return j >= 0; }) - in_u.begin());
    const int j = in_u[static_cast<std::size_t>(i)];
    return overlap_at_vertex(P(at(t, i)), P(at(t, i + 1)), P(at(t, i + 2)), P(at(u, j + 1)), P(at(u, j + 2)));
  }
  // Two shared: the corner of t not in u, and the corner of u not in t.
  const int i = static_cast<int>(std::find(in_u.begin(), in_u.end(), -1) - in_u.begin());
  int j = 0;
  while (u[static_cast<std::size_t>(j)] == at(t, i + 1) || u[static_cast<std::size_t>(j)] == at(t, i + 2))
    ++j;
  return overlap_at_edge(P(at(t, i + 1)), P(at(t, i + 2)), P(at(t, i)), P(u[static_cast<std::size_t>(j)]));
}

bool point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  if (o3(a, b, c, p) != 0) return false;
  const Chart chart(a, b, c);
  return point_in_triangle(chart(p), chart(a), chart(b), chart(c));
}

}  // namespace cvms::detail
