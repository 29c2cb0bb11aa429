// SPDX-License-Identifier: MIT
// Seeded random point clouds and operand pairs for the Minkowski-sum tests:
// integer, decimal and double coordinates, clouds with forced coplanarity,
// and pairs whose second operand shares edge and facet directions with the
// first.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "cvms/convex_polyhedron.hpp"

namespace cvms::test {

/// One random operand pair; `description` says how it was made.
struct RandomPair {
  ConvexPolyhedron a;
  ConvexPolyhedron b;
  std::string description;
};

/// A random pair of hulls for `seed` (always the same for the same seed).
/// Clouds have 4..max_points points, mostly small.
RandomPair random_pair(std::uint64_t seed, int max_points = 200);

}  // namespace cvms::test
