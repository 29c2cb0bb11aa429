// SPDX-License-Identifier: MIT
// Which fragments of the boundary of dA + B lie inside A + b (b interior to
// the convex B), for the sum of a solid A with a convex B (solid_sum.cpp):
// those fragments bound nothing of A + B and are dropped. One exact locate
// in A decides a whole group of fragments that share corners, since
// dA + b, the boundary of A + b, lies in the interior of dA + B and so
// meets no fragment (the proof is in translate_side.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "boundary_fragments.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/solid.hpp"
#include "cvms/vec.hpp"

namespace cvms::detail {

/// Groups of fragments joined through shared corners (exactly equal
/// points): group[i] for fragment i, groups numbered in order of their
/// first fragment; `count` receives the number of groups.
std::vector<std::uint32_t> corner_groups(const BoundaryFragments& fragments, std::uint32_t& count);

/// For each fragment, nonzero iff it lies in the interior of A + b.
/// Deterministic: one locate per group (of its first fragment), the groups
/// shared over options.threads threads, each answer in its own slot.
/// \pre every fragment lies on the boundary of dA + B for a convex,
///   full-dimensional B with b in its interior (so none meets dA + b).
/// \throw Error(cancelled) if options.progress returns false.
std::vector<char> inside_translate(const BoundaryFragments& fragments, const Solid& a, const Vec3& b,
                                   const Options& options);

}  // namespace cvms::detail
