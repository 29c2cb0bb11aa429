// SPDX-License-Identifier: MIT
// The exact EPA: the nearest facet of M = A + (-B) to the origin, on support
// points of M (w = a - b, a maximising <x, n> on A and b minimising it on B,
// two warm-started walks), without building M. The origin is in M (the GJK
// found it); the claim of penetration_by_sum.cpp (the distance from a point
// of a convex polytope to its boundary is the distance to its nearest facet
// plane) is used for M and for P below.
//
// Start. The GJK's final simplex S has the origin in its relative interior.
// While S has fewer than 4 points, take a nonzero n orthogonal to aff(S)
// and the support points of M in n and -n: if one of them is strictly off
// the plane <x, n> = <s_0, n>, it is off aff(S) and joins S; if neither is,
// M lies in that plane: M is flat and has no facets (the caller's business).
// So P = conv(S), a tetrahedron, satisfies the invariant:
//   P is a convex polytope of dimension 3, P is inside M, 0 is in P, and
//   every vertex of P is a support point a - b of M.
//
// Loop. Every face G of P (a triangle, plane <n_G, x> = c_G, c_G >= 0
// because 0 is in P) has squared distance c_G^2 / |n_G|^2 from the origin,
// compared exactly. Let d be the least. If some face at d is not verified,
// take the support point w of M in n_G: <w, n_G> = h_M(n_G) >= c_G (G's
// vertices are in M). If equal, G's plane supports M and touches it in the
// triangle G, a 2-dimensional set: it is a facet plane of M, and G is
// "verified". Otherwise w is strictly beyond G's plane, so not in P, and
// P := conv(P + {w}) (expanding_polytope.cpp) keeps the invariant. A
// verified face stays a face for ever: no point of M is beyond its plane.
// Each expansion adds a vertex of M not yet in P and M has finitely many,
// so the loop ends, with every face at distance d verified.
//
// Why d is the depth. Some face G at d lies in a facet plane of M, so the
// distance from 0 to the boundary of M is at most d. Conversely, P's
// distance to its boundary is d (the claim, for P), so the open ball B of
// radius d about 0 is in P, hence in M: M's distance is at least d.
//
// Why the tied facets are exactly the faces at d. Every face at d is in a
// facet plane of M at distance d (verified). Conversely let F be a facet of
// M at distance d, with unit outward normal u.
//  - d > 0: its foot point p = d u is in the closed ball of radius d, which
//    is in P (P is closed), and on the boundary of M, so p is not interior
//    to P (P is inside M): p lies on a face G of P, <n_G, p> = c_G. Then
//    d <= c_G / |n_G| = <n_G, p> / |n_G| <= |p| = d, so Cauchy-Schwarz is an
//    equality: n_G has the direction of p, i.e. of u, and G is at d.
//  - d = 0: the origin is on the boundary of M, hence of P. The tangent
//    cone T_P of P at 0 is the intersection of the half-spaces of P's faces
//    through 0, all verified: facet half-spaces of M through 0, each
//    holding T_M, so T_P contains T_M; and P inside M gives T_P inside T_M.
//    So T_P = T_M, a solid cone whose facets are M's facets through 0; an
//    intersection of some of those half-spaces equal to it uses each of
//    them (none is redundant), so each is the plane of a face of P at 0.
// So the tied facets of M are the distinct directions of P's faces at d,
// and the tie rule (the smallest primitive normal, penetration.cpp) reads
// them off P; the plane offset of the chosen direction N is <N, x> for any
// vertex x of such a face.
//
// The witnesses. Let N be the chosen direction and q = offset / |N|^2 N the
// translation. If d > 0, q is the foot point of the facet of direction N,
// on a face of P with that direction (above); if d = 0, q = 0 is in P and on
// the plane, and P's intersection with a plane supporting it is the union of
// its faces on that plane. Either way q is in a triangle of P on N's plane:
// with its barycentric weights l_i (exact), a = sum l_i a_i is in A, b =
// sum l_i b_i is in B, and a - b = q.
//
// Warm start. Nothing above needs P to grow by the loop's own support
// points: any point of M keeps the invariant. So before the loop, the
// support points a floating-point EPA ends with (double_epa.cpp, on the
// operands' approximations from the same tetrahedron) are inserted exactly,
// each a pair of vertices of A and B, hence a point of M whatever rounding
// did. When the guess is good the loop then only verifies the nearest faces
// (one exact support query each), instead of growing P one exact step at a
// time; when not, it goes on growing. The answer is the same either way:
// the depth, the tied facets and the tie rule depend on M only, and the
// witnesses on the triangle of P the chosen facet's foot point falls in,
// which, like the triangulation of P, may differ from a cold start.
//
// Exactness and cost. Signs are filtered predicates (orient3d against the
// face's vertices for "beyond", filtered on the face's approximate plane,
// expanding_polytope.cpp); the planes and squared distances are exact
// (scaled integers, expanding_polytope.cpp), since they are values the loop
// compares, but computed only for the faces whose double bounds on the
// squared distance (error_bounds.hpp, quotient_bounds) cannot rule them out
// of the nearest (nearest_faces). Coplanar faces of a verified plane are
// marked with it, so one support query verifies a facet however P
// triangulates it. Each walk starts at the vertices of the face it queries
// from, a short climb when P is already close to M there.
#include "epa.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "double_epa.hpp"
#include "expanding_polytope.hpp"
#include "filtered_predicates.hpp"
#include "nearest_on_simplex.hpp"

