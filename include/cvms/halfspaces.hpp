// SPDX-License-Identifier: MIT
/// \file
/// Convex sets as intersections of half-spaces a·x <= b, both ways, exactly;
/// and the Pontryagin difference A ⊖ B = {x : x + B ⊆ A} (erosion).
///
/// Names: control and robotics (robust and tube MPC, MPT3, CORA) call the
/// erosion A ⊖ B "Pontryagin difference" and often also "Minkowski
/// difference"; collision detection and graphics (GJK, configuration space
/// obstacles) call A ⊕ (−B) the "Minkowski difference". Here the erosion is
/// pontryagin_difference and A ⊕ (−B) is minkowski_difference, never the
/// other way round.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include "cvms/convex_set.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/vec.hpp"

namespace cvms {

/// One half-space dot(normal, x) <= offset (or, as an equality, == offset).
struct HalfspaceRow {
  Vec3 normal;      ///< a: any vector, zero allowed (then the row is 0 <= offset)
  Rational offset;  ///< b
  /// Exact equality of both parts (no scaling: (2a, 2b) != (a, b)).
  friend bool operator==(const HalfspaceRow&, const HalfspaceRow&) = default;
};

/// A system of equalities a·x == b and inequalities a·x <= b.
struct HalfspaceSystem {
  std::vector<HalfspaceRow> equalities;    ///< rows that hold with ==
  std::vector<HalfspaceRow> inequalities;  ///< rows that hold with <=
};

/// The answer of intersect_halfspaces: the set, or a direction of
/// unboundedness when the rows do not bound it.
struct HalfspaceIntersection {
  /// The exact intersection when it is bounded (possibly the empty set).
  ConvexSet set;
  /// When the intersection is non-empty and unbounded: a nonzero d with
  /// a·d <= 0 for every inequality and a·d == 0 for every equality (so x + s·d
  /// stays inside for every s >= 0); set is then the empty set. Its
  /// coordinates are coprime integers (the primitive integer vector of the
  /// direction).
  std::optional<Vec3> unbounded_direction;
};

/// The exact intersection of the half-spaces, or a direction in which it is
/// unbounded (see HalfspaceIntersection). Redundant, repeated and scaled rows
/// are harmless; implied equalities (rows that hold with equality on the
/// whole intersection) give a set of lower dimension. A zero row 0 <= b is
/// dropped when b >= 0 and makes the set empty when b < 0.
/// Algorithm: an exact simplex in rationals finds the largest t (<= 1) with
/// a·x + t <= b for every row; t < 0 means empty; t == 0 means implied
/// equalities (read off the LP's dual), removed by restricting to them and
/// solving again in fewer dimensions; t > 0 gives a strict interior point x0
/// (when every row has b > 0 and a nonzero normal, the origin is one and the
/// LP is skipped for a bounded set),
/// around which the rows are dualised to the points a/(b − a·x0), whose exact
/// hull (convex_hull_set) has the vertices of the result as its facets and
/// the irredundant rows as its vertices; the origin not strictly inside that
/// hull means unbounded, and a facet (or plane) of the hull that misses it
/// names the direction. A bounded polyhedron is read off that hull (its
/// polar: dual facets are the vertices, dual vertices the facets, dual edges
/// the edges), with no second hull.
/// Order (deterministic, the same on every run and thread count): a
/// polyhedron's facets come in the order of their rows (of duplicated rows,
/// one stands for all), its vertices in order of first use by the facets; a
/// polygon, segment or point comes in convex_hull_set's order of its
/// vertices.
/// Complexity: O(m) rational operations per simplex pivot (m rows), then
/// O(m log m) expected for the dual hull.
HalfspaceIntersection intersect_halfspaces(std::span<const HalfspaceRow> inequalities);

/// The same for a system with equalities (each taken as two inequalities).
HalfspaceIntersection intersect_halfspaces(const HalfspaceSystem& system);

/// intersect_halfspaces(inequalities), reporting the stage "hull" of its
/// exact dual hull (in rows settled) to `progress`, which may stop it
/// (cvms/progress.hpp); the stage may run more than once (a hull that finds
/// the set unbounded or flat, then the hull in fewer dimensions). Same
/// result. \throw Error(cancelled) if `progress` returns false.
HalfspaceIntersection intersect_halfspaces(std::span<const HalfspaceRow> inequalities,
                                           const ProgressCallback& progress);

/// The same for a system with equalities, with a progress callback.
/// \throw Error(cancelled) if `progress` returns false.
HalfspaceIntersection intersect_halfspaces(const HalfspaceSystem& system, const ProgressCallback& progress);

/// The exact intersection of the half-spaces dot(normal, x) <= offset: a
/// polyhedron, polygon, segment, point or the empty set (see
/// intersect_halfspaces).
/// \throw Error(invalid_argument) if the intersection is non-empty and
///   unbounded, naming a direction d in which it is (a·d <= 0 for every row).
///
/// \code
/// std::vector<cvms::HalfspaceRow> rows = {{{1, 0, 0}, 1}, {{-1, 0, 0}, 1},
///     {{0, 1, 0}, 1}, {{0, -1, 0}, 1}, {{0, 0, 1}, 0}, {{0, 0, -1}, 0}};
/// cvms::from_halfspaces(rows).dimension();  // 2: the square [-1,1]² × {0}
/// \endcode
ConvexSet from_halfspaces(std::span<const HalfspaceRow> inequalities);

/// The same for a system with equalities.
/// \throw Error(invalid_argument) if the intersection is unbounded, naming
///   a direction.
ConvexSet from_halfspaces(const HalfspaceSystem& system);

/// from_halfspaces(inequalities), reporting to `progress` as
/// intersect_halfspaces does. Same result.
/// \throw Error(cancelled) if `progress` returns false; else as above.
ConvexSet from_halfspaces(std::span<const HalfspaceRow> inequalities, const ProgressCallback& progress);

/// from_halfspaces(system), reporting to `progress` as intersect_halfspaces
/// does. Same result.
/// \throw Error(cancelled) if `progress` returns false; else as above.
ConvexSet from_halfspaces(const HalfspaceSystem& system, const ProgressCallback& progress);

/// The same for rows {a_x, a_y, a_z, b} given as doubles, each taken as the
/// exact binary number it is.
/// \throw Error(invalid_argument) for a NaN or infinite entry (naming the
///   row) or an unbounded intersection.
ConvexSet from_halfspaces(std::span<const std::array<double, 4>> inequalities);

/// The same for integer rows {a_x, a_y, a_z, b}.
/// \throw Error(invalid_argument) if the intersection is unbounded.
ConvexSet from_halfspaces(std::span<const std::array<long long, 4>> inequalities);

/// The minimal exact description of the set, every row primitive integer
/// (integer a and b with gcd 1):
///  - a polyhedron: one inequality per facet (its outward normal), no
///    equalities;
///  - a polygon: its plane as one equality (the polygon's canonical normal)
///    and one inequality per edge, normal cross(edge, plane normal) (within
///    the plane, outward);
///  - a segment from p to q: two equalities for its line and the two
///    inequalities ±(q − p)·x;
///  - a point: the three equalities x = p_x, y = p_y, z = p_z;
///  - the empty set: the single inequality 0·x <= −1.
/// from_halfspaces(to_halfspaces(s)) == s.
/// Complexity: O(size of the set).
HalfspaceSystem to_halfspaces(const ConvexSet& set);

/// The row scaled by a positive rational so that a and b are integers with
/// gcd 1 (a zero row becomes 0 <= 1, 0 <= 0 or 0 <= −1).
HalfspaceRow primitive_row(const HalfspaceRow& row);

/// The Pontryagin difference (erosion) A ⊖ B = {x : x + B ⊆ A}, exact, for
/// sets of any dimension: the rows n·x <= d − h_B(n) for each row (n, d) of
/// to_halfspaces(A) (each equality as two opposite inequalities), with h_B
/// the support function of B (for a polyhedron by the hill-climbing walk of
/// cvms/proximity.hpp, for a polygon, segment or point by the climb along
/// its vertex cycle; both warm-started from the previous answer), then
/// from_halfspaces.
/// A lower-dimensional A gives a set within its affine hull; the result may
/// be empty (a value, not an error). P ⊖ P == {0} for every non-empty P.
/// \throw Error(invalid_argument) if B is empty (the difference would be all
///   of space).
/// Complexity: O(facets of A × walk length) plus from_halfspaces.
ConvexSet pontryagin_difference(const ConvexSet& a, const ConvexSet& b);

/// pontryagin_difference(a, b), reporting the stage "difference: rows"
/// (rows of A shifted by h_B) and then the stages of from_halfspaces to
/// `progress`, which may stop it (cvms/progress.hpp). Same result.
/// \throw Error(cancelled) if `progress` returns false; else as above.
ConvexSet pontryagin_difference(const ConvexSet& a, const ConvexSet& b, const ProgressCallback& progress);

/// A ⊕ (−B), the set of differences a − b (what collision detection calls
/// the "Minkowski difference"; see the file comment): minkowski_sum(a,
/// b.reflected(), options).
/// \throw the errors of minkowski_sum (cvms/set_sum.hpp).
ConvexSet minkowski_difference(const ConvexSet& a, const ConvexSet& b, const Options& options = {});

}  // namespace cvms
