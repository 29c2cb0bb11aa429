// SPDX-License-Identifier: MIT
// A brute-force oracle for intersections of half-spaces: every triple of
// rows whose normals are independent meets in one point (Cramer's rule);
// the vertices of the intersection are exactly those points that satisfy
// every row (a vertex of a polytope in R^3 is where three independent rows
// are tight). O(m^4) plain Rational arithmetic; public API only, nothing of
// lib/halfspaces/.
#pragma once

#include <span>
#include <vector>

#include "cvms/halfspaces.hpp"
#include "support/set_oracle.hpp"

namespace cvms::test {

/// The system as inequalities only: each equality as two opposite rows.
std::vector<HalfspaceRow> as_inequalities(const HalfspaceSystem& s);

/// The vertices of {x : every row} by the triple enumeration (no duplicates).
std::vector<Vec3> brute_force_vertices(std::span<const HalfspaceRow> rows);

/// The shape of the intersection: hull_oracle of brute_force_vertices
/// (correct for bounded intersections; empty when no triple is feasible).
SetShape brute_force_intersection(std::span<const HalfspaceRow> rows);

/// The brute-force A ⊖ B: the intersection over the vertices b of B of
/// A − b, each A − b given by the rows of to_halfspaces(A) shifted by b.
SetShape brute_force_difference(const ConvexSet& a, const ConvexSet& b);

/// True iff every vertex of `inner` satisfies every row of `outer`'s
/// to_halfspaces (so inner ⊆ outer).
bool contained(const ConvexSet& inner, const ConvexSet& outer);

}  // namespace cvms::test
