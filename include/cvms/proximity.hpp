// SPDX-License-Identifier: MIT
/// \file
/// Exact proximity queries on convex polyhedra and on convex sets of any
/// dimension (ConvexSet: a point, a segment, a polygon or a polyhedron):
/// support, intersection test, separation distance and penetration depth. Everything is exact: inputs are
/// rational, answers are rational (the squared distance of two polytopes with
/// rational vertices is rational, and so is the squared depth), every sign
/// decision goes through the filtered predicates.
///
/// The configuration-space view: A and B intersect iff the origin lies in
/// C = A + (-B); their distance is the distance from the origin to C and the
/// penetration depth is the distance from the origin to the boundary of C.
/// Closed sets throughout: touching (a common boundary point) counts as
/// intersecting, with distance 0 and depth 0.
///
/// Operands may carry a rigid motion given in doubles (Placement): every
/// double is an exact rational, so the moved operand is the exact image
/// R P + t; distance queries apply it lazily (to the search directions and to
/// the few vertices they touch), never re-validating or copying the operand.
/// (Placements are for polyhedra; a ConvexSet operand is taken as it is.)
///
/// Overloads: each query takes two PlacedPolyhedron, two ConvexPolyhedron
/// (the same, unmoved) or two ConvexSet. A polyhedron passed where a
/// ConvexSet is expected (mixing it with a flat operand) is converted, which
/// copies it; convert once (ConvexSet(p)) to query it many times.
///
/// \code
/// cvms::ConvexPolyhedron a = cvms::shapes::cube(), b = ...;
/// cvms::DistanceResult d = cvms::squared_distance(a, b);  // exact, with witnesses
/// if (d.intersect) {
///   cvms::PenetrationResult p = cvms::penetration(a, b);  // translate B by p.translation() to separate
/// }
/// \endcode
#pragma once

#include <array>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/convex_set.hpp"
#include "cvms/vec.hpp"

namespace cvms {

/// A rigid motion x -> rotation * x + translation given in doubles, applied
/// exactly (each double is the exact binary number it is). The matrix need
/// not be exactly orthogonal (a rotation rounded to doubles never is): the
/// moved operand is the exact image under this linear map, which is what the
/// answers refer to. Row-major: rotation[row][column].
struct Placement {
  /// The linear part; the identity by default.
  std::array<std::array<double, 3>, 3> rotation{{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}};
  /// The translation; zero by default.
  std::array<double, 3> translation{0.0, 0.0, 0.0};
};

/// A convex polyhedron together with an optional placement: the operand of
/// the proximity queries. A view: it refers to the polyhedron, which must
/// outlive it. Implicitly made from a polyhedron (no motion).
class PlacedPolyhedron {
 public:
  /// p itself (no motion).
  PlacedPolyhedron(const ConvexPolyhedron& p) noexcept : polyhedron_(&p) {}  // NOLINT: implicit on purpose
  /// The image of p under `placement`, applied exactly.
  /// \throw Error(invalid_argument) if a number of the placement is NaN or infinite.
  PlacedPolyhedron(const ConvexPolyhedron& p, const Placement& placement);

  /// The unmoved polyhedron.
  [[nodiscard]] const ConvexPolyhedron& polyhedron() const noexcept { return *polyhedron_; }
  /// True iff a placement was given.
  [[nodiscard]] bool is_placed() const noexcept { return placed_; }
  /// The exact linear part (the identity when not placed).
  [[nodiscard]] const Mat3& linear() const noexcept { return linear_; }
  /// The exact transposed linear part (maps a search direction into the
  /// polyhedron's own frame).
  [[nodiscard]] const Mat3& linear_transposed() const noexcept { return transposed_; }
  /// The exact translation (zero when not placed).
  [[nodiscard]] const Vec3& translation() const noexcept { return translation_; }
  /// The moved position of vertex v: linear() * vertex(v) + translation().
  [[nodiscard]] Vec3 position(VertexId v) const;
  /// The moved polyhedron, built explicitly (ConvexPolyhedron::transformed:
  /// O(V + F) exact arithmetic; the penetration query needs it).
  /// \throw Error(invalid_argument) if the linear part is singular.
  [[nodiscard]] ConvexPolyhedron materialized() const;

