// SPDX-License-Identifier: MIT
// What the public Mesh keeps private, and the library's own access to it:
// the arrays (Mesh::Storage, shared by copies) and the constructors that
// skip the point checks for outputs whose points are distinct by
// construction. Only the library includes this header, so no user can build
// an unchecked mesh or name its arrays' types.
#pragma once

#include <memory>
#include <vector>

#include "cvms/mesh.hpp"
#include "dyadic_points.hpp"
#include "kept_allocator.hpp"
#include "limb_arena.hpp"
#include "packed_vectors.hpp"

namespace cvms {

namespace detail {
class ResultSlab;
}  // namespace detail

/// A mesh's arrays: on their own, or carved from one slab with the rest of
/// a result (kept_allocator.hpp). Immutable once a Mesh views them.
struct Mesh::Storage {
  /// The arena the positions keep their limbs in, if they do (a sum's
  /// output): kept alive by every mesh that views them. Declared first so
  /// that it outlives them.
  std::shared_ptr<const detail::LimbArena> limbs;
  std::vector<Vec3> positions;  ///< empty when packed_positions holds them
  std::shared_ptr<const detail::PackedVectors> packed_positions;
  detail::KeptVector<HalfedgeId> vertex_he;  ///< one outgoing halfedge per vertex
  detail::KeptVector<VertexId> he_to;
  detail::KeptVector<HalfedgeId> he_next;
  detail::KeptVector<HalfedgeId> he_prev;
  detail::KeptVector<FaceId> he_face;
  detail::KeptVector<HalfedgeId> face_he;
};

/// The library's access to Mesh's private parts (see the file comment).
struct MeshAccess {
  /// Mesh's arrays, by a name the library can use.
  using Storage = Mesh::Storage;

  /// The mesh that views storage.
  static Mesh view(std::shared_ptr<const Mesh::Storage> storage) noexcept {
    Mesh m;
    const Mesh::Storage& s = *storage;
    if (s.packed_positions == nullptr) {
      m.positions_ = &s.positions;
      m.position_data_ = s.positions.data();
    }
    m.vertex_he_ = s.vertex_he.data();
    m.he_to_ = s.he_to.data();
    m.he_next_ = s.he_next.data();
    m.he_prev_ = s.he_prev.data();
    m.he_face_ = s.he_face.data();
    m.face_he_ = s.face_he.data();
    m.num_vertices_ = static_cast<std::uint32_t>(s.vertex_he.size());
    m.num_halfedges_ = static_cast<std::uint32_t>(s.he_to.size());
    m.num_faces_ = static_cast<std::uint32_t>(s.face_he.size());
    m.storage_ = std::move(storage);
    return m;
  }
  /// Makes m's storage keep `limbs` alive, the arena its positions point
  /// into. \pre m was just built (MeshAccess::from_distinct_points and the
  /// like make its storage, not const) and no other thread reads it yet.
  static void keep_limbs(Mesh& m, std::shared_ptr<const detail::LimbArena> limbs) noexcept {
    if (m.storage_ != nullptr) const_cast<Storage&>(*m.storage_).limbs = std::move(limbs);
  }
  /// The arrays of m (null for an empty mesh).
  [[nodiscard]] static const Mesh::Storage* storage(const Mesh& m) noexcept { return m.storage_.get(); }

  /// Mesh::from_soup without the point checks, for the algorithms' output:
  /// topology is checked in full. \pre the points are canonical and no two
  /// are equal (distinct sums a_i + b_j by construction).
  static Mesh from_distinct_points(PolygonSoup soup);
  /// from_distinct_points for a soup without points whose points are
  /// `positions`, kept packed until a caller asks for Vec3s; the
  /// connectivity carved from `slab` when it has room (kept_allocator.hpp).
  static Mesh from_distinct_points(PolygonSoup faces, std::shared_ptr<const detail::PackedVectors> positions,
                                   const std::shared_ptr<detail::ResultSlab>& slab);
  /// m.with_positions(positions), and each face's stored halfedge the one
  /// leaving its smallest vertex: by the numbering rules of from_soup, the
  /// mesh from_soup builds from m's soup with every face cycle rotated to
  /// start there. \pre as for from_distinct_points.
  static Mesh with_faces_from_smallest_vertex(const Mesh& m, std::vector<Vec3> positions);

  /// The exact positions as packed dyadics if m keeps them so, else null:
  /// what the library's own readers take instead of making Vec3s.
  [[nodiscard]] static const detail::DyadicPoints* packed_positions(const Mesh& m) noexcept {
    const Mesh::Storage* s = m.storage_.get();
    return s == nullptr || s->packed_positions == nullptr || s->packed_positions->is_scaled()
               ? nullptr
               : &s->packed_positions->packed();
  }
  /// to(h) is halfedge_targets(m)[h]: for loops that fetch it ahead.
  [[nodiscard]] static const VertexId* halfedge_targets(const Mesh& m) noexcept { return m.he_to_; }
};

}  // namespace cvms
