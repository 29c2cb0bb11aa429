// SPDX-License-Identifier: MIT
// The half-space systems of cvms_halfspace_bench, shared by its exact rows
// (halfspace_bench.cpp) and its qhull rows (halfspace_peers.cpp), so that
// both intersect the same rows:
//  - sphere(k): the facet planes of Sphere_k (to_halfspaces, primitive
//    integer rows; 20·4^(k−1) rows), none redundant;
//  - redundant(n): the facet planes of the hull of n seeded random points
//    in a ball, plus as many redundant rows u·x <= h(u) + s for seeded
//    random integer directions u (h the exact support value, found by the
//    walk) and slack s in 0..4 (s == 0 touches the set: weakly redundant).
// Each comes with an interior point, which qhull needs and from_halfspaces
// finds itself (its timed rows include that).
#pragma once

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/halfspaces.hpp"
#include "cvms/proximity.hpp"
#include "cvms/shapes.hpp"

namespace cvms_bench {

struct HalfspaceOperands {
  std::vector<cvms::HalfspaceRow> rows;
  cvms::Vec3 interior;  ///< a point strictly inside every row
};

inline HalfspaceOperands sphere_rows(int k) {
  const cvms::ConvexSet s(cvms::shapes::geodesic_sphere(k));
  return {cvms::to_halfspaces(s).inequalities, cvms::Vec3{0, 0, 0}};
}

// The hull of n seeded random points in the ball of radius 1000.
inline cvms::ConvexPolyhedron ball_hull(std::uint64_t seed, int n) {
  std::vector<cvms::Vec3> points;
  for (const cvms::Vec3& p : cvms::shapes::random_points(seed, 2 * n)) {
    if (points.size() < static_cast<std::size_t>(n) && dot(p, p) <= 1000000) points.push_back(p);
  }
  return cvms::convex_hull(points);
}

// The centroid of the vertices: strictly inside a full-dimensional hull.
inline cvms::Vec3 vertex_centroid(const cvms::ConvexPolyhedron& p) {
  cvms::Vec3 sum{0, 0, 0};
  for (const cvms::Vec3& v : p.mesh().positions()) sum = sum + v;
  return cvms::Rational(1, static_cast<long>(p.num_vertices())) * sum;
}

inline HalfspaceOperands redundant_rows(int n) {
  const cvms::ConvexPolyhedron p = ball_hull(77, n);
  HalfspaceOperands out{cvms::to_halfspaces(cvms::ConvexSet(p)).inequalities, vertex_centroid(p)};
  std::mt19937_64 rng(78);
  std::uniform_int_distribution<int> coordinate(-20, 20), slack(0, 4);
  const std::size_t facets = out.rows.size();
  cvms::VertexId start(0);
  while (out.rows.size() < 2 * facets) {
    const cvms::Vec3 u{coordinate(rng), coordinate(rng), coordinate(rng)};
    if (is_zero(u)) continue;
    const cvms::SupportResult h = cvms::support(p, u, start);
    start = h.vertex;
    out.rows.push_back({u, h.value + slack(rng)});
  }
  std::shuffle(out.rows.begin(), out.rows.end(), rng);
  return out;
}

}  // namespace cvms_bench
