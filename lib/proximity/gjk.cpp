// SPDX-License-Identifier: MIT
// Exact GJK (Gilbert, Johnson and Keerthi 1988) on support walks, in exact
// rationals: the point of C = A + (-B) nearest to the origin. Nothing below
// uses more of A and B than support points, so they may be convex sets of
// any dimension (SupportOperand): then C is too, and every step holds as
// written (the affine independence argument does not need C to be solid).
//
// The loop. Keep a set W of points of C (each a_i - b_j for a vertex a_i of
// A and b_j of B) and v, the point of conv(W) nearest to the origin. Take the
// support point w of C in direction -v: w = a - b with a maximising <x, -v>
// on A and b maximising <x, v> on B (two support walks, each started from the
// previous answer). For every x in C, <v, x> >= <v, w>. Then:
//  - if <v, w> >= |v|^2, every x in C has <v, x> >= |v|^2, so |x| >= |v|
//    (Cauchy-Schwarz): v is the nearest point of C, exactly;
//  - otherwise replace W by the support of the nearest point of
//    conv(W' + {w}), W' the points of W with positive weight
//    (nearest_on_simplex).
// A zero v means the origin is in C: the operands intersect.
//
// Why W' + {w} is affinely independent (nearest_on_simplex's precondition).
// v is the projection of the origin onto aff(W'), so every x in aff(W') has
// <v, x> = |v|^2; w has <v, w> < |v|^2, so w is not in aff(W'). Induction
// from the one-point start.
//
// Why the nearest point's support contains w. Every face of conv(W') has its
// nearest point at distance >= |v|; the segment from v to w holds points
// nearer than v (the derivative of |v + t (w - v)|^2 at t = 0 is
// 2 <v, w - v> < 0), so the new nearest point is not on a face without w.
//
// Termination. The squared distance |v|^2 strictly decreases at every step
// (by the previous paragraph), and each value is the distance to conv(S) for
// a subset S of the finite set {a_i - b_j}; no S can come back, so the loop
// ends after at most 2^(v_A v_B) steps, and in practice after a handful
// (the points a_i - b_j with nonzero weight are at most 4, and each support
// walk starts at the previous answer). Exactness makes this argument hold:
// there is no tolerance to tune and no "no progress" case to guess at, which
// is where the floating-point versions fail (fcl #493, #495).
//
// Warm start. Nothing above needs the loop to begin with one point: it
// needs W affinely independent with v the nearest point of conv(W) and
// every weight positive. So the loop starts from the simplex a GJK in
// doubles ends with (double_gjk.cpp) when the exact projection of the
// origin onto its affine hull has positive weights (project_inside: then
// the points are independent and v is that nearest point), else from one
// point as before. When the guess is right the first exact step proves it
// optimal (two exact support walks, one comparison); when not, the exact
// loop goes on from there. The distance is the same either way (the
// nearest point is unique); the simplex, hence the witnesses when closest
// points are not unique, is the one the loop ends with, deterministic.
//
// Intersection only (GjkGoal::intersection): stop as soon as <v, w> > 0, the
// plane {x : <v, x> = <v, w>} then separating the origin from C.
#include "gjk.hpp"

#include "double_gjk.hpp"
#include "filtered_predicates.hpp"
#include "nearest_on_simplex.hpp"

