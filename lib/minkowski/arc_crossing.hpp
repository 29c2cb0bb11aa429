// SPDX-License-Identifier: MIT
// Where the Gaussian arcs of two edges cross: paper Eq. 9 reduced to signs of
// dot products, for the edge facets e_A + e_B of CVMS (Section 4.3, Eq. 4)
// and ESSDMS (Section 5.2, case 3, Eq. 12). Private to the library.
//
// Arc convention. For a halfedge h of a convex polyhedron with d = to(h) -
// from(h), s = n(face(h)) (the facet on its left) and t = n(face(twin(h))),
// cross(s, t) is a positive multiple of d: the Gaussian arc of the edge runs
// from s to t counterclockwise about d, on the great circle {x : <x, d> = 0},
// and x on that circle is strictly inside the arc iff det[s, x, d] > 0 and
// det[x, t, d] > 0 (paper Eq. 9 with the arc's pole d in place of
// cross(s, t)).
//
// The reduction. For a direction e not parallel to d, the great circle of
// directions perpendicular to e meets that of the arc at +-x, x = cross(e, d).
// With a x (b x c) = b<a,c> - c<a,b> and <s, d> = <t, d> = 0:
//   det[s, x, d] = -|d|^2 <s, e>,   det[x, t, d] = |d|^2 <t, e>,
// so x is strictly inside the arc iff <s, e> < 0 and <t, e> > 0, and -x iff
// <s, e> > 0 and <t, e> < 0. Nothing is constructed: the signs are dot
// products of facet normals with the other edge's direction.
//
// Two arcs, of e_A (s_A, t_A, pole d_A) and of e_B (s_B, t_B, pole d_B), meet
// at +-x with x = cross(d_A, d_B) (x = 0: parallel edges, one great circle,
// no facet). For the arc of e_B take e = d_A; for that of e_A, e = d_B and
// cross(d_B, d_A) = -x. So sigma * x (sigma = +-1) is strictly inside both
// arcs iff
//   sign<s_A, d_B> = sigma, sign<t_A, d_B> = -sigma,
//   sign<s_B, d_A> = -sigma, sign<t_B, d_A> = sigma,
// and then e_A + e_B is a facet of A + B with outward normal sigma * x. Arcs
// on one great circle have <s_A, d_B> = 0 and are rejected (overlapping arcs
// give no facet); an arc through a facet point of the other, or ending on the
// other arc, makes one of the four signs zero: a contact, not a crossing.
#pragma once

#include "filtered_predicates.hpp"
#include "polyhedron_builder.hpp"

namespace cvms::detail {

/// An arc of A: its facet points s_A, t_A and its pole d_A (see the file
/// comment), as the filtered predicates take them.
struct ArcRef {
  Vec3Ref s;
  Vec3Ref t;
  Vec3Ref pole;
};

/// The sigma for which sigma * cross(d_A, d_B) lies strictly inside the arc
/// `a` of A and the arc of halfedge hb of b (pole d_B), or zero if the arcs
/// do not cross at a point interior to both. Evaluates the four signs of the
/// file comment in its order and stops at the first that rules the crossing
/// out (B's facet points are read only if A's arc passes).
inline Sign proper_crossing(const ArcRef& a, const ConvexPolyhedron& b, HalfedgeId hb, Vec3Ref d_b) {
  const Sign sigma = sign_dot(a.s, d_b);
  if (sigma == Sign::zero) return Sign::zero;  // parallel arcs, or s_A on the great circle of the arc of B
  if (sign_dot(a.t, d_b) != -sigma) return Sign::zero;
  const Mesh& mb = b.mesh();
  if (sign_dot(normal_ref(b, mb.face(hb)), a.pole) != -sigma) return Sign::zero;
  if (sign_dot(normal_ref(b, mb.face(Mesh::twin(hb))), a.pole) != sigma) return Sign::zero;
  return sigma;
}

}  // namespace cvms::detail
