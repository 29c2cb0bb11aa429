// SPDX-License-Identifier: MIT
// Where two parts of a set touch along an edge or at a point, its boundary
// is not a 2-manifold: four triangles on one edge, or several fans of
// triangles around one vertex. The assembled boundary is made one by
// pairing the triangles on such an edge so that each part closes, and by
// giving each fan around a vertex its own copy of the vertex (the same
// point under a new index): every shell is then a closed 2-manifold, as
// mesh formats and tools expect, and the set it bounds is unchanged.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "cvms/vec.hpp"

namespace cvms::detail {

/// Splits the non-manifold edges and vertices of closed, outward triangles
/// (every edge has as many triangles one way as the other), appending the
/// copies of split vertices to `vertices` and renumbering `triangles`.
/// Afterwards every edge has exactly two triangles, in opposite directions,
/// and the triangles around every vertex form one fan.
/// \throw Error(invalid_argument) if an edge's triangles do not alternate
///   in direction around it (the triangles do not bound a solid).
void split_non_manifold(std::vector<Vec3>& vertices, std::vector<std::array<std::uint32_t, 3>>& triangles);

/// The same split, reporting instead of throwing: the vertex indices (as
/// given) of an edge whose triangles do not alternate in direction around
/// it, or that a fan would cross more than the split can cut (the triangles
/// are then left in an unspecified state), or nothing on success.
/// \pre every edge has as many triangles one way as the other.
std::optional<std::pair<std::uint32_t, std::uint32_t>> try_split_non_manifold(
    std::vector<Vec3>& vertices, std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace cvms::detail
