// SPDX-License-Identifier: MIT
// The set oracle (see the header).
#include "support/set_oracle.hpp"

#include <algorithm>
#include <numeric>

#include "cvms/convex_hull.hpp"
#include "cvms/set_sum.hpp"

namespace cvms::test {

namespace {

Vec3 primitive_canonical(const Vec3& v) {
  mpz_class den = 1;
  for (int k = 0; k < 3; ++k) den = lcm(den, v[k].get_den());
  mpz_class c[3];
  mpz_class g = 0;
  for (int k = 0; k < 3; ++k) {
    c[k] = v[k].get_num() * (den / v[k].get_den());
    g = gcd(g, c[k]);
  }
  int first = sgn(c[0]) != 0 ? 0 : (sgn(c[1]) != 0 ? 1 : 2);
  if (sgn(c[first]) < 0) g = -g;
  return {Rational(c[0] / g), Rational(c[1] / g), Rational(c[2] / g)};
}

Vec3 primitive_positive(const Vec3& v) {
  Vec3 p = primitive_canonical(v);
  // Same direction as v.
  return dot(p, v) < 0 ? -p : p;
}

// Rank of the differences p - points[0], with up to three witnesses.
std::vector<Vec3> independent_directions(std::span<const Vec3> points) {
  std::vector<Vec3> basis;
  for (const Vec3& p : points) {
    const Vec3 d = p - points[0];
    if (basis.empty() ? !is_zero(d)
                      : basis.size() == 1 ? !is_zero(cross(basis[0], d))
                                          : basis.size() == 2 ? dot(cross(basis[0], basis[1]), d) != 0 : false)
      basis.push_back(d);
  }
  return basis;
}

// Gift wrapping in the plane with normal n: the vertices counterclockwise.
std::vector<Vec3> wrap(std::span<const Vec3> points, const Vec3& n) {
  std::vector<Vec3> pts(points.begin(), points.end());
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  std::vector<Vec3> hull{pts[0]};  // the smallest point is a vertex
  for (;;) {
    const Vec3& p = hull.back();
    const Vec3* best = nullptr;
    for (const Vec3& q : pts) {
      if (q == p) continue;
      if (!best) {
        best = &q;
        continue;
      }
      const Rational turn = dot(cross(*best - p, q - p), n);
      // q clockwise of best: q is the better candidate; collinear: farther.
      if (turn < 0 || (turn == 0 && dot(q - p, q - p) > dot(*best - p, *best - p))) best = &q;
    }
    if (*best == hull[0]) break;
    hull.push_back(*best);
    if (hull.size() > pts.size()) break;  // cannot happen; keeps a broken input finite
  }
  return hull;
}

void add_polygon_planes(SetShape& shape, const std::vector<Vec3>& cycle, const Vec3& n) {
  shape.planes.insert({n, dot(n, cycle[0])});
  for (std::size_t i = 0; i < cycle.size(); ++i) {
    const Vec3 out = primitive_positive(cross(cycle[(i + 1) % cycle.size()] - cycle[i], n));
    shape.planes.insert({out, dot(out, cycle[i])});
  }
}

}  // namespace

SetShape hull_oracle(std::span<const Vec3> points) {
  SetShape shape;
  if (points.empty()) return shape;
  const std::vector<Vec3> basis = independent_directions(points);
  shape.dimension = static_cast<int>(basis.size());
  switch (shape.dimension) {
    case 0:
      shape.vertices.insert(points[0]);
      break;
    case 1: {  // on a line, lexicographic order is the order along it
      const auto [lo, hi] = std::minmax_element(points.begin(), points.end());
      shape.vertices = {*lo, *hi};
      break;
    }
    case 2: {
      const Vec3 n = primitive_canonical(cross(basis[0], basis[1]));
      const std::vector<Vec3> cycle = wrap(points, n);
      shape.vertices.insert(cycle.begin(), cycle.end());
      add_polygon_planes(shape, cycle, n);
      break;
    }
    default: {
      const Shape s = describe(convex_hull(points));
      shape.vertices = s.vertices;
      shape.planes = s.planes;
    }
  }
  return shape;
}

SetShape sum_oracle(const ConvexSet& a, const ConvexSet& b) {
  const std::vector<Vec3> va = a.vertices(), vb = b.vertices();
  return hull_oracle(pairwise_sums(va, vb));
}

SetShape describe_set(const ConvexSet& s) {
  SetShape shape;
  shape.dimension = s.dimension();
  const std::vector<Vec3> v = s.vertices();
  shape.vertices.insert(v.begin(), v.end());
  if (s.dimension() == 2) add_polygon_planes(shape, v, primitive_canonical(s.normal()));
  if (s.dimension() == 3) shape.planes = describe(s.polyhedron()).planes;
  return shape;
}

std::string check_set_invariants(const ConvexSet& s) {
  const std::vector<Vec3> v = s.vertices();
  if (v.size() != s.num_vertices()) return "num_vertices() differs from vertices().size()";
  switch (s.dimension()) {
    case -1:
      return v.empty() ? "" : "the empty set has vertices";
    case 0:
      return v.size() == 1 ? "" : "a point without exactly one vertex";
    case 1:
      return v.size() == 2 && v[0] < v[1] ? "" : "a segment's endpoints are not two, distinct and ordered";
    case 2: {
      if (v.size() < 3) return "a polygon with fewer than 3 vertices";
      const Vec3& n = s.normal();
      if (is_zero(n) || primitive_canonical(n) != n) return "polygon normal " + to_text(n) + " is not canonical";
      if (*std::min_element(v.begin(), v.end()) != v[0]) return "the polygon does not start at its smallest vertex";
      for (std::size_t i = 0; i < v.size(); ++i) {
        if (dot(n, v[i]) != s.plane_offset()) return "polygon vertex " + std::to_string(i) + " is off the plane";
        const Vec3& a = v[i];
        const Vec3& b = v[(i + 1) % v.size()];
        for (std::size_t j = 0; j < v.size(); ++j)
          if (j != i && j != (i + 1) % v.size() && dot(cross(b - a, v[j] - a), n) <= 0)
            return "polygon vertex " + std::to_string(j) + " is not strictly left of edge " + std::to_string(i);
      }
      return "";
    }
    case 3:
      return check_invariants(s.polyhedron());
    default:
      return "dimension " + std::to_string(s.dimension());
  }
}

std::string check_set_sum(const ConvexSet& a, const ConvexSet& b, const Options& options) {
  const SetShape expected = sum_oracle(a, b);
  for (int order = 0; order < 2; ++order) {
    const ConvexSet sum = order == 0 ? minkowski_sum(a, b, options) : minkowski_sum(b, a, options);
    const std::string which = order == 0 ? "a + b: " : "b + a: ";
    if (std::string bad = check_set_invariants(sum); !bad.empty()) return which + bad;
    if (describe_set(sum) != expected) return which + difference(expected, describe_set(sum));
  }
  return "";
}

std::string difference(const SetShape& expected, const SetShape& actual) {
  std::string out;
  if (expected.dimension != actual.dimension)
    out += "dimension " + std::to_string(expected.dimension) + " expected, got " + std::to_string(actual.dimension) + "; ";
  out += difference(Shape{expected.vertices, expected.planes}, Shape{actual.vertices, actual.planes});
  return out;
}

}  // namespace cvms::test
