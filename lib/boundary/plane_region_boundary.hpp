// SPDX-License-Identifier: MIT
// The boundary of the region that the fragments on one oriented plane cover,
// as maximal directed segments: the first step of boundary_assembly.hpp.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "boundary_fragments.hpp"
#include "cvms/vec.hpp"

namespace cvms::detail {

/// A straight piece of a plane region's boundary, the region on its left
/// seen from the side the plane's normal points to.
struct DirectedSegment {
  Vec3 from;
  Vec3 to;
};

/// The boundary of the union of the fragments `on_plane` (indices into
/// fragments.fragments, all on the plane `normal` names): every maximal
/// straight piece of it, directed so that the region is on its left. Where
/// the region touches itself at a point, the pieces on either side of that
/// point are separate segments. Every segment's end is a corner of the
/// region (its boundary is not one straight line through it).
/// \throw Error(invalid_argument) if two fragments on the same side of a line
///   overlap along it (the fragments' interiors are not disjoint).
std::vector<DirectedSegment> plane_region_boundary(const BoundaryFragments& fragments,
                                                   std::span<const std::uint32_t> on_plane, const Vec3& normal);

}  // namespace cvms::detail
