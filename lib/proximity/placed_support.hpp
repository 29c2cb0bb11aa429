// SPDX-License-Identifier: MIT
// The support walk on a placed operand, for the queries of this layer
// (support.cpp explains how the placement is applied to the direction).
#pragma once

#include "approx.hpp"
#include "cvms/proximity.hpp"
#include "cvms/sign.hpp"

namespace cvms::detail {

/// A vertex of p maximising <x, u> (sense positive) or minimising it (sense
/// negative) over the moved polyhedron, climbing from `start` (a valid vertex).
VertexId support_vertex(const PlacedPolyhedron& p, Vec3Ref u, Sign sense, VertexId start);

/// squared_distance with B moved further by *b_offset (if not null), exact;
/// witness_b includes the offset. \pre both operands non-empty.
DistanceResult distance_with_offset(const PlacedPolyhedron& a, const PlacedPolyhedron& b, const Vec3* b_offset);

/// \throw Error(invalid_argument) naming `who` if an operand is empty.
void check_operands(const PlacedPolyhedron& a, const PlacedPolyhedron& b, const char* who);

}  // namespace cvms::detail
