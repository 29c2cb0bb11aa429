// SPDX-License-Identifier: MIT
// Cutting planes for the auto-partition that hold no facet of the solid:
// each spanned by a reflex edge and a second edge of the solid at one of its
// ends. Facet planes alone cannot cut a ring of convex segments (a coarse
// torus, a bent tube) at the joints between segments, since no facet lies
// there; a plane through the joint's edges can, and when it cuts no
// boundary fragment of a cell it splits the cell's boundary in two without
// making any new piece of boundary (see auto_partition.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "boundary_planes.hpp"
#include "cvms/solid.hpp"

namespace cvms::decomposition {

// At most this many free planes are kept: each one is tried at partition
// nodes, so their number bounds that work.
inline constexpr std::size_t kMaxFreePlanes = 32;

// The distinct planes through a reflex edge of `planes.edges` and another
// edge of it sharing an end (not collinear), that are no plane of
// `planes.planes`; canonical as Plane says. The planes holding the most such
// edge pairs first (a plane through many of the solid's edges follows its
// shape), ties in plane order; at most kMaxFreePlanes. Deterministic.
std::vector<Plane> free_planes(const Solid& solid, const BoundaryPlanes& planes);

}  // namespace cvms::decomposition
