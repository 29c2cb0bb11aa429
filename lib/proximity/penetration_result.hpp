// SPDX-License-Identifier: MIT
// How a PenetrationResult is filled, shared by the EPA (penetration.cpp) and
// its reference on the whole sum (penetration_by_sum.cpp), so that both
// answer alike once they agree on the nearest facet.
#pragma once

#include "cvms/proximity.hpp"
#include "support_operand.hpp"

namespace cvms::detail {

/// The answer when apart (the closest points) or, provisionally, when they
/// intersect (a common point, depth 0, no direction yet).
PenetrationResult penetration_from_distance(const DistanceResult& d);

/// Sets the nearest facet {x : <direction, x> = offset} of A + (-B), the
/// squared depth, and as witnesses the contact of A with B moved by the
/// translation (an exact GJK: they touch there, so it returns a common
/// point x, and x, x - translation are the witnesses).
void set_nearest_facet(PenetrationResult& r, Vec3 direction, Rational offset, const SupportOperand& a,
                       const SupportOperand& b);

}  // namespace cvms::detail
