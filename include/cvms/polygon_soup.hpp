// SPDX-License-Identifier: MIT
// The plain exchange format between readers, writers and mesh construction:
// exact points plus faces given as index lists, with no checks at all.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

#include "cvms/vec.hpp"

namespace cvms {

struct PolygonSoup {
  std::vector<Vec3> points;
  /// Face f uses face_indices[face_offsets[f] .. face_offsets[f+1]).
  std::vector<std::uint32_t> face_offsets{0};
  std::vector<std::uint32_t> face_indices;

  [[nodiscard]] std::size_t num_faces() const noexcept { return face_offsets.size() - 1; }
  [[nodiscard]] std::span<const std::uint32_t> face(std::size_t f) const noexcept {
    return {face_indices.data() + face_offsets[f], face_offsets[f + 1] - face_offsets[f]};
  }
  void add_face(std::span<const std::uint32_t> indices) {
    face_indices.insert(face_indices.end(), indices.begin(), indices.end());
    face_offsets.push_back(static_cast<std::uint32_t>(face_indices.size()));
  }
  void add_face(std::initializer_list<std::uint32_t> indices) {
    add_face(std::span<const std::uint32_t>(indices.begin(), indices.size()));
  }
};

}  // namespace cvms
