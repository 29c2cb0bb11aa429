// SPDX-License-Identifier: MIT
// The combinatorial checks of a solid's boundary, on its input faces (with
// equal points merged): every edge used by exactly two faces in opposite
// directions, and the faces around every vertex one fan.
#pragma once

#include <cstdint>
#include <span>

namespace cvms::detail {

/// Faces as corner lists: face f is corners[offsets[f] .. offsets[f + 1])
/// of vertex ids below num_vertices, each face with distinct corners.
struct FaceLists {
  std::span<const std::uint32_t> offsets;
  std::span<const std::uint32_t> corners;
  std::uint32_t num_vertices = 0;
};

/// \throw Error(topology) for an edge with one face (open surface), more
///   than two faces, or two faces in the same direction (inconsistent
///   orientation); for a vertex whose faces form several fans. Vertices
///   and faces are named by input indices (`names[id]` for vertex id).
/// O(n log n) in the number of corners.
void check_closed_manifold(const FaceLists& faces, std::span<const std::uint32_t> names);

}  // namespace cvms::detail