 private:
  const ConvexPolyhedron* polyhedron_;
  bool placed_ = false;
  Mat3 linear_ = Mat3::identity();
  Mat3 transposed_ = Mat3::identity();
  Vec3 translation_{0, 0, 0};
};

/// The face of a polyhedron on which a linear function is maximal.
struct SupportFace {
  /// 0 (a vertex), 1 (an edge) or 2 (a facet).
  int dimension = 0;
  /// The face's vertices in increasing index order (1, 2 or the facet's).
  std::vector<VertexId> vertices;
  /// The facet when dimension is 2, else invalid.
  FaceId facet;
};

/// The answer of support(): the maximum of <x, u> over P and where it is reached.
struct SupportResult {
  /// A vertex of P that maximises <x, u> (the one the walk ends at).
  VertexId vertex;
  /// The position of that vertex (moved, for a placed operand).
  Vec3 point;
  /// The maximum value of <x, u> over P, exact.
  Rational value;
  /// The whole maximising face; filled only when asked for (else empty).
  SupportFace face;
};

/// The support of P in direction u: max over x in P of <x, u>, a maximising
/// vertex, and on request the whole maximising face. Found by hill-climbing on
/// the vertex graph from `start` (a linear function on a convex polyhedron has
/// no local maximum that is not global; see lib/proximity/support_walk.hpp),
/// not by a scan: pass the previous answer's vertex as `start` for coherent
/// queries (nearby directions) and the walk is a few steps.
/// Ties among maximising vertices are broken by the walk (deterministic for
/// the same inputs); the face, when asked, lists all of them.
/// \throw Error(invalid_argument) if P is empty (default-constructed), u is
///   zero, or start is not a vertex of P, or P's placement maps u to zero
///   (a singular linear part).
/// Complexity: O(length of the climb times the vertex degrees) filtered
/// predicates, plus O(face) when the face is asked for.
SupportResult support(const PlacedPolyhedron& p, const Vec3& u, VertexId start = VertexId(0),
                      bool want_face = false);

/// support(p, u, start, want_face) on the unmoved polyhedron (this overload
/// makes the call with a ConvexPolyhedron unambiguous).
SupportResult support(const ConvexPolyhedron& p, const Vec3& u, VertexId start = VertexId(0), bool want_face = false);

/// The support of a convex set of any dimension, as above; vertex indices
/// (SupportResult::vertex, `start`, the face's vertices) index s.vertices().
/// A polyhedron walks its mesh; a polygon walks its cycle (a linear function
/// on a convex polygon has no local maximum that is not global either), a
/// segment or a point has nothing to walk. The face, when asked, is a
/// vertex, an edge or, for a polygon orthogonal to u, the whole polygon
/// (dimension 2; SupportFace::facet is then invalid: a polygon has no facet
/// ids) or, for a polyhedron, one of its facets.
/// \throw Error(invalid_argument) if s is the empty set, u is zero or start
///   is not a vertex index of s.
/// Complexity: O(length of the climb) filtered predicates, plus O(n) to copy
/// a lower-dimensional set's n vertices with their approximations.
SupportResult support(const ConvexSet& s, const Vec3& u, VertexId start = VertexId(0), bool want_face = false);

/// True iff A and B have a common point (touching counts: closed sets).
/// Exact GJK on support walks that stops at the first separating direction
/// (see squared_distance); sign decisions only, filtered.
/// \throw Error(invalid_argument) for an empty operand.
bool intersects(const PlacedPolyhedron& a, const PlacedPolyhedron& b);

/// intersects() on the unmoved polyhedra.
bool intersects(const ConvexPolyhedron& a, const ConvexPolyhedron& b);
/// intersects() on convex sets of any dimension: the same exact GJK (it only
/// needs support points, and a point, a segment or a polygon has them).
/// \throw Error(invalid_argument) naming the operand (A or B) if one is the
///   empty set.
bool intersects(const ConvexSet& a, const ConvexSet& b);

/// The distance between two operands and where it is reached.
struct DistanceResult {
  /// min |a - b|^2 over a in A, b in B: exact; 0 iff they intersect.
  Rational squared_distance;
  /// A point of A closest to B (moved, for a placed operand).
  Vec3 witness_a;
  /// A point of B closest to A: |witness_a - witness_b|^2 == squared_distance;
  /// equal to witness_a when they intersect (a common point).
  Vec3 witness_b;
  /// True iff they intersect (squared_distance == 0; touching counts).
  bool intersect = false;
  /// Iterations of the exact GJK loop (one support query of each operand
  /// each), counted after its warm start: 0 or 1 when the floating-point
  /// guess was right.
  int iterations = 0;
};

/// The exact squared distance between A and B with witness points, by an
/// exact GJK: support walks on A and B give points of A + (-B), and the
/// nearest point to the origin of the current simplex (at most 4 such
/// points) is computed in exact rationals; the loop ends when the support
/// point proves optimality exactly. It terminates because the distance
/// strictly decreases and there are finitely many simplices (the proof is in
/// lib/proximity/gjk.cpp). Output-sensitive: it never builds A + (-B).
/// The loop starts from the simplex a floating-point GJK ends with, if an
/// exact test accepts it (else from one point): rounding changes the time,
/// never the answer. Which closest points are reported when they are not
/// unique (parallel faces) is deterministic for the same inputs and the same
/// build (the floating-point guess picks among tied answers; a build with
/// other floating-point code generation, e.g. contracted multiply-adds, may
/// pick another witness pair at the same exact distance).
/// \throw Error(invalid_argument) for an empty operand.
DistanceResult squared_distance(const PlacedPolyhedron& a, const PlacedPolyhedron& b);

/// squared_distance() on the unmoved polyhedra.
DistanceResult squared_distance(const ConvexPolyhedron& a, const ConvexPolyhedron& b);
/// squared_distance() on convex sets of any dimension (the same exact GJK).
/// \throw Error(invalid_argument) naming the operand (A or B) if one is the
///   empty set.
DistanceResult squared_distance(const ConvexSet& a, const ConvexSet& b);

/// The penetration of two operands: how far B must be translated to separate.
struct PenetrationResult {
  /// True iff they intersect (touching counts).
  bool intersect = false;
  /// The squared minimum translation distance: the squared distance from the
  /// origin to the boundary of A + (-B); 0 when they only touch or are apart.
  Rational squared_depth;
  /// When they intersect, the primitive integer outward normal of the facet
  /// of A + (-B) nearest to the origin: translating B by depth along it
  /// (translation()) makes them touch. Zero when they are apart. (For convex
  /// sets whose A + (-B) is flat, see penetration(const ConvexSet&, ...).)
  Vec3 direction;
  /// When they intersect, the plane offset of that facet:
  /// dot(direction, x) = offset on it, offset >= 0.
  Rational offset;
  /// When they intersect: a point of A and a point of B with
  /// witness_a - witness_b == translation() (the contact after separating
  /// B by translation()); when apart, the closest points.
  Vec3 witness_a;
  /// See witness_a.
  Vec3 witness_b;

