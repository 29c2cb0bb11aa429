// SPDX-License-Identifier: MIT
// The polytope P of the exact EPA (epa.cpp): a triangulated convex polytope
// whose vertices are points of M = A + (-B), each kept with the pair of
// vertices (of A and of B) it is the difference of, grown one point at a time
// by the beneath-beyond step (expanding_polytope.cpp has the argument).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "approx.hpp"
#include "cvms/mesh.hpp"
#include "cvms/vec.hpp"

namespace cvms::detail {

/// A vertex of P: a - b for vertex_a of A and vertex_b of B.
struct PolytopePoint {
  VertexId vertex_a, vertex_b;
  Vec3 c;
  ApproxVec3 approx;
};

/// A triangle of P's boundary, counterclockwise seen from outside. Its
/// plane {x : <normal, x> = offset} (normal = cross(c1 - c0, c2 - c0), not
/// normalised) and the squared distance of that plane from the origin are
/// exact once `exact` is set (ExpandingPolytope::make_exact); until then
/// only the bounds of that distance, from the points' approximations, are.
struct PolytopeFace {
  std::array<std::uint32_t, 3> v;
  double distance_low = 0.0;   ///< <= squared_distance
  double distance_high = 0.0;  ///< >= squared_distance (may be infinite or NaN: no bound)
  bool exact = false;
  bool verified = false;  ///< the plane is known to be a facet plane of M
  Vec3 normal;
  ApproxVec3 normal_approx;
  Rational offset;
  Rational squared_distance;  ///< offset^2 / |normal|^2
};

class ExpandingPolytope {
 public:
  /// The tetrahedron on four affinely independent points.
  explicit ExpandingPolytope(std::array<PolytopePoint, 4> points);

  [[nodiscard]] const std::vector<PolytopePoint>& points() const noexcept { return points_; }
  [[nodiscard]] std::vector<PolytopeFace>& faces() noexcept { return faces_; }
  [[nodiscard]] const std::vector<PolytopeFace>& faces() const noexcept { return faces_; }

  /// P := conv(P + {x}). \pre x is strictly beyond some face of P.
  void add(PolytopePoint x);

  /// Computes f's exact plane and distance, once.
  void make_exact(PolytopeFace& f) const;

 private:
  void add_face(std::uint32_t i, std::uint32_t j, std::uint32_t k);
  [[nodiscard]] bool sees(const PolytopeFace& f, const PolytopePoint& x) const;

  std::vector<PolytopePoint> points_;
  std::vector<PolytopeFace> faces_;
};

}  // namespace cvms::detail
