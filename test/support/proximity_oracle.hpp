// SPDX-License-Identifier: MIT
// The independent oracle of the proximity tests: the exact hull of the
// pairwise differences M = A + (-B) (CHMS) and a brute-force exact
// projection of the origin onto each of its facets, edges and vertices.
// Plain rational arithmetic, no predicates and no walks: nothing shared with
// the code under test but the hull.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/proximity.hpp"

namespace cvms::test {

/// What the brute force finds for the origin and a convex polyhedron M.
struct OriginAndPolytope {
  bool inside = false;             ///< the origin is in M (closed)
  Rational boundary_distance2;     ///< squared distance from the origin to the boundary of M
  std::vector<Vec3> nearest_normals;  ///< the facet normals whose planes are at that distance (inside only)
};

/// Brute force over every facet, edge and vertex of M.
OriginAndPolytope origin_versus(const ConvexPolyhedron& m);

/// M = chms(a, b.reflected()) and the brute force on it.
OriginAndPolytope proximity_oracle(const ConvexPolyhedron& a, const ConvexPolyhedron& b);

/// True iff x satisfies every facet inequality of p (exactly).
bool contains(const ConvexPolyhedron& p, const Vec3& x);

/// The squared distance from the origin to the closed segment [u, w], u != w.
Rational origin_segment_distance2(const Vec3& u, const Vec3& w);

/// An exact membership test of an operand (for the witnesses).
using Membership = std::function<bool(const Vec3&)>;

/// check_distance with the operands given by their membership tests.
std::string check_distance_by(const Membership& in_a, const Membership& in_b, const DistanceResult& d,
                              const OriginAndPolytope& oracle);

/// check_penetration with the operands given by their membership tests
/// (M = A + (-B) solid).
std::string check_penetration_by(const Membership& in_a, const Membership& in_b, const PenetrationResult& p,
                                 const OriginAndPolytope& oracle);

/// "" if the distance answer agrees with the oracle and its witnesses are
/// valid (in A, in B, at the right distance), else what is wrong.
std::string check_distance(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const DistanceResult& d,
                           const OriginAndPolytope& oracle);

/// "" if the penetration answer agrees with the oracle (depth, direction
/// among the nearest facets with the documented tie-break, witnesses), else
/// what is wrong.
std::string check_penetration(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const PenetrationResult& p,
                              const OriginAndPolytope& oracle);

/// How a random pair was placed.
enum class Placing { overlapping = 0, touching = 1, separated = 2 };

/// The outcome of one seeded random placement.
struct RandomPlacementCheck {
  Placing kind = Placing::overlapping;
  std::string description;  ///< the pair and the placement
  std::string failure;      ///< "" when every query agreed with the oracle
};

/// A seeded random pair, placed (see check_random_placement), with its oracle.
struct RandomPlacement {
  Placing kind = Placing::overlapping;
  std::string description;  ///< the pair and the placement
  ConvexPolyhedron a, b;
  OriginAndPolytope oracle;
  std::string failure;  ///< "" unless the oracle contradicts the construction
};

/// The pair of check_random_placement(seed), not yet queried.
RandomPlacement random_placement(std::uint64_t seed);

RandomPlacementCheck check_random_placement(std::uint64_t seed);

}  // namespace cvms::test
