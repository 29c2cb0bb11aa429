// SPDX-License-Identifier: MIT
// The test that ends the auto-partition at a cell whose part of the solid is
// convex, and that part's points (proof in convex_part.cpp).
#pragma once

#include <optional>
#include <vector>

#include "boundary_planes.hpp"
#include "convex_cell.hpp"
#include "cvms/progress.hpp"
#include "cvms/vec.hpp"

namespace cvms::decomposition {

// When every fragment of the cell lies on or behind the plane of every other
// fragment (each plane taken with its fragment's outward side), the solid's
// part in the cell is the convex K = cell n (the closed half-spaces behind
// the fragments), and this returns points whose hull is K: the fragments'
// points and the cell's vertices in K. Otherwise, or when the fragments'
// points span no volume, nothing. O(m log m) for m fragment points, plus
// the cell's vertices times the distinct fragment planes.
// \pre fragments is not empty and holds the solid's boundary in the cell.
// `progress` hears the hull (stage "hull") and may stop it (Error(cancelled)).
std::optional<std::vector<Vec3>> convex_part(const Cell& cell, const std::vector<Fragment>& fragments,
                                             const std::vector<Plane>& planes, const ProgressCallback& progress);

}  // namespace cvms::decomposition
