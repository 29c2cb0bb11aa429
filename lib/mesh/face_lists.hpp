// SPDX-License-Identifier: MIT
// A mesh's faces as index lists: offsets from 0 and, face by face, the
// vertices of its cycle from its first halfedge. The one numbering that
// Mesh::to_soup and the file writers (which read a mesh in place) share.
#pragma once

#include <cstdint>
#include <vector>

#include "cvms/mesh.hpp"

namespace cvms::detail {

struct FaceLists {
  std::vector<std::uint32_t> offsets{0};  ///< faces + 1 entries, as PolygonSoup::face_offsets
  std::vector<std::uint32_t> indices;     ///< as PolygonSoup::face_indices
};

FaceLists face_lists(const Mesh& mesh);

}  // namespace cvms::detail
