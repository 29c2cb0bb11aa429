// SPDX-License-Identifier: MIT
// Written independently of the library's algorithms: plain rational
// arithmetic, no predicates, no caches.
#include "support/oracle.hpp"

#include <sstream>

namespace cvms::test {
namespace {

// The positive multiple of a nonzero rational vector that is a primitive integer vector.
Vec3 primitive(const Vec3& v) {
  mpz_class l = 1;
  for (int i = 0; i < 3; ++i) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), v[i].get_den_mpz_t());
  mpz_class c[3];
  for (int i = 0; i < 3; ++i) c[i] = v[i].get_num() * (l / v[i].get_den());
  mpz_class g = 0;
  for (auto& x : c) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), x.get_mpz_t());
  return {Rational(c[0] / g), Rational(c[1] / g), Rational(c[2] / g)};
}

Plane plane_of(const Vec3& normal, const Vec3& point) {
  Vec3 n = primitive(normal);
  return {n, dot(n, point)};
}

std::vector<Vec3> face_points(const ConvexPolyhedron& p, FaceId f) {
  std::vector<Vec3> pts;
  for (HalfedgeId h : p.mesh().face_halfedges(f)) pts.push_back(p.vertex(p.mesh().from(h)));
  return pts;
}

// Outward plane of a facet: normal from three non-collinear facet points,
// signed so that the whole polyhedron is on or below it.
bool outward_plane(const ConvexPolyhedron& p, FaceId f, Plane& out) {
  auto pts = face_points(p, f);
  for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
    Vec3 n = cross(pts[i] - pts[0], pts[i + 1] - pts[0]);
    if (is_zero(n)) continue;
    for (VertexId v : p.mesh().vertices()) {
      int s = sgn(dot(n, p.vertex(v) - pts[0]));
      if (s > 0) n = -n;
      if (s != 0) break;
    }
    out = plane_of(n, pts[0]);
    return true;
  }
  return false;
}

}  // namespace

Shape describe(const ConvexPolyhedron& p) {
  Shape s;
  for (VertexId v : p.mesh().vertices()) s.vertices.insert(p.vertex(v));
  for (FaceId f : p.mesh().faces()) {
    Plane pl;
    if (outward_plane(p, f, pl)) s.planes.insert(pl);
  }
  return s;
}

namespace {
Vec3 area_vector(const PolygonSoup& soup, std::size_t f) {
  auto face = soup.face(f);
  Vec3 n{0, 0, 0};
  for (std::size_t i = 0; i < face.size(); ++i)
    n += cross(soup.points[face[i]], soup.points[face[(i + 1) % face.size()]]);
  return n;
}
}  // namespace

Shape describe(const PolygonSoup& soup) {
  Shape s;
  s.vertices.insert(soup.points.begin(), soup.points.end());
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    Vec3 n = area_vector(soup, f);
    if (!is_zero(n) && !soup.face(f).empty()) s.planes.insert(plane_of(n, soup.points[soup.face(f)[0]]));
  }
  return s;
}

std::string check_soup_invariants(const PolygonSoup& soup) {
  const std::size_t nv = soup.points.size(), nf = soup.num_faces();
  if (std::set<Vec3>(soup.points.begin(), soup.points.end()).size() != nv) return "two points are equal";
  std::vector<int> used(nv, 0);
  std::set<std::pair<std::uint32_t, std::uint32_t>> directed;
  std::vector<Plane> planes(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const std::string name = "face " + std::to_string(f);
    auto face = soup.face(f);
    if (face.size() < 3) return name + " has fewer than 3 vertices";
    for (std::uint32_t i : face) {
      if (i >= nv) return name + " has an index out of range";
      ++used[i];
    }
    Vec3 n = area_vector(soup, f);
    if (is_zero(n)) return name + " has zero area";
    planes[f] = plane_of(n, soup.points[face[0]]);
    const Plane& pl = planes[f];
    for (std::size_t i = 0; i < face.size(); ++i) {
      const Vec3& a = soup.points[face[i]];
      const Vec3& b = soup.points[face[(i + 1) % face.size()]];
      const Vec3& c = soup.points[face[(i + 2) % face.size()]];
      if (dot(pl.normal, a) != pl.offset) return name + " is not planar";
      if (sgn(dot(cross(b - a, c - b), pl.normal)) <= 0) return name + " is not strictly convex";
      if (!directed.insert({face[i], face[(i + 1) % face.size()]}).second)
        return name + " repeats a directed edge";
    }
    for (const Vec3& q : soup.points)
      if (dot(pl.normal, q) > pl.offset) return "a point is above " + name;
  }
  for (std::size_t v = 0; v < nv; ++v)
    if (used[v] == 0) return "point " + std::to_string(v) + " is unused";
  for (const auto& [a, b] : directed)
    if (!directed.count({b, a})) return "edge without a twin";
  const long euler = static_cast<long>(nv) - static_cast<long>(directed.size() / 2) + static_cast<long>(nf);
  if (euler != 2) return "Euler characteristic " + std::to_string(euler);
  // On a convex polyhedron no two faces lie in one plane (a stronger check
  // than "faces sharing an edge are not coplanar").
  if (std::set<Plane>(planes.begin(), planes.end()).size() != nf) return "two faces are coplanar";
  return "";
}

