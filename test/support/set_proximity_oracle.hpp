// SPDX-License-Identifier: MIT
// The proximity oracle for convex sets of any dimension: M = A + (-B) as the
// independent hull of the pairwise differences (set_oracle's hull_oracle,
// which finds M's dimension), then the brute-force projection of the origin:
// onto every facet, edge and vertex when M is solid (origin_versus on the
// hull), onto its vertices, edges and (a polygon) its face when M is flat.
// Plain rational arithmetic; nothing of lib/proximity or lib/sets.
#pragma once

#include <cstdint>
#include <string>

#include "cvms/convex_set.hpp"
#include "cvms/proximity.hpp"
#include "support/proximity_oracle.hpp"

namespace cvms::test {

/// What the brute force finds for the origin and M.
struct SetProximityOracle {
  int dimension = -1;  ///< of M
  /// inside: the origin is in M. boundary_distance2: for a solid M the
  /// squared distance to its boundary; for a flat M (no interior) the
  /// squared distance to M itself. nearest_normals: for a solid M as in
  /// origin_versus; for a flat polygon M containing the origin, its
  /// canonical plane normal (the documented direction).
  OriginAndPolytope origin;
};

/// The oracle of a and b (both non-empty).
SetProximityOracle set_proximity_oracle(const ConvexSet& a, const ConvexSet& b);

/// True iff x is in s, exactly (s non-empty).
bool set_contains(const ConvexSet& s, const Vec3& x);

/// "" if squared_distance, intersects and penetration of (a, b) agree with
/// the oracle and their witnesses are valid, else what is wrong.
std::string check_set_queries(const ConvexSet& a, const ConvexSet& b);
/// The same with the oracle already computed.
std::string check_set_queries(const ConvexSet& a, const ConvexSet& b, const SetProximityOracle& oracle);

/// One seeded random pair of flattened or collapsed sets (dimensions 0 to 3
/// from the seed, on random_set's grid), B moved so that they overlap, touch
/// or are apart by construction (the oracle is checked against it), then
/// check_set_queries.
struct RandomSetPairCheck {
  bool intersect = false;
  bool touching = false;  ///< intersect with squared depth 0
  std::string description;
  std::string failure;  ///< "" when every query agreed with the oracle
};
RandomSetPairCheck check_random_set_pair(std::uint64_t seed);

}  // namespace cvms::test
