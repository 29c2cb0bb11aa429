// SPDX-License-Identifier: MIT
// How a PenetrationResult is filled, shared by the EPA (penetration.cpp) and
// its reference on the whole sum (penetration_by_sum.cpp), so that both give
// the same apart answer and the same depth from the same nearest facet (each
// finds its own witnesses).
#pragma once

#include "cvms/proximity.hpp"

namespace cvms::detail {

/// The answer when apart (the closest points) or, provisionally, when they
/// intersect (a common point, depth 0, no direction yet).
PenetrationResult penetration_from_distance(const DistanceResult& d);

/// Sets the nearest facet {x : <direction, x> = offset} of A + (-B) and the
/// squared depth (the witnesses are the caller's).
void set_depth(PenetrationResult& r, Vec3 direction, Rational offset);

}  // namespace cvms::detail
