// SPDX-License-Identifier: MIT
// penetration_by_sum(): the exact minimum translation distance on the whole
// sum M = A + (-B) (CVMS), then a scan of its facets: the reference of the
// EPA that penetration() runs (epa.cpp), which uses the
// claim below for M and for its inner polytopes.
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
// The witnesses: after moving B by the translation p the operands touch,
// and the exact GJK of A against the moved B returns a common point x; then
// x is in A, x - p is in B, and their difference is p.
//
// Convex sets of any dimension: M = A + (-B) from the sets layer. If M is
// solid the claim applies unchanged. If M is flat (dimension <= 2), its
// interior in space is empty, so every point of M is a boundary point: when
// the origin is in M the distance to the boundary is 0, and any translation
// of B off M's affine hull, however small, separates the operands. There is
// no depth to find; the direction reported is M's canonical plane normal for
// a polygon (one of the two that leave its plane) and zero for a segment or a
// point (a whole circle or sphere of directions would do).
#include "penetration_by_sum.hpp"

#include <optional>

#include "cvms/minkowski.hpp"
#include "cvms/set_sum.hpp"
#include "penetration_result.hpp"
#include "query_operands.hpp"
#include "reflection.hpp"

namespace cvms::detail {
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

// The depth from a solid M = A + (-B) with the origin inside.
void depth_from_sum(const ConvexPolyhedron& m, const SupportOperand& a, const SupportOperand& b,
                    PenetrationResult& r) {
  const FaceId f = nearest_facet(m);
  set_depth(r, m.normal(f), m.plane_offset(f));
  const Vec3 t = r.translation();
  const DistanceResult contact = distance_with_offset(a, b, &t);
  r.witness_a = contact.witness_a;
  r.witness_b = contact.witness_b - t;
}

ConvexSet reflected(const ConvexSet& s) {
  return s.dimension() == 3 ? ConvexSet(reflection(s.polyhedron())) : s.reflected();
}

}  // namespace

PenetrationResult penetration_by_sum(const PlacedPolyhedron& a, const PlacedPolyhedron& b) {
  check_operands(a, b, "penetration");
  PenetrationResult r = penetration_from_distance(squared_distance(a, b));
  if (!r.intersect) return r;
  // The moved operands, built only when a placement asks for it.
  std::optional<ConvexPolyhedron> moved_a;
  std::optional<ConvexPolyhedron> moved_b;
  const ConvexPolyhedron& pa = a.is_placed() ? moved_a.emplace(a.materialized()) : a.polyhedron();
  const ConvexPolyhedron& pb = b.is_placed() ? moved_b.emplace(b.materialized()) : b.polyhedron();
  const ConvexPolyhedron m = minkowski_sum(pa, reflection(pb)).polyhedron;
  const PlacedPolyhedron unmoved_a(pa);
  const PlacedPolyhedron unmoved_b(pb);
  depth_from_sum(m, SupportOperand(unmoved_a), SupportOperand(unmoved_b), r);
  return r;
}

PenetrationResult penetration_by_sum(const ConvexSet& a, const ConvexSet& b) {
  check_operands(a, b, "penetration");
  const SupportOperand sa(a);
  const SupportOperand sb(b);
  PenetrationResult r = penetration_from_distance(distance_with_offset(sa, sb, nullptr));
  if (!r.intersect) return r;
  const ConvexSet m = minkowski_sum(a, reflected(b));
  if (m.dimension() == 3)
    depth_from_sum(m.polyhedron(), sa, sb, r);
  else if (m.dimension() == 2)
    r.direction = m.normal();  // flat M: depth and offset stay 0 (the file comment)
  return r;
}

}  // namespace cvms::detail
