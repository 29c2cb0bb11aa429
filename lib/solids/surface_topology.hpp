// SPDX-License-Identifier: MIT
// The combinatorial check of a solid's boundary, on its input faces (with
// equal points merged): every edge used by as many faces in one direction as
// in the other, at least one each way. Two faces on an edge are its two
// sides; four or more are parts of the solid touching along it, and several
// fans around a vertex are parts touching at it: both are split into closed
// 2-manifold shells afterwards (manifold_split.hpp), after the faces were
// checked to meet only in shared edges and vertices.
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

/// \throw Error(topology) for an edge with one face (open surface), two
///   faces in the same direction (inconsistent orientation), or an odd
///   number of faces or not as many each way (an open or inconsistently
///   oriented surface where parts touch). Vertices and faces are named by
///   input indices (`names[id]` for vertex id). O(n log n) in the number of
///   corners.
void check_closed_surface(const FaceLists& faces, std::span<const std::uint32_t> names);

}  // namespace cvms::detail
