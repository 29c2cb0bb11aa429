// SPDX-License-Identifier: MIT
// -P for the penetration query's sum A + (-B), without recomputing anything
// that negation only flips.
#pragma once

#include "cvms/convex_polyhedron.hpp"

namespace cvms::detail {

/// -P, same vertex and facet numbering. The same polyhedron as
/// P.reflected(), but built from what negation maps exactly: positions and
/// normals negated (still canonical, primitive, distinct), offsets unchanged
/// (<-n, -x> = <n, x>), approximations negated (negation is exact in double);
/// only the facet cycles are reversed and the mesh rebuilt. reflected() goes
/// through transformed(), which recomputes every plane (a cross product and
/// a gcd per facet).
ConvexPolyhedron reflection(const ConvexPolyhedron& p);

}  // namespace cvms::detail