namespace cvms::detail {
namespace {

// The point a - b of M for vertex a of A and b of B.
PolytopePoint point_of(const SupportOperand& a, const SupportOperand& b, VertexId va, VertexId vb) {
  Vec3 c;
  subtract_positions(c, a, va, b, vb);
  return polytope_point(va, vb, std::move(c));
}

// The support point of M in direction n, the walks started at `from`'s pair.
PolytopePoint support_point(const SupportOperand& a, const SupportOperand& b, const Vec3& n,
                            const PolytopePoint& from) {
  const ApproxVec3 approx = ApproxVec3::of(n);
  const Vec3Ref u{n, approx};
  const VertexId va = a.support(u, Sign::positive, from.vertex_a);
  const VertexId vb = b.support(u, Sign::negative, from.vertex_b);
  return point_of(a, b, va, vb);
}

// A nonzero normal of aff(s) (1 to 3 affinely independent points).
Vec3 normal_of(const std::vector<PolytopePoint>& s) {
  if (s.size() == 1) return Vec3{1, 0, 0};
  const Vec3 d = s[1].c - s[0].c;
  if (s.size() == 3) return cross(d, s[2].c - s[0].c);
  const Vec3 n = cross(d, Vec3{1, 0, 0});
  return is_zero(n) ? cross(d, Vec3{0, 1, 0}) : n;
}

// Adds a support point of M off aff(s); false iff M lies in a plane.
bool extend(const SupportOperand& a, const SupportOperand& b, std::vector<PolytopePoint>& s) {
  const Vec3 n = normal_of(s);
  for (const Vec3& u : {n, -n}) {
    PolytopePoint w = support_point(a, b, u, s.front());
    const ApproxVec3 approx = ApproxVec3::of(u);
    if (compare_dot({w.c, w.approx}, {s.front().c, s.front().approx}, {u, approx}) == Sign::positive) {
      s.push_back(std::move(w));
      return true;
    }
  }
  return false;
}

// The faces at the least distance. The filter keeps the faces whose lower
// bound is at most every face's upper bound (a NaN bound keeps the face);
// only those get exact planes, and exact comparisons decide among them.
std::vector<PolytopeFace*> nearest_faces(ExpandingPolytope& p) {
  double least_high = std::numeric_limits<double>::infinity();
  for (const PolytopeFace& f : p.faces()) least_high = std::min(least_high, f.distance_high);
  std::vector<PolytopeFace*> out;
  for (PolytopeFace& f : p.faces()) {
    if (f.distance_low > least_high) continue;
    const FacePlane& e = p.plane(f);
    const int order = out.empty() ? 0 : compare_distances(e, p.plane(*out.front()));
    if (order < 0) out.clear();
    if (order <= 0) out.push_back(&f);
  }
  return out;
}

PolytopeFace* first_unverified(const std::vector<PolytopeFace*>& faces) {
  for (PolytopeFace* f : faces)
    if (!f->verified) return f;
  return nullptr;
}

// f's coplanar faces: the same distance and the same outward direction.
void mark_verified(const ExpandingPolytope& p, const std::vector<PolytopeFace*>& nearest,
                   const PolytopeFace& f) {
  const Vec3Ref nf{p.plane(f).normal, p.plane(f).normal_approx};
  for (PolytopeFace* g : nearest) {
    const Vec3Ref ng{p.plane(*g).normal, p.plane(*g).normal_approx};
    if (!g->verified && sign_dot(nf, ng) == Sign::positive && is_parallel(nf, ng)) g->verified = true;
  }
}

// The barycentric weights of q = t n (the foot point of f's plane, n its
// normal) in f's triangle c_0 c_1 c_2, or nothing if q is outside it. The
// weight of c_i is proportional to <cross(c_j - q, c_k - q), n> = <cross(c_j,
// c_k), n> (the terms with q vanish: det(c, q, n) = 0 as q is parallel to n),
// and with c = C / D (PolytopePoint::scaled) that is det(C_j, C_k, n) /
// (D_j D_k): times D_0 D_1 D_2 > 0, the integer det(C_j, C_k, n) D_i.
std::optional<std::array<mpz_class, 3>> foot_weights(const ExpandingPolytope& p, const PolytopeFace& f) {
  const Vec3& n = p.plane(f).normal;
  std::array<mpz_class, 3> w;
  for (int i = 0; i < 3; ++i) {
    const PolytopePoint& u = p.points()[f.v[(i + 1) % 3]];
    const PolytopePoint& v = p.points()[f.v[(i + 2) % 3]];
    const auto& x = u.scaled;
    const auto& y = v.scaled;
    w[i] = (x[1] * y[2] - x[2] * y[1]) * n.x.get_num() + (x[2] * y[0] - x[0] * y[2]) * n.y.get_num() +
           (x[0] * y[1] - x[1] * y[0]) * n.z.get_num();
    if (sgn(w[i]) < 0) return std::nullopt;
    w[i] *= p.points()[f.v[i]].scale;
  }
  return w;
}

// The witnesses of the contact: q = offset / |N|^2 N, the translation, is a
// point of P on the chosen plane (the header), so in one of P's triangles
// on it; with its weights l_i, sum l_i a_i is in A, sum l_i b_i in B, and
// their difference is q.
void set_witnesses(const SupportOperand& a, const SupportOperand& b, const ExpandingPolytope& p,
                   const std::vector<PolytopeFace*>& nearest, NearestFacet& out) {
  const ApproxVec3 approx = ApproxVec3::of(out.direction);
  const Vec3Ref n{out.direction, approx};
  for (const PolytopeFace* f : nearest) {
    const Vec3Ref fn{p.plane(*f).normal, p.plane(*f).normal_approx};
    if (sign_dot(n, fn) != Sign::positive || !is_parallel(n, fn)) continue;
    const std::optional<std::array<mpz_class, 3>> w = foot_weights(p, *f);
    if (!w) continue;
    std::array<std::optional<Vec3>, 6> moved;  // positions when the operands are moved
    const Vec3* pa[3];
    const Vec3* pb[3];
    for (int i = 0; i < 3; ++i) {
      pa[i] = &a.position_view(p.points()[f->v[i]].vertex_a, moved[i]);
      pb[i] = &b.position_view(p.points()[f->v[i]].vertex_b, moved[3 + i]);
    }
    const mpz_class total = (*w)[0] + (*w)[1] + (*w)[2];
    out.witness_a = weighted_sum(pa, w->data(), total, 3);
    out.witness_b = weighted_sum(pb, w->data(), total, 3);
    return;
  }
}

// Whether f's outward normal has the direction of one of `seen`'s.
bool same_direction_as_any(const ExpandingPolytope& p, const std::vector<const PolytopeFace*>& seen,
                           const PolytopeFace& f) {
  const Vec3Ref nf{p.plane(f).normal, p.plane(f).normal_approx};
  for (const PolytopeFace* g : seen) {
    const Vec3Ref ng{p.plane(*g).normal, p.plane(*g).normal_approx};
    if (sign_dot(nf, ng) == Sign::positive && is_parallel(nf, ng)) return true;
  }
  return false;
}

// The tie rule on the (verified) faces at the least distance. The triangles
// of one facet share its primitive normal, so it is reduced (gcds) once per
// direction.
NearestFacet smallest_nearest(const ExpandingPolytope& p, const std::vector<PolytopeFace*>& nearest) {
  const PolytopeFace* best = nullptr;
  Vec3 best_direction;
  std::vector<const PolytopeFace*> seen;
  for (const PolytopeFace* f : nearest) {
    if (same_direction_as_any(p, seen, *f)) continue;
    seen.push_back(f);
    Vec3 n = primitive_direction(p.plane(*f).normal);
    if (best == nullptr || n < best_direction) {
      best = f;
      best_direction = std::move(n);
    }
  }
  NearestFacet out{std::move(best_direction), {}, {}, {}};
  out.offset = dot(out.direction, p.points()[best->v[0]].c);
  return out;
}

// The support points a floating-point EPA ends with, inserted exactly
// (those in P already are skipped): each is a point of M, so P keeps the
// invariant, and the loop below then mostly verifies.
void warm_start(const SupportOperand& a, const SupportOperand& b, const std::vector<VertexPair>& guess,
                ExpandingPolytope& p) {
  for (const auto& [va, vb] : guess) p.add(point_of(a, b, va, vb));
}

}  // namespace

std::optional<NearestFacet> epa_nearest_facet(const SupportOperand& a, const SupportOperand& b,
                                              const GjkOutcome& gjk) {
  return epa_nearest_facet_from(a, b, gjk, nullptr);
}

std::optional<NearestFacet> epa_nearest_facet_from(const SupportOperand& a, const SupportOperand& b,
                                                   const GjkOutcome& gjk, const std::vector<VertexPair>* guess) {
  std::vector<PolytopePoint> s;
  for (int i = 0; i < gjk.size; ++i)
    s.push_back(polytope_point(gjk.simplex[i].vertex_a, gjk.simplex[i].vertex_b, gjk.simplex[i].c));
  while (s.size() < 4)
    if (!extend(a, b, s)) return std::nullopt;
  ExpandingPolytope p({std::move(s[0]), std::move(s[1]), std::move(s[2]), std::move(s[3])});
  if (guess != nullptr) {
    warm_start(a, b, *guess, p);
  } else {
    std::array<VertexPair, 4> start;
    for (std::uint32_t i = 0; i < 4; ++i) start[i] = {p.points()[i].vertex_a, p.points()[i].vertex_b};
    warm_start(a, b, double_epa(a, b, start), p);
  }
  for (;;) {
    const std::vector<PolytopeFace*> nearest = nearest_faces(p);
    PolytopeFace* f = first_unverified(nearest);
    if (f == nullptr) {
      NearestFacet out = smallest_nearest(p, nearest);
      set_witnesses(a, b, p, nearest, out);
      return out;
    }
    PolytopePoint w = support_point(a, b, p.plane(*f).normal, p.points()[f->v[0]]);
    if (p.sees(*f, w))
      p.add(std::move(w));
    else
      mark_verified(p, nearest, *f);
  }
}

}  // namespace cvms::detail
