// SPDX-License-Identifier: MIT
// penetration(): the exact minimum translation distance, first version on
// the whole sum M = A + (-B) (CVMS), then a scan of its facets.
//
// Claim: for a convex polytope M = {x : <n_f, x> <= c_f for all facets f}
// containing the origin, the distance from the origin to the boundary of M
// is min_f c_f / |n_f| (the distance to the nearest facet plane).
// Proof. (<=) Let f minimise c_f / |n_f| and p = c_f / |n_f|^2 n_f the
// projection of the origin onto f's plane; |p| = c_f / |n_f|. The segment
// from 0 to p stays in M: for any facet g, <n_g, t p> = t c_f <n_g, n_f> /
// |n_f|^2 <= t (c_f / |n_f|) |n_g| <= t c_g for t in [0, 1] (Cauchy-Schwarz,
// then minimality of f; for <n_g, n_f> <= 0 the left side is <= 0 <= c_g).
// So p is in M and on f's plane, hence on the boundary: the distance is at
// most |p|. (>=) Every boundary point q lies on some facet g, <n_g, q> = c_g,
// so |q| >= c_g / |n_g| >= min_f c_f / |n_f| (Cauchy-Schwarz). []
// The squared depth is therefore min_f c_f^2 / |n_f|^2, compared exactly
// (c_f^2 |n_g|^2 against c_g^2 |n_f|^2, all rational); 0 iff some c_f is 0,
// i.e. the operands only touch. The facet achieving it gives the direction:
// translating B by t turns M into M - t, which no longer has the origin in
// its interior iff t is outside the interior of M, and p is the shortest such
// t. Ties go to the smallest normal in Vec3's lexicographic order, which is
// independent of how the sum numbers its facets.
//
// The witnesses: after moving B by p the operands touch, and the exact GJK
// of A against the moved B returns a common point x; then x is in A,
// x - p is in B, and their difference is p.
#include <optional>

#include "cvms/minkowski.hpp"
#include "cvms/proximity.hpp"
#include "gjk.hpp"
#include "placed_support.hpp"
#include "reflection.hpp"

namespace cvms {
namespace {

// The facet of m nearest to the origin (assumed inside), by the exact
// comparison of c_f^2 / |n_f|^2; ties to the smallest normal.
FaceId nearest_facet(const ConvexPolyhedron& m) {
  FaceId best;
  Rational best_num;  // c^2 of the best
  Rational best_den;  // |n|^2 of the best
  for (FaceId f : m.mesh().faces()) {
    const Rational& c = m.plane_offset(f);
    const Vec3& n = m.normal(f);
    const Rational num = c * c;
    const Rational den = dot(n, n);
    if (best.is_valid()) {
      const int order = cmp(num * best_den, best_num * den);
      if (order > 0 || (order == 0 && !(n < m.normal(best)))) continue;
    }
    best = f;
    best_num = num;
    best_den = den;
  }
  return best;
}

}  // namespace

Vec3 PenetrationResult::translation() const {
  if (is_zero(direction)) return Vec3{0, 0, 0};
  return (offset / dot(direction, direction)) * direction;
}

PenetrationResult penetration(const PlacedPolyhedron& a, const PlacedPolyhedron& b) {
  detail::check_operands(a, b, "penetration");
  PenetrationResult r;
  const DistanceResult apart = squared_distance(a, b);
  r.intersect = apart.intersect;
  r.direction = Vec3{0, 0, 0};
  if (!r.intersect) {
    r.witness_a = apart.witness_a;
    r.witness_b = apart.witness_b;
    return r;
  }
  // The moved operands, built only when a placement asks for it.
  std::optional<ConvexPolyhedron> moved_a;
  std::optional<ConvexPolyhedron> moved_b;
  const ConvexPolyhedron& pa = a.is_placed() ? moved_a.emplace(a.materialized()) : a.polyhedron();
  const ConvexPolyhedron& pb = b.is_placed() ? moved_b.emplace(b.materialized()) : b.polyhedron();
  const ConvexPolyhedron m = minkowski_sum(pa, detail::reflection(pb)).polyhedron;
  const FaceId f = nearest_facet(m);
  r.direction = m.normal(f);
  r.offset = m.plane_offset(f);
  r.squared_depth = r.offset * r.offset / dot(r.direction, r.direction);
  const Vec3 t = r.translation();
  const DistanceResult contact = detail::distance_with_offset(pa, pb, &t);
  r.witness_a = contact.witness_a;
  r.witness_b = contact.witness_b - t;
  return r;
}

}  // namespace cvms
