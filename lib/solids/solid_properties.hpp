// SPDX-License-Identifier: MIT
// What a solid's triangles determine: facets with their planes, reflex
// edges, shells with their genus and signed volume, the cavities and the
// volume. Shared by the validation (which then checks the orientations)
// and by SolidAccess::assume_valid (which trusts them).
#pragma once

#include <cstdint>
#include <vector>

#include "cvms/rational.hpp"
#include "solid_access.hpp"
#include "solid_impl.hpp"

namespace cvms::detail {

struct Shells {
  std::vector<std::uint32_t> of_triangle;     // the shell of each triangle
  std::vector<std::uint32_t> first_triangle;  // each shell's smallest triangle
  std::vector<Rational> signed_volumes;       // positive: faces outward
};

/// Fills every field of impl other than vertices and triangles, which it
/// reads. `areas[t]` is cross(b - a, c - a) for triangle t = (a, b, c), or
/// `areas` is empty and they are computed here. \pre every triangle has positive area and every edge of the
/// triangles has two triangles on it, in opposite directions (an edge
/// otherwise is skipped: it joins nothing and is no reflex edge).
Shells derive_properties(SolidAccess::Impl& impl, std::vector<Vec3> areas = {});

}  // namespace cvms::detail
