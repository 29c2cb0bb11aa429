// SPDX-License-Identifier: MIT
// The proximity oracle of convex sets (see set_proximity_oracle.hpp). For a
// flat M the nearest point to the origin is, as for a facet, either the
// projection onto M's plane when that lies inside all of M's edge lines, or
// the nearest point of an edge, or a vertex; a segment is one edge, a point
// one vertex. M has no interior then, so the origin in M is on its boundary.
#include "support/set_proximity_oracle.hpp"

#include <algorithm>
#include <optional>
#include <random>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "support/oracle.hpp"
#include "support/random_sets.hpp"
#include "support/set_oracle.hpp"

namespace cvms::test {
namespace {

Rational norm2(const Vec3& v) { return dot(v, v); }

std::vector<Vec3> differences(const ConvexSet& a, const ConvexSet& b) {
  std::vector<Vec3> out;
  for (const Vec3& p : a.vertices())
    for (const Vec3& q : b.vertices()) out.push_back(p - q);
  return out;
}

// M's own plane (the one holding every vertex) and its edge planes.
std::optional<Rational> polygon_face_candidate(const SetShape& m, const Plane& own) {
  const Vec3 p = (own.offset / norm2(own.normal)) * own.normal;
  for (const Plane& e : m.planes)
    if (!(e == own) && dot(e.normal, p) > e.offset) return std::nullopt;
  return norm2(p);
}

bool holds_all(const SetShape& m, const Plane& plane) {
  for (const Vec3& v : m.vertices)
    if (dot(plane.normal, v) != plane.offset) return false;
  return true;
}

// The squared distance from the origin to a flat M, and its plane normal.
Rational flat_distance2(const SetShape& m, Vec3& plane_normal) {
  std::optional<Rational> best;
  auto keep = [&best](const Rational& c) {
    if (!best || c < *best) best = c;
  };
  for (const Vec3& v : m.vertices) keep(norm2(v));
  if (m.dimension == 1) keep(origin_segment_distance2(*m.vertices.begin(), *m.vertices.rbegin()));
  for (const Plane& plane : m.planes) {
    if (holds_all(m, plane)) {
      plane_normal = plane.normal;
      if (auto c = polygon_face_candidate(m, plane)) keep(*c);
      continue;
    }
    std::vector<Vec3> ends;
    for (const Vec3& v : m.vertices)
      if (dot(plane.normal, v) == plane.offset) ends.push_back(v);
    if (ends.size() == 2) keep(origin_segment_distance2(ends[0], ends[1]));
  }
  return *best;
}

std::string check_flat_penetration(const Membership& in_a, const Membership& in_b, const PenetrationResult& p,
                                   const SetProximityOracle& oracle) {
  if (p.intersect != oracle.origin.inside) return std::string("penetration: intersect ") + (p.intersect ? "yes" : "no");
  if (sgn(p.squared_depth) != 0 || sgn(p.offset) != 0) return "flat M: the depth and offset must be 0";
  const Vec3 expected = oracle.origin.inside && oracle.dimension == 2 ? oracle.origin.nearest_normals.front()
                                                                      : Vec3{0, 0, 0};
  if (p.direction != expected) return "flat M: direction " + to_text(p.direction) + ", expected " + to_text(expected);
  if (!in_a(p.witness_a) || !in_b(p.witness_b)) return "penetration: a witness is not in its operand";
  if (norm2(p.witness_a - p.witness_b) != oracle.origin.boundary_distance2 && !oracle.origin.inside)
    return "penetration: the witnesses are not at the distance";
  if (oracle.origin.inside && p.witness_a != p.witness_b) return "penetration: the witnesses are not a common point";
  return "";
}

}  // namespace

SetProximityOracle set_proximity_oracle(const ConvexSet& a, const ConvexSet& b) {
  const std::vector<Vec3> points = differences(a, b);
  const SetShape m = hull_oracle(points);
  SetProximityOracle out;
  out.dimension = m.dimension;
  if (m.dimension == 3) {
    out.origin = origin_versus(convex_hull(points));
    return out;
  }
  Vec3 normal{0, 0, 0};
  out.origin.boundary_distance2 = flat_distance2(m, normal);
  out.origin.inside = sgn(out.origin.boundary_distance2) == 0;
  if (out.origin.inside && m.dimension == 2) out.origin.nearest_normals.push_back(normal);
  return out;
}

bool set_contains(const ConvexSet& s, const Vec3& x) {
  const std::vector<Vec3> v = s.vertices();
  switch (s.dimension()) {
    case 0:
      return x == v[0];
    case 1: {
      const Vec3 e = v[1] - v[0], d = x - v[0];
      return is_zero(cross(e, d)) && dot(e, d) >= 0 && dot(e, d) <= norm2(e);
    }
    case 2: {
      if (dot(s.normal(), x) != s.plane_offset()) return false;
      for (std::size_t i = 0; i < v.size(); ++i)
        if (dot(cross(v[(i + 1) % v.size()] - v[i], x - v[i]), s.normal()) < 0) return false;
      return true;
    }
    default:
      return contains(s.polyhedron(), x);
  }
}

std::string check_set_queries(const ConvexSet& a, const ConvexSet& b) {
  return check_set_queries(a, b, set_proximity_oracle(a, b));
}

std::string check_set_queries(const ConvexSet& a, const ConvexSet& b, const SetProximityOracle& oracle) {
  const Membership in_a = [&a](const Vec3& x) { return set_contains(a, x); };
  const Membership in_b = [&b](const Vec3& x) { return set_contains(b, x); };
  std::string failure = check_distance_by(in_a, in_b, squared_distance(a, b), oracle.origin);
  if (!failure.empty()) return "squared_distance: " + failure;
  if (intersects(a, b) != oracle.origin.inside) return "intersects disagrees";
  const PenetrationResult p = penetration(a, b);
  if (oracle.dimension < 3) return check_flat_penetration(in_a, in_b, p, oracle);
  failure = check_penetration_by(in_a, in_b, p, oracle.origin);
  return failure.empty() ? "" : "penetration: " + failure;
}

RandomSetPairCheck check_random_set_pair(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const int da = static_cast<int>(seed % 4);
  const int db = static_cast<int>((seed / 4) % 4);
  const ConvexSet a = random_set(rng, da, Vec3{0, 0, 0});
  const ConvexSet b0 = random_set(rng, db, Vec3{0, 0, 0});
  // M0 = A + (-B0); moving B0 by t gives M = M0 - t, so the origin is in M iff
  // t is in M0. c (the mean of the differences) is in M0 and p (their
  // lexicographic maximum) is a vertex of it: t = (c + p) / 2 is in M0, t = p
  // on its boundary, t = 2p - c outside it (else the vertex p would be the
  // midpoint of two points of M0), unless M0 is a single point.
  const std::vector<Vec3> d = differences(a, b0);
  Vec3 c{0, 0, 0};
  for (const Vec3& x : d) c += x;
  c = Rational(1, static_cast<long>(d.size())) * c;
  const Vec3 p = *std::max_element(d.begin(), d.end());
  const int kind = static_cast<int>(rng() % 3);
  const Vec3 t = kind == 0 ? Rational(1, 2) * (c + p) : kind == 1 ? p : Rational(2) * p - c;
  const ConvexSet b = b0.translated(t);
  RandomSetPairCheck out;
  out.description = "dimensions " + std::to_string(da) + " and " + std::to_string(db) + ", B moved by " + to_text(t) +
                    (kind == 0 ? " (overlapping)" : kind == 1 ? " (touching)" : " (apart)");
  const SetProximityOracle oracle = set_proximity_oracle(a, b);
  out.intersect = oracle.origin.inside;
  out.touching = out.intersect && sgn(oracle.origin.boundary_distance2) == 0;
  if (out.intersect != (kind != 2 || is_zero(p - c))) {
    out.failure = "the oracle contradicts the construction (inside)";
  } else if (kind == 1 && !out.touching) {
    out.failure = "the oracle contradicts the construction (touching)";
  } else {
    out.failure = check_set_queries(a, b, oracle);
  }
  return out;
}

}  // namespace cvms::test
