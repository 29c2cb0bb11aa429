// SPDX-License-Identifier: MIT
// One input face of a solid: checked to be a planar simple polygon of
// positive area (collinear vertices allowed), and triangulated without new
// vertices and without a zero-area triangle.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "cvms/vec.hpp"

namespace cvms::detail {

/// The most corners a face may have: its checks are quadratic in its size.
inline constexpr std::size_t max_face_corners = 4096;

/// Appends the triangles of face `face` (its corners `ids`, vertex ids into
/// `points`) to `out`, each turning as the face does, and the area vector
/// cross(b - a, c - a) of each triangle (a, b, c) to `areas` (nonzero).
/// `input_names[id]` is the input index a message gives for vertex id.
/// \throw Error(degenerate) if the face is not planar, not simple or has
///   zero area, Error(limit) beyond max_face_corners; naming the face.
void triangulate_face(std::span<const Vec3> points, std::span<const std::uint32_t> ids,
                      std::span<const std::uint32_t> input_names, std::uint32_t face,
                      std::vector<std::array<std::uint32_t, 3>>& out, std::vector<Vec3>& areas);

}  // namespace cvms::detail
