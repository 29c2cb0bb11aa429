// SPDX-License-Identifier: MIT
// The ray test of ray_parity.hpp.
//
// Directions: d_k = M (1, t, t^2) for t = 2, 3, 4, ..., M a fixed
// invertible integer matrix. The points (1, t, t^2) lie on the moment
// curve, of which a plane through the origin holds at most two; M keeps
// that. A ray from p meets a given edge (not through p) only for directions
// in the plane through p and the edge, and a given vertex only for one
// direction; it runs inside a triangle's plane only for directions in a
// plane. So each triangle rules out at most a handful of the d_k, and the
// search ends after at most a few times as many attempts as the ray meets
// triangles.
//
// Crossing test of the ray {p + s d : s > 0} with triangle (a, b, c), q =
// p + d: the line pq passes through the closed triangle iff the signs of
// orient3d(p, q, a, b), (p, q, b, c), (p, q, c, a) are not both positive and
// negative; their common nonzero sign is that of dot(n, d), n the
// triangle's normal cross(b - a, c - a) (their sum is dot(n, d)). The line
// meets the plane ahead of p iff p is strictly on the side opposite to
// that sign: orient3d(a, b, c, p) = dot(n, p - a).
#include "ray_parity.hpp"

#include "cvms/error.hpp"
#include "cvms/predicates.hpp"

namespace cvms::detail {

namespace {

Vec3 direction(int k) {
  const Rational t = k + 2;
  const Rational t2 = t * t;
  // M = [[7, 3, 1], [2, -5, 1], [-3, 1, 2]], det = -113.
  return {7 + 3 * t + t2, 2 - 5 * t + t2, -3 + t + 2 * t2};
}

enum class Hit { none, crossing, degenerate, at_start };

Hit ray_hit(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const int s1 = static_cast<int>(orient3d(p, q, a, b));
  const int s2 = static_cast<int>(orient3d(p, q, b, c));
  const int s3 = static_cast<int>(orient3d(p, q, c, a));
  if (s1 == 0 && s2 == 0 && s3 == 0) return Hit::degenerate;  // the ray lies in the triangle's plane
  const bool positive = s1 > 0 || s2 > 0 || s3 > 0;
  const bool negative = s1 < 0 || s2 < 0 || s3 < 0;
  if (positive && negative) return Hit::none;
  const int side = static_cast<int>(orient3d(a, b, c, p));
  const int toward = positive ? 1 : -1;  // sign of dot(n, d)
  if (side == 0) return Hit::at_start;   // the line meets the triangle at p itself
  if (side == toward) return Hit::none;  // the plane is behind p
  return s1 == 0 || s2 == 0 || s3 == 0 ? Hit::degenerate : Hit::crossing;
}

}  // namespace

bool odd_crossings(const TriangleTree& tree, std::span<const Vec3> points,
                   std::span<const std::array<std::uint32_t, 3>> triangles, const Vec3& p,
                   const std::function<bool(std::uint32_t)>& counts) {
  for (int k = 0;; ++k) {
    const Vec3 d = direction(k);
    const Vec3 q = p + d;
    bool odd = false;
    bool degenerate = false;
    tree.for_each_on_ray(p, d, [&](std::uint32_t t) {
      if (!counts(t)) return false;
      const auto& tri = triangles[t];
      const Hit hit = ray_hit(p, q, points[tri[0]], points[tri[1]], points[tri[2]]);
      // No direction helps then: every ray from p starts on the triangle.
      if (hit == Hit::at_start)
        throw Error(ErrorCategory::invalid_argument, "odd_crossings: the point lies on a counted triangle");
      if (hit == Hit::degenerate) degenerate = true;
      if (hit == Hit::crossing) odd = !odd;
      return degenerate;
    });
    if (!degenerate) return odd;
  }
}

}  // namespace cvms::detail