namespace cvms::detail {
namespace {

void set_point(GjkPoint& p, const SupportOperand& a, const SupportOperand& b, const Vec3* b_offset, VertexId va,
               VertexId vb) {
  p.vertex_a = va;
  p.vertex_b = vb;
  subtract_positions(p.c, a, va, b, vb);
  if (b_offset != nullptr) p.c -= *b_offset;
}

SimplexPoints points_of(const GjkOutcome& out) {
  SimplexPoints points{};
  for (int i = 0; i < out.size; ++i) points[i] = &out.simplex[i].c;
  return points;
}

// W := the support of conv(W + {w})'s nearest point, w appended last.
void add_and_reduce(GjkOutcome& out, GjkPoint w) {
  out.simplex[out.size++] = std::move(w);
  SimplexNearest n = nearest_on_simplex(points_of(out), out.size);
  int kept = 0;
  for (int i = 0; i < out.size; ++i) {
    if (!(n.support_mask & (1u << i))) continue;
    if (kept != i) out.simplex[kept] = std::move(out.simplex[i]);
    out.weight_num[kept++] = std::move(n.weight_num[i]);
  }
  out.size = kept;
  out.weight_den = std::move(n.weight_den);
  out.nearest = std::move(n.point);
  out.squared_norm = std::move(n.squared_norm);
}

void cold_start(GjkOutcome& out, const SupportOperand& a, const SupportOperand& b, const Vec3* b_offset) {
  set_point(out.simplex[0], a, b, b_offset, VertexId(0), VertexId(0));
  out.weight_num[0] = 1;
  out.weight_den = 1;
  out.size = 1;
  out.nearest = out.simplex[0].c;
  out.squared_norm = dot(out.nearest, out.nearest);
}

// The guessed simplex, if the exact projection has positive weights.
bool warm_start(GjkOutcome& out, const SupportOperand& a, const SupportOperand& b, const Vec3* b_offset,
                const GjkCandidate& guess) {
  if (guess.size < 1 || guess.size > 4) return false;
  for (int i = 0; i < guess.size; ++i) set_point(out.simplex[i], a, b, b_offset, guess.vertex_a[i], guess.vertex_b[i]);
  out.size = guess.size;
  std::optional<SimplexNearest> n = project_inside(points_of(out), guess.size);
  if (!n) return false;
  for (int i = 0; i < out.size; ++i) out.weight_num[i] = std::move(n->weight_num[i]);
  out.weight_den = std::move(n->weight_den);
  out.nearest = std::move(n->point);
  out.squared_norm = std::move(n->squared_norm);
  return true;
}

}  // namespace

GjkOutcome exact_gjk(const SupportOperand& a, const SupportOperand& b, GjkGoal goal, const Vec3* b_offset) {
  std::array<double, 3> offset{0, 0, 0};
  if (b_offset != nullptr)
    for (int i = 0; i < 3; ++i) offset[i] = (*b_offset)[i].get_d();
  return exact_gjk_from(a, b, goal, b_offset, double_gjk(a, b, offset, goal == GjkGoal::intersection));
}

GjkOutcome exact_gjk_from(const SupportOperand& a, const SupportOperand& b, GjkGoal goal, const Vec3* b_offset,
                          const GjkCandidate& guess) {
  GjkOutcome out;
  if (!warm_start(out, a, b, b_offset, guess)) cold_start(out, a, b, b_offset);
  VertexId hint_a = out.simplex[0].vertex_a;
  VertexId hint_b = out.simplex[0].vertex_b;
  while (sgn(out.squared_norm) != 0) {
    ++out.iterations;
    const ApproxVec3 v_approx = ApproxVec3::of(out.nearest);
    const Vec3Ref v{out.nearest, v_approx};
    hint_a = a.support(v, Sign::negative, hint_a);  // maximises <x, -v> on A
    hint_b = b.support(v, Sign::positive, hint_b);
    GjkPoint w;
    set_point(w, a, b, b_offset, hint_a, hint_b);
    const ApproxVec3 w_approx = ApproxVec3::of(w.c);
    const Vec3Ref wr{w.c, w_approx};
    if (goal == GjkGoal::intersection && sign_dot(v, wr) == Sign::positive) return out;
    if (compare_dot(wr, v, v) != Sign::negative) return out;  // <w, v> >= <v, v>: v is nearest
    add_and_reduce(out, std::move(w));
  }
  out.intersect = true;
  return out;
}

}  // namespace cvms::detail
