// SPDX-License-Identifier: MIT
// Exact tests between closed triangles, for the self-intersection test of a
// solid's boundary. Triangles are given by vertex ids into one array of
// distinct points, so a shared vertex or edge is recognised by its ids.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "cvms/vec.hpp"

namespace cvms::detail {

using Triangle = std::array<std::uint32_t, 3>;

/// True iff the closed triangles t and u (each of positive area) have a
/// point in common other than their shared vertices and edge: for no shared
/// vertex, any common point; for one shared vertex v, a common point other
/// than v; for a shared edge, the two are coplanar on the same side of it (a
/// fold); equal vertex sets always intersect.
bool triangles_overlap(std::span<const Vec3> points, const Triangle& t, const Triangle& u);

/// True iff p lies on the closed triangle (a, b, c) of positive area.
bool point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace cvms::detail
