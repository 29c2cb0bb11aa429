// SPDX-License-Identifier: MIT
/// \file
/// The plain exchange format between readers, writers and mesh construction:
/// exact points plus faces given as index lists, with no checks at all.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

#include "cvms/vec.hpp"

namespace cvms {

/// Points plus faces as lists of point indices, exactly as read or to be
/// written. Nothing is checked here: Mesh::from_soup and
/// ConvexPolyhedron::from_soup do that.
///
/// Build one by hand:
/// \code
/// cvms::PolygonSoup soup;
/// soup.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
/// soup.add_face({0, 2, 1});  // counterclockwise seen from outside
/// soup.add_face({0, 1, 3});
/// soup.add_face({0, 3, 2});
/// soup.add_face({1, 2, 3});
/// \endcode
struct PolygonSoup {
  std::vector<Vec3> points;  ///< exact coordinates, indexed from 0
  /// Face f uses face_indices[face_offsets[f] .. face_offsets[f+1]).
  std::vector<std::uint32_t> face_offsets{0};
  std::vector<std::uint32_t> face_indices;  ///< the faces' point indices, concatenated

  /// Number of faces.
  [[nodiscard]] std::size_t num_faces() const noexcept { return face_offsets.size() - 1; }
  /// The point indices of face f, in order. \pre f < num_faces().
  [[nodiscard]] std::span<const std::uint32_t> face(std::size_t f) const noexcept {
    return {face_indices.data() + face_offsets[f], face_offsets[f + 1] - face_offsets[f]};
  }
  /// Appends a face with these point indices (not checked).
  void add_face(std::span<const std::uint32_t> indices) {
    face_indices.insert(face_indices.end(), indices.begin(), indices.end());
    face_offsets.push_back(static_cast<std::uint32_t>(face_indices.size()));
  }
  /// Appends a face with these point indices: `soup.add_face({0, 1, 2})`.
  void add_face(std::initializer_list<std::uint32_t> indices) {
    add_face(std::span<const std::uint32_t>(indices.begin(), indices.size()));
  }
};

}  // namespace cvms
