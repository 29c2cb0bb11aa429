// SPDX-License-Identifier: MIT
// The support walk on a placed operand, for the queries of this layer
// (support.cpp explains how the placement is applied to the direction).
#pragma once

#include "cvms/proximity.hpp"

namespace cvms::detail {

/// A vertex of p maximising <x, u> over the moved polyhedron, climbing from
/// `start` (a valid vertex).
VertexId support_vertex(const PlacedPolyhedron& p, const Vec3& u, VertexId start);

/// \throw Error(invalid_argument) naming `who` if an operand is empty.
void check_operands(const PlacedPolyhedron& a, const PlacedPolyhedron& b, const char* who);

}  // namespace cvms::detail
