// SPDX-License-Identifier: MIT
// The ray test of ray_parity.hpp.
//
// Directions: d_k = R (1, t, t^2) for t = 2, 3, 4, ..., R a fixed
// invertible integer matrix. The points (1, t, t^2) lie on the moment
// curve, of which a plane through the origin holds at most two; R keeps
// that. R = M + s N e_a e_0^T, M below, turns the first directions to within
// a few degrees of s e_a, the axis direction along which p is nearest to
// leaving the tree's box: a ray that leaves the box soon meets few boxes
// (through a thin plate, say, instead of along it). R is invertible:
// det R = det M (1 + s N (M^-1)_{0a}), and (M^-1)_{0.} = (11, 5, -8) / 113
// makes the bracket 1 + s N k / 113 with |k| <= 11, not zero for N = 1000.
// The answer is the parity whatever the direction; the choice only saves
// work. A ray from p meets a given edge (not through p) only for directions
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

#include <cmath>
#include <limits>
#include <utility>

#include "cvms/error.hpp"
#include "cvms/predicates.hpp"

namespace cvms::detail {

namespace {

// The axis (0, 1, 2) and sign (+1, -1) along which p is nearest to leaving
// `box` (in doubles: only a preference); {-1, 0} for no box.
struct Exit {
  int axis = -1;
  int sign = 0;
};

Exit nearest_exit(const Box* box, const Vec3& p) {
  Exit best;
  if (box == nullptr) return best;
  double least = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const double x = to_double_nearest(p[k]);
    for (const auto& [gap, sign] : {std::pair{box->hi[i] - x, 1}, std::pair{x - box->lo[i], -1}}) {
      if (gap < least) {
        least = gap;
        best = {k, sign};
      }
    }
  }
  return best;
}

Vec3 direction(int k, Exit exit) {
  constexpr int turn = 1000;  // N of the file comment
  const Rational t = k + 2;
  const Rational t2 = t * t;
  // M = [[7, 3, 1], [2, -5, 1], [-3, 1, 2]], det = -113.
  Vec3 d{7 + 3 * t + t2, 2 - 5 * t + t2, -3 + t + 2 * t2};
  if (exit.axis == 0) d.x += exit.sign * turn;
  if (exit.axis == 1) d.y += exit.sign * turn;
  if (exit.axis == 2) d.z += exit.sign * turn;
  return d;
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
  const Exit exit = nearest_exit(tree.bounds(), p);
  for (int k = 0;; ++k) {
    const Vec3 d = direction(k, exit);
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
