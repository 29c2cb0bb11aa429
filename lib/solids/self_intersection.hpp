// SPDX-License-Identifier: MIT
// The exact self-intersection test of a solid's boundary: candidate pairs of
// triangles from the hierarchy (triangle_tree.hpp), each decided exactly
// (triangle_intersection.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>

#include "cvms/vec.hpp"
#include "triangle_tree.hpp"

namespace cvms::detail {

struct SelfIntersection {
  std::optional<std::pair<std::uint32_t, std::uint32_t>> faces;  // the first pair found, smaller first
  std::uint64_t candidate_pairs = 0;  // pairs whose boxes overlap, examined up to the first hit
};

/// The first pair of input faces whose triangles meet other than in shared
/// vertices and edges. `face_of[t]` is the input face of triangle t; two
/// triangles of one face are not compared (the face was checked simple).
SelfIntersection find_self_intersection(const TriangleTree& tree, std::span<const Vec3> points,
                                        std::span<const std::array<std::uint32_t, 3>> triangles,
                                        std::span<const std::uint32_t> face_of);

}  // namespace cvms::detail
