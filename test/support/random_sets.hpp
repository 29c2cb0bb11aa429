// SPDX-License-Identifier: MIT
// Seeded random convex sets of a given dimension on a small grid, so that
// alignments (parallel edges and facets, coplanar polygons, collinear
// segments) are frequent: for the set-sum tests and their soak run.
#pragma once

#include <random>

#include "cvms/convex_set.hpp"

namespace cvms::test {

/// The hull of up to dimension + max_extra points origin + sum c_k b_k, with
/// coefficients c_k in {-radius .. radius} / {1, 2} and bases b_k either the
/// axes or random grid vectors; drawn again until it has the dimension asked
/// for (0 to 3).
ConvexSet random_set(std::mt19937_64& rng, int dimension, const Vec3& origin, int radius = 2, int max_extra = 8);

}  // namespace cvms::test
