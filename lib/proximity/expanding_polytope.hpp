// SPDX-License-Identifier: MIT
// The polytope P of the exact EPA (epa.cpp): a triangulated convex polytope
// whose vertices are points of M = A + (-B), each kept with the pair of
// vertices (of A and of B) it is the difference of, grown one point at a time
// by the beneath-beyond step (expanding_polytope.cpp has the argument).
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

#include "approx.hpp"
#include "cvms/mesh.hpp"
#include "cvms/vec.hpp"

namespace cvms::detail {

/// A vertex of P: a - b for vertex_a of A and vertex_b of B; also as the
/// integer vector scaled / scale (scale > 0, the lcm of the denominators),
/// so that planes are computed in integers.
struct PolytopePoint {
  VertexId vertex_a, vertex_b;
  Vec3 c;
  ApproxVec3 approx;
  std::array<mpz_class, 3> scaled;
  mpz_class scale;
};

/// The point a - b with its approximation and scaled form.
PolytopePoint polytope_point(VertexId vertex_a, VertexId vertex_b, Vec3 c);

/// A face's exact plane: an integer outward normal (a positive multiple of
/// cross(c1 - c0, c2 - c0)), the plane <normal, x> = offset / offset_scale,
/// and its squared distance from the origin, distance_num / distance_den,
/// kept unreduced (compared by products).
struct FacePlane {
  Vec3 normal;
  ApproxVec3 normal_approx;
  mpz_class offset;
  mpz_class offset_scale;  ///< > 0
  mpz_class distance_num;
  mpz_class distance_den;  ///< > 0
};

/// The sign of a's squared distance minus b's.
int compare_distances(const FacePlane& a, const FacePlane& b);

/// A triangle of P's boundary, counterclockwise seen from outside, with
/// double bounds on its plane's squared distance from the origin (from the
/// points' approximations) and, once asked for (ExpandingPolytope::plane),
/// its exact plane, kept apart so that the faces P discards cost no
/// rational arithmetic.
struct PolytopeFace {
  std::array<std::uint32_t, 3> v;
  /// cross(c1 - c0, c2 - c0) and its product with c0, from the points'
  /// approximations with running error bounds: the filter of sees().
  ApproxVec3 normal_filter;
  Approx offset_filter;
  double distance_low = 0.0;       ///< <= the squared distance
  double distance_high = 0.0;      ///< >= it (may be infinite or NaN: no bound)
  std::uint32_t plane = no_plane;  ///< index of the exact plane, or no_plane
  bool verified = false;           ///< the plane is known to be a facet plane of M
  static constexpr std::uint32_t no_plane = 0xffffffffu;
};

class ExpandingPolytope {
 public:
  /// The tetrahedron on four affinely independent points.
  explicit ExpandingPolytope(std::array<PolytopePoint, 4> points);

  [[nodiscard]] const std::deque<PolytopePoint>& points() const noexcept { return points_; }
  [[nodiscard]] std::vector<PolytopeFace>& faces() noexcept { return faces_; }
  [[nodiscard]] const std::vector<PolytopeFace>& faces() const noexcept { return faces_; }

  /// P := conv(P + {x}); false (and P unchanged) if x is beyond no face of
  /// P, i.e. in P. \pre P + {x} is inside M (x a point of M).
  bool add(PolytopePoint x);

  /// Whether x is strictly beyond f's plane (exact: a filter on the face's
  /// approximate plane, then the integer plane).
  bool sees(PolytopeFace& f, const PolytopePoint& x);

  /// f's exact plane, computed on the first call.
  const FacePlane& plane(PolytopeFace& f);
  /// f's exact plane. \pre plane(f) was called.
  [[nodiscard]] const FacePlane& plane(const PolytopeFace& f) const { return planes_[f.plane]; }

 private:
  void add_face(std::uint32_t i, std::uint32_t j, std::uint32_t k);

  std::deque<PolytopePoint> points_;  // a deque: points never move
  std::vector<PolytopeFace> faces_;
  std::deque<FacePlane> planes_;  // a deque: planes never move
  // add()'s scratch, kept so that its storage is reused.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> visible_edges_;
  std::vector<char> visible_;
};

}  // namespace cvms::detail
