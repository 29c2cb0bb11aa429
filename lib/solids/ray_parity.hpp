// SPDX-License-Identifier: MIT
// Inside or outside by the parity of the crossings of a ray with the
// boundary, exactly: the ray's direction is taken from a fixed sequence and
// replaced by the next one whenever the ray meets an edge or a vertex of a
// triangle, or runs inside a triangle's plane.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>

#include "cvms/vec.hpp"
#include "triangle_tree.hpp"

namespace cvms::detail {

/// True iff a ray from p crosses the triangles that `counts` accepts an odd
/// number of times. \pre p lies on none of the accepted triangles.
bool odd_crossings(const TriangleTree& tree, std::span<const Vec3> points,
                   std::span<const std::array<std::uint32_t, 3>> triangles, const Vec3& p,
                   const std::function<bool(std::uint32_t)>& counts);

}  // namespace cvms::detail