  /// The minimum translation of B, exact: offset / |direction|^2 * direction
  /// (zero when apart).
  [[nodiscard]] Vec3 translation() const;
};

/// The exact penetration depth of A and B. The exact GJK decides
/// intersection; if they intersect, an exact EPA (expanding polytope) grows a
/// polytope inside A + (-B) from support points until every face nearest to
/// the origin is proved to lie in a facet of A + (-B): the depth is the
/// distance to that facet plane (the origin is inside, and the distance from
/// an interior point of a convex polytope to its boundary is the smallest
/// distance to a facet plane; the proofs are in lib/proximity/epa.cpp),
/// compared exactly. A + (-B) is never built. Ties (several facets at the
/// same depth) go to the lexicographically smallest primitive normal (x,
/// then y, then z), so the answer does not depend on facet numbering; the
/// EPA finds every tied facet before it answers. The witnesses come from an
/// exact GJK of A against B moved by the translation (they touch there).
/// \throw Error(invalid_argument) for an empty operand or, when they
///   intersect, a placed operand with a singular linear part.
/// Complexity: the distance query when apart; when they intersect, one
/// support query of each operand per EPA step (a warm-started walk) and
/// O(faces of the polytope) exact comparisons per step, plus the witnesses'
/// distance query. The steps are as many as the vertices of A + (-B) the
/// polytope needs near the answer, not all of them; most are proposed by a
/// floating-point EPA and only inserted and verified exactly.
PenetrationResult penetration(const PlacedPolyhedron& a, const PlacedPolyhedron& b);

/// penetration() on the unmoved polyhedra.
PenetrationResult penetration(const ConvexPolyhedron& a, const ConvexPolyhedron& b);

/// The penetration of convex sets of any dimension. When they intersect and
/// M = A + (-B) is solid (dimension 3: at least one operand is, or two flat
/// ones span space together), as for polyhedra: the nearest facet of M, by
/// the same exact EPA. When M is flat (both operands in parallel planes, or
/// on parallel lines, or points...), M has no interior: the origin is on its
/// boundary whenever it is in M, so an intersecting pair has squared_depth 0
/// and translation() zero (any small move off M's affine hull separates
/// them). Then offset is 0 and direction is M's canonical plane normal
/// (ConvexSet::normal(), M from minkowski_sum of ConvexSets,
/// cvms/set_sum.hpp) when M is a polygon, zero when it is a segment or a
/// point (no single normal); the witnesses are a common point.
/// \throw Error(invalid_argument) naming the operand (A or B) if one is the
///   empty set;
/// \throw Error(limit) when they intersect, M is flat and beyond the
///   default SumLimits.
PenetrationResult penetration(const ConvexSet& a, const ConvexSet& b);

/// The double nearest to the square root of q (ties to even), for printing a
/// distance or a depth next to its exact square: decided by exact
/// comparisons of q with squared midpoints, not by rounding twice.
/// \throw Error(invalid_argument) if q is negative.
double nearest_double_sqrt(const Rational& q);

}  // namespace cvms
