// SPDX-License-Identifier: MIT
// What the queries of this layer share: the operand checks and the distance
// with B moved further (the penetration query's witnesses).
#pragma once

#include "cvms/convex_set.hpp"
#include "cvms/proximity.hpp"
#include "gjk.hpp"
#include "support_operand.hpp"

namespace cvms::detail {

/// squared_distance with B moved further by *b_offset (if not null), exact;
/// witness_b includes the offset.
DistanceResult distance_with_offset(const SupportOperand& a, const SupportOperand& b, const Vec3* b_offset);

/// The distance answer of a finished exact_gjk (goal distance) on operand
/// `a`: the witnesses are the simplex's weighted vertices.
DistanceResult distance_from(const SupportOperand& a, const GjkOutcome& g);

/// \throw Error(invalid_argument) naming `who` if an operand is empty.
void check_operands(const PlacedPolyhedron& a, const PlacedPolyhedron& b, const char* who);
/// The same for unmoved polyhedra.
void check_operands(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const char* who);
/// \throw Error(invalid_argument) naming `who` and the operand (A or B) if
///   one is the empty set.
void check_operands(const ConvexSet& a, const ConvexSet& b, const char* who);

}  // namespace cvms::detail
