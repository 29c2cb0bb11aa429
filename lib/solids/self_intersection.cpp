// SPDX-License-Identifier: MIT
// The search of self_intersection.hpp: every pair of triangles with
// overlapping boxes, in the hierarchy's fixed order, so the pair reported
// for a given input is always the same.
#include "self_intersection.hpp"

#include <algorithm>

#include "triangle_intersection.hpp"

namespace cvms::detail {

SelfIntersection find_self_intersection(const TriangleTree& tree, std::span<const Vec3> points,
                                        std::span<const std::array<std::uint32_t, 3>> triangles,
                                        std::span<const std::uint32_t> face_of) {
  SelfIntersection result;
  result.candidate_pairs = tree.for_each_overlapping_pair([&](std::uint32_t s, std::uint32_t t) {
    if (face_of[s] == face_of[t]) return false;
    if (!triangles_overlap(points, triangles[s], triangles[t])) return false;
    result.faces = std::pair{std::min(face_of[s], face_of[t]), std::max(face_of[s], face_of[t])};
    return true;
  });
  return result;
}

}  // namespace cvms::detail
