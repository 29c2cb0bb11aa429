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

// The closed segment [p, q] and the closed triangle (a, b, c).
bool segment_meets_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const int op = o3(a, b, c, p);
  const int oq = o3(a, b, c, q);
  if (op * oq > 0) return false;
  if (op == 0 && oq == 0) {
    const Chart chart(a, b, c);
    return segment_meets_triangle_2d(chart(p), chart(q), chart(a), chart(b), chart(c));
  }
  // The segment crosses the plane at one point: it is in the triangle iff
  // the line pq passes through the closed triangle, i.e. it turns the same
  // way (or not at all) around the three edges.
  const int s1 = o3(p, q, a, b);
  const int s2 = o3(p, q, b, c);
  const int s3 = o3(p, q, c, a);
  const bool positive = s1 > 0 || s2 > 0 || s3 > 0;
  const bool negative = s1 < 0 || s2 < 0 || s3 < 0;
  return !(positive && negative);
}

// a lies in the plane of the triangle (v, c, d): does the direction a - v
// lie in the triangle's closed angle at v?
bool in_angle(const Vec3& v, const Vec3& c, const Vec3& d, const Vec3& a) {
  const Chart chart(v, c, d);
  const Vec2 v2 = chart(v);
  const Vec2 c2 = chart(c);
  const Vec2 d2 = chart(d);
  const Vec2 a2 = chart(a);
  const int s = o2(v2, c2, d2);
  return o2(v2, c2, a2) * s >= 0 && o2(v2, a2, d2) * s >= 0;
}

// t = (v, a, b) and u = (v, c, d) share exactly the vertex v.
bool overlap_at_vertex(const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const int oc = o3(v, a, b, c);
  const int od = o3(v, a, b, d);
  if (oc * od > 0) return false;  // u meets t's plane only at v
  const int oa = o3(v, c, d, a);
  const int ob = o3(v, c, d, b);
  if (oa * ob > 0) return false;
  if (segment_meets_triangle(a, b, v, c, d) || segment_meets_triangle(c, d, v, a, b)) return true;
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

bool overlap_disjoint_ids(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
                          const Vec3& f) {
  const int od = o3(a, b, c, d);
  const int oe = o3(a, b, c, e);
  const int of = o3(a, b, c, f);
  if ((od > 0 && oe > 0 && of > 0) || (od < 0 && oe < 0 && of < 0)) return false;
  const int oa = o3(d, e, f, a);
  const int ob = o3(d, e, f, b);
  const int oc = o3(d, e, f, c);
  if ((oa > 0 && ob > 0 && oc > 0) || (oa < 0 && ob < 0 && oc < 0)) return false;
  return segment_meets_triangle(a, b, d, e, f) || segment_meets_triangle(b, c, d, e, f) ||
         segment_meets_triangle(c, a, d, e, f) || segment_meets_triangle(d, e, a, b, c) ||
         segment_meets_triangle(e, f, a, b, c) || segment_meets_triangle(f, d, a, b, c);
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
  if (shared == 0)
    return overlap_disjoint_ids(P(t[0]), P(t[1]), P(t[2]), P(u[0]), P(u[1]), P(u[2]));
  if (shared == 1) {
    const int i = static_cast<int>(std::find_if(in_u.begin(), in_u.end(), [](int j) { return j >= 0; }) - in_u.begin());
    const int j = in_u[static_cast<std::size_t>(i)];
    return overlap_at_vertex(P(at(t, i)), P(at(t, i + 1)), P(at(t, i + 2)), P(at(u, j + 1)), P(at(u, j + 2)));
  }
  // Two shared: the corner of t not in u, and the corner of u not in t.
  const int i = static_cast<int>(std::find(in_u.begin(), in_u.end(), -1) - in_u.begin());
  int j = 0;
  while (u[static_cast<std::size_t>(j)] == at(t, i + 1) || u[static_cast<std::size_t>(j)] == at(t, i + 2)) ++j;
  return overlap_at_edge(P(at(t, i + 1)), P(at(t, i + 2)), P(at(t, i)), P(u[static_cast<std::size_t>(j)]));
}

bool point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  if (o3(a, b, c, p) != 0) return false;
  const Chart chart(a, b, c);
  return point_in_triangle(chart(p), chart(a), chart(b), chart(c));
}

}  // namespace cvms::detail