Shape brute_force_hull(std::span<const Vec3> input) {
  std::set<Vec3> unique(input.begin(), input.end());
  std::vector<Vec3> pts(unique.begin(), unique.end());
  Shape s;
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        Vec3 normal = cross(pts[j] - pts[i], pts[k] - pts[i]);
        if (is_zero(normal)) continue;
        bool any_above = false, any_below = false;
        const Rational offset = dot(normal, pts[i]);
        for (const Vec3& q : pts) {
          int side = cmp(dot(normal, q), offset);
          any_above |= side > 0;
          any_below |= side < 0;
          if (any_above && any_below) break;
        }
        if (any_above && any_below) continue;
        if (!any_above && !any_below) return {};  // all coplanar: not 3D
        s.planes.insert(plane_of(any_above ? -normal : normal, pts[i]));
      }
  for (const Vec3& q : pts) {
    int on = 0;
    for (const Plane& pl : s.planes) on += dot(pl.normal, q) == pl.offset;
    if (on >= 3) s.vertices.insert(q);
  }
  return s;
}

std::vector<Vec3> pairwise_sums(std::span<const Vec3> a, std::span<const Vec3> b) {
  std::vector<Vec3> out;
  out.reserve(a.size() * b.size());
  for (const Vec3& x : a)
    for (const Vec3& y : b) out.push_back(x + y);
  return out;
}

// Appended piece by piece: "(" + std::string&& makes GCC 12 at -O3 print a
// false -Wrestrict for the insert at position 0 (GCC bug 105329).
std::string to_text(const Vec3& v) {
  std::string s = "(";
  s += to_string(v.x);
  s += ", ";
  s += to_string(v.y);
  s += ", ";
  s += to_string(v.z);
  s += ")";
  return s;
}

std::string difference(const Shape& expected, const Shape& actual) {
  std::ostringstream out;
  out << "expected V=" << expected.vertices.size() << " F=" << expected.planes.size() << ", got V="
      << actual.vertices.size() << " F=" << actual.planes.size() << "\n";
  int shown = 0;
  for (const Vec3& v : expected.vertices)
    if (!actual.vertices.count(v) && shown++ < 5) out << "  missing vertex " << to_text(v) << "\n";
  for (const Vec3& v : actual.vertices)
    if (!expected.vertices.count(v) && shown++ < 10) out << "  extra vertex " << to_text(v) << "\n";
  for (const Plane& p : expected.planes)
    if (!actual.planes.count(p) && shown++ < 15) out << "  missing plane " << to_text(p.normal) << " . x = " << to_string(p.offset) << "\n";
  for (const Plane& p : actual.planes)
    if (!expected.planes.count(p) && shown++ < 20) out << "  extra plane " << to_text(p.normal) << " . x = " << to_string(p.offset) << "\n";
  return out.str();
}

std::string check_invariants(const ConvexPolyhedron& p) {
  try {
    p.mesh().validate();
  } catch (const std::exception& e) {
    return std::string("validate: ") + e.what();
  }
  const Mesh& m = p.mesh();
  if (p.euler_characteristic() != 2 ||
      static_cast<int>(m.num_vertices()) - static_cast<int>(m.num_edges()) + static_cast<int>(m.num_faces()) != 2)
    return "Euler characteristic is not 2";
  std::vector<Plane> planes(m.num_faces());
  for (FaceId f : m.faces()) {
    if (!outward_plane(p, f, planes[f.index()])) return "face " + std::to_string(f.index()) + " has zero area";
    const Plane& pl = planes[f.index()];
    auto pts = face_points(p, f);
    for (const Vec3& q : pts)
      if (dot(pl.normal, q) != pl.offset) return "face " + std::to_string(f.index()) + " is not planar";
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Vec3& a = pts[i];
      const Vec3& b = pts[(i + 1) % pts.size()];
      const Vec3& c = pts[(i + 2) % pts.size()];
      if (sgn(dot(cross(b - a, c - b), pl.normal)) <= 0)
        return "face " + std::to_string(f.index()) + " is not strictly convex counterclockwise from outside";
    }
    for (VertexId v : m.vertices())
      if (dot(pl.normal, p.vertex(v)) > pl.offset)
        return "vertex " + std::to_string(v.index()) + " is above face " + std::to_string(f.index());
    if (primitive(p.normal(f)) != pl.normal || p.normal(f) != pl.normal)
      return "cached normal of face " + std::to_string(f.index()) + " is wrong";
    if (p.plane_offset(f) != pl.offset) return "cached offset of face " + std::to_string(f.index()) + " is wrong";
  }
  for (EdgeId e : m.edges()) {
    HalfedgeId h = Mesh::halfedge(e);
    if (planes[m.face(h).index()].normal == planes[m.face(Mesh::twin(h)).index()].normal)
      return "faces " + std::to_string(m.face(h).index()) + " and " + std::to_string(m.face(Mesh::twin(h)).index()) +
             " are coplanar";
  }
  return "";
}

}  // namespace cvms::test
