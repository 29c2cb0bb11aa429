// SPDX-License-Identifier: MIT
// A mesh's faces as index lists (see the header).
#include "face_lists.hpp"

namespace cvms::detail {

FaceLists face_lists(const Mesh& mesh) {
  FaceLists lists;
  lists.offsets.reserve(mesh.num_faces() + 1);
  lists.indices.reserve(mesh.num_halfedges());
  for (FaceId f : mesh.faces()) {
    for (HalfedgeId h : mesh.face_halfedges(f)) lists.indices.push_back(mesh.from(h).index());
    lists.offsets.push_back(static_cast<std::uint32_t>(lists.indices.size()));
  }
  return lists;
}

}  // namespace cvms::detail
