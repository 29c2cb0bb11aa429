// SPDX-License-Identifier: MIT
// round_to_doubles and to_float_mesh: exact convex sets in doubles.
//
// Both modes end in the exact hull of a set of double points R, so the
// result is a convex set whose facets are maximal and exactly planar in its
// own double coordinates: the quickhull decides every sign exactly on the
// doubles themselves.
//
// nearest. R = {round(v) : v a vertex of the exact set P}, round to nearest
// per coordinate, and Q = conv R. Bound: d_H(P, Q) <= max_v |v - round(v)|.
// Proof: a point p = sum l_v v of P (l_v >= 0, sum l_v = 1) has the point
// q = sum l_v round(v) of Q with |p - q| <= sum l_v |v - round(v)| <= max_v
// |v - round(v)|, and symmetrically every point of Q is that close to one of
// P. Each coordinate moves by at most half an ulp of itself, so
// |v - round(v)| <= sqrt(3) * ulp(v) / 2, ulp(v) the largest of its
// coordinates' ulps.
//
// outer. For a coordinate c, lo(c) is the largest double <= c and hi(c) the
// smallest double >= c (both c when c is a double). The box
// B(v) = [lo(x), hi(x)] x [lo(y), hi(y)] x [lo(z), hi(z)] is the hull of its
// corners, and v lies in it; R is the union of the corners of every B(v)
// (2^k of them for a vertex with k coordinates that are not doubles) and
// Q = conv R. Containment: every vertex v of P lies in B(v) = conv(corners)
// within conv R = Q, and Q is convex, so P = conv(vertices) lies in Q.
// Bound: every corner is within |hi - lo| <= ulp per coordinate of its v,
// and the proof above gives d_H(P, Q) <= max_v sqrt(3) * ulp(v). Taking
// only the corners (not the boxes' other points) is what keeps R small: the
// hull of the corners is the hull of the boxes.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/float_mesh.hpp"
#include "cvms/rational.hpp"

namespace cvms {

namespace {

using DoublePoint = std::array<double, 3>;

constexpr double infinity = std::numeric_limits<double>::infinity();

[[noreturn]] void beyond_range(std::size_t vertex, int axis) {
  throw Error(ErrorCategory::invalid_argument, "vertex " + std::to_string(vertex) + ": coordinate " +
                                                   "xyz"[axis] + " is beyond the range of double");
}

double nearest(const Rational& c, std::size_t vertex, int axis) {
  const double d = to_double_nearest(c);
  if (!std::isfinite(d)) beyond_range(vertex, axis);
  return d;
}

// lo(c) and hi(c) of the file comment; equal when c is a double.
std::array<double, 2> enclosing(const Rational& c, std::size_t vertex, int axis) {
  const double d = nearest(c, vertex, axis);
  const int order = cmp(Rational(d), c);
  const std::array<double, 2> bounds =
      order == 0 ? std::array{d, d} : order < 0 ? std::array{d, std::nextafter(d, infinity)}
                                                : std::array{std::nextafter(d, -infinity), d};
  if (!std::isfinite(bounds[0]) || !std::isfinite(bounds[1])) beyond_range(vertex, axis);
  return bounds;
}

// The corners of v's enclosing box, each once.
void append_box_corners(const Vec3& v, std::size_t vertex, std::vector<DoublePoint>& out) {
  const std::array<double, 2> x = enclosing(v.x, vertex, 0), y = enclosing(v.y, vertex, 1),
                              z = enclosing(v.z, vertex, 2);
  for (int i = 0; i < (x[0] == x[1] ? 1 : 2); ++i)
    for (int j = 0; j < (y[0] == y[1] ? 1 : 2); ++j)
      for (int k = 0; k < (z[0] == z[1] ? 1 : 2); ++k) out.push_back({x[i], y[j], z[k]});
}

template <class VertexAt>
std::vector<DoublePoint> rounded_points(std::size_t n, VertexAt vertex_at, FloatMode mode) {
  std::vector<DoublePoint> points;
  points.reserve(mode == FloatMode::nearest ? n : 2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& v = vertex_at(i);
    if (mode == FloatMode::nearest)
      points.push_back({nearest(v.x, i, 0), nearest(v.y, i, 1), nearest(v.z, i, 2)});
    else
      append_box_corners(v, i, points);
  }
  return points;
}

template <class VertexAt>
bool all_doubles(std::size_t n, VertexAt vertex_at) {
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& v = vertex_at(i);
    if (!is_double_exact(v.x) || !is_double_exact(v.y) || !is_double_exact(v.z)) return false;
  }
  return true;
}

// The hull in the dimension the points span. The double quickhull converts
// only what it needs; the general hull, which converts every point, is for
// the rare rounding that flattens a polyhedron.
ConvexSet hull_of(const std::vector<DoublePoint>& points, bool expect_solid) {
  if (expect_solid) {
    try {
      return convex_hull(std::span<const DoublePoint>(points));
    } catch (const Error& e) {
      if (e.category() != ErrorCategory::degenerate) throw;
    }
  }
  return convex_hull_set(std::span<const DoublePoint>(points));
}

FloatMesh mesh_of(const ConvexSet& rounded) {
  const PolygonSoup soup = rounded.to_soup();
  FloatMesh mesh;
  mesh.positions.reserve(3 * soup.points.size());
  for (const Vec3& p : soup.points)
    for (const Rational* c : {&p.x, &p.y, &p.z}) mesh.positions.push_back(to_double_nearest(*c));
  mesh.face_offsets = soup.face_offsets;
  mesh.face_indices = soup.face_indices;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const std::span<const std::uint32_t> face = soup.face(f);
    for (std::size_t i = 1; i + 1 < face.size(); ++i)
      mesh.triangles.insert(mesh.triangles.end(), {face[0], face[i], face[i + 1]});
  }
  return mesh;
}

}  // namespace

ConvexSet round_to_doubles(const ConvexPolyhedron& p, FloatMode mode) {
  const auto vertex_at = [&p](std::size_t i) -> const Vec3& { return p.vertex(VertexId(static_cast<std::uint32_t>(i))); };
  if (all_doubles(p.num_vertices(), vertex_at)) return ConvexSet(p);
  return hull_of(rounded_points(p.num_vertices(), vertex_at, mode), true);
}

ConvexSet round_to_doubles(const ConvexSet& set, FloatMode mode) {
  if (set.dimension() == 3) return round_to_doubles(set.polyhedron(), mode);
  const std::vector<Vec3> vertices = set.vertices();
  const auto vertex_at = [&vertices](std::size_t i) -> const Vec3& { return vertices[i]; };
  if (all_doubles(vertices.size(), vertex_at)) return set;
  return hull_of(rounded_points(vertices.size(), vertex_at, mode), false);
}

FloatMesh to_float_mesh(const ConvexSet& set, FloatMode mode) { return mesh_of(round_to_doubles(set, mode)); }

FloatMesh to_float_mesh(const ConvexPolyhedron& p, FloatMode mode) { return mesh_of(round_to_doubles(p, mode)); }

}  // namespace cvms
