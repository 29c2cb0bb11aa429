// SPDX-License-Identifier: MIT
// The brute-force proximity oracle (see proximity_oracle.hpp). The boundary
// of M is the union of its closed facets, and the nearest point of a closed
// convex polygon is either the projection onto its plane (when that lies in
// the polygon) or the nearest point of one of its edges, which is either an
// interior projection onto the edge's line or an end: so the minimum over all
// those candidates is the distance to the boundary.
#include "support/proximity_oracle.hpp"

#include <algorithm>
#include <optional>

#include <random>
#include <utility>

#include "cvms/minkowski.hpp"
#include "support/oracle.hpp"
#include "support/random_clouds.hpp"

namespace cvms::test {
namespace {

Rational norm2(const Vec3& v) { return dot(v, v); }

void keep_min(std::optional<Rational>& best, const Rational& candidate) {
  if (!best || candidate < *best) best = candidate;
}

// The projection of the origin onto facet f's plane, if it is in the facet.
std::optional<Rational> facet_candidate(const ConvexPolyhedron& m, FaceId f) {
  const Vec3& n = m.normal(f);
  const Rational c = m.plane_offset(f);
  const Vec3 p = (c / norm2(n)) * n;
  const Mesh& mesh = m.mesh();
  for (HalfedgeId h : mesh.face_halfedges(f)) {
    const Vec3& u = mesh.position(mesh.from(h));
    const Vec3& w = mesh.position(mesh.to(h));
    if (dot(cross(w - u, p - u), n) < 0) return std::nullopt;  // outside this edge (facets are ccw from outside)
  }
  return norm2(p);
}

}  // namespace

Rational origin_segment_distance2(const Vec3& u, const Vec3& w) {
  const Vec3 e = w - u;
  const Rational t = -dot(u, e) / norm2(e);
  if (t <= 0) return norm2(u);
  if (t >= 1) return norm2(w);
  return norm2(u + t * e);
}

OriginAndPolytope origin_versus(const ConvexPolyhedron& m) {
  OriginAndPolytope out;
  out.inside = true;
  for (FaceId f : m.mesh().faces())
    if (sgn(m.plane_offset(f)) < 0) out.inside = false;
  std::optional<Rational> best;
  for (FaceId f : m.mesh().faces())
    if (auto c = facet_candidate(m, f)) keep_min(best, *c);
  for (EdgeId e : m.mesh().edges()) {
    const HalfedgeId h = Mesh::halfedge(e);
    keep_min(best, origin_segment_distance2(m.mesh().position(m.mesh().from(h)), m.mesh().position(m.mesh().to(h))));
  }
  for (VertexId v : m.mesh().vertices()) keep_min(best, norm2(m.vertex(v)));
  out.boundary_distance2 = *best;
  if (out.inside) {
    for (FaceId f : m.mesh().faces()) {
      const Rational& c = m.plane_offset(f);
      if (c * c / norm2(m.normal(f)) == out.boundary_distance2) out.nearest_normals.push_back(m.normal(f));
    }
    std::sort(out.nearest_normals.begin(), out.nearest_normals.end());
  }
  return out;
}

OriginAndPolytope proximity_oracle(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  return origin_versus(chms(a, b.reflected()));
}

bool contains(const ConvexPolyhedron& p, const Vec3& x) {
  for (FaceId f : p.mesh().faces())
    if (dot(p.normal(f), x) > p.plane_offset(f)) return false;
  return true;
}

std::string check_distance_by(const Membership& in_a, const Membership& in_b, const DistanceResult& d,
                              const OriginAndPolytope& oracle) {
  const Rational expected = oracle.inside ? Rational(0) : oracle.boundary_distance2;
  if (d.squared_distance != expected)
    return "squared_distance " + to_string(d.squared_distance) + ", expected " + to_string(expected);
  if (d.intersect != oracle.inside) return std::string("intersect ") + (d.intersect ? "yes" : "no") + ", expected the opposite";
  if (!in_a(d.witness_a)) return "witness_a " + to_text(d.witness_a) + " is not in A";
  if (!in_b(d.witness_b)) return "witness_b " + to_text(d.witness_b) + " is not in B";
  if (norm2(d.witness_a - d.witness_b) != d.squared_distance)
    return "the witnesses are at squared distance " + to_string(norm2(d.witness_a - d.witness_b));
  return "";
}

std::string check_penetration_by(const Membership& in_a, const Membership& in_b, const PenetrationResult& p,
                                 const OriginAndPolytope& oracle) {
  if (p.intersect != oracle.inside) return std::string("intersect ") + (p.intersect ? "yes" : "no") + ", expected the opposite";
  if (!oracle.inside) {
    if (sgn(p.squared_depth) != 0 || !is_zero(p.direction)) return "apart, but a depth or direction is reported";
    return "";
  }
  if (p.squared_depth != oracle.boundary_distance2)
    return "squared_depth " + to_string(p.squared_depth) + ", expected " + to_string(oracle.boundary_distance2);
  if (oracle.nearest_normals.empty() || p.direction != oracle.nearest_normals.front())
    return "direction " + to_text(p.direction) + " is not the smallest nearest facet normal";
  const Vec3 t = p.translation();
  if (norm2(t) != p.squared_depth) return "|translation|^2 differs from squared_depth";
  if (!in_a(p.witness_a)) return "witness_a " + to_text(p.witness_a) + " is not in A";
  if (!in_b(p.witness_b)) return "witness_b " + to_text(p.witness_b) + " is not in B";
  if (p.witness_a - p.witness_b != t) return "witness_a - witness_b is not the translation";
  return "";
}

namespace {

Membership membership(const ConvexPolyhedron& p) {
  return [&p](const Vec3& x) { return contains(p, x); };
}

}  // namespace

std::string check_distance(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const DistanceResult& d,
                           const OriginAndPolytope& oracle) {
  return check_distance_by(membership(a), membership(b), d, oracle);
}

std::string check_penetration(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const PenetrationResult& p,
                              const OriginAndPolytope& oracle) {
  return check_penetration_by(membership(a), membership(b), p, oracle);
}

namespace {

// A point on the boundary of m: a vertex, an edge midpoint or the average of a facet's vertices.
Vec3 boundary_point(const ConvexPolyhedron& m, std::mt19937_64& rng) {
  const Mesh& mesh = m.mesh();
  switch (rng() % 3) {
    case 0:
      return m.vertex(VertexId(static_cast<std::uint32_t>(rng() % m.num_vertices())));
    case 1: {
      const HalfedgeId h = Mesh::halfedge(EdgeId(static_cast<std::uint32_t>(rng() % m.num_edges())));
      return Rational(1, 2) * (mesh.position(mesh.from(h)) + mesh.position(mesh.to(h)));
    }
    default: {
      const FaceId f(static_cast<std::uint32_t>(rng() % m.num_facets()));
      Vec3 s{0, 0, 0};
      for (HalfedgeId h : mesh.face_halfedges(f)) s += mesh.position(mesh.from(h));
      return Rational(1, mesh.degree(f)) * s;
    }
  }
}

const char* placing_name(Placing p) {
  return p == Placing::overlapping ? "overlapping" : (p == Placing::touching ? "touching" : "separated");
}

}  // namespace

RandomPlacement random_placement(std::uint64_t seed) {
  RandomPair pair = random_pair(seed, 20);
  std::mt19937_64 rng(seed);
  const ConvexPolyhedron m = chms(pair.a, pair.b.reflected());
  Vec3 c{0, 0, 0};
  for (VertexId v : m.mesh().vertices()) c += m.vertex(v);
  c = Rational(1, m.num_vertices()) * c;  // interior: M is full-dimensional
  const Vec3 q = boundary_point(m, rng);
  RandomPlacement out;
  out.kind = static_cast<Placing>(rng() % 3);
  const Rational lambda = out.kind == Placing::overlapping ? Rational(static_cast<long>(rng() % 7) + 1, 8)
                          : out.kind == Placing::touching  ? Rational(1)
                                                           : Rational(static_cast<long>(rng() % 16) + 9, 8);
  out.a = std::move(pair.a);
  out.b = pair.b.translated(c + lambda * (q - c));
  out.description = pair.description + ", " + placing_name(out.kind);
  out.oracle = proximity_oracle(out.a, out.b);
  if (out.oracle.inside != (out.kind != Placing::separated))
    out.failure = "the oracle contradicts the construction (inside)";
  else if (out.kind == Placing::touching && sgn(out.oracle.boundary_distance2) != 0)
    out.failure = "the oracle contradicts the construction (touching)";
  return out;
}

RandomPlacementCheck check_random_placement(std::uint64_t seed) {
  const RandomPlacement p = random_placement(seed);
  RandomPlacementCheck out{p.kind, p.description, p.failure};
  if (!out.failure.empty()) return out;
  out.failure = check_distance(p.a, p.b, squared_distance(p.a, p.b), p.oracle);
  if (out.failure.empty() && intersects(p.a, p.b) != p.oracle.inside) out.failure = "intersects disagrees";
  if (out.failure.empty()) out.failure = check_penetration(p.a, p.b, penetration(p.a, p.b), p.oracle);
  return out;
}

}  // namespace cvms::test
