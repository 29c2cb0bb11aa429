// SPDX-License-Identifier: MIT
// Penetration by the whole sum M = A + (-B) and a scan of its facets. Not
// the library's path (penetration.cpp runs the exact EPA of epa.cpp, which
// never builds M); kept as the EPA's reference in the tests and the benchmark,
// and for convex sets whose M is flat, where there is no facet to find.
#pragma once

#include "cvms/convex_set.hpp"
#include "cvms/proximity.hpp"

namespace cvms::detail {

/// penetration(a, b) by the whole sum: the same answers (the EPA's tests
/// compare them), at the cost of one Minkowski sum when they intersect.
PenetrationResult penetration_by_sum(const PlacedPolyhedron& a, const PlacedPolyhedron& b);

/// The same on the unmoved polyhedra (this overload makes the call unambiguous).
inline PenetrationResult penetration_by_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  return penetration_by_sum(PlacedPolyhedron(a), PlacedPolyhedron(b));
}

/// penetration(a, b) on convex sets by the whole sum (the sets layer's).
PenetrationResult penetration_by_sum(const ConvexSet& a, const ConvexSet& b);

}  // namespace cvms::detail
