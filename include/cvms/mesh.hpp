// SPDX-License-Identifier: MIT
/// \file
/// Index-based half-edge mesh of a closed, consistently oriented 2-manifold
/// polygon surface. Connectivity lives in plain arrays owned by the mesh;
/// handles are typed 32-bit indices. Halfedges come in pairs: twin(h) = h ^ 1
/// and the undirected edge of h is h >> 1. Faces are oriented counterclockwise
/// seen from outside (for a closed surface: the orientation of the input).
#pragma once

#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "cvms/polygon_soup.hpp"
#include "cvms/vec.hpp"

namespace cvms {

/// A typed 32-bit index, invalid by default.
template <class Tag>
class Handle {
 public:
  /// The index of a default-constructed (invalid) handle.
  static constexpr std::uint32_t invalid_index = std::numeric_limits<std::uint32_t>::max();
  constexpr Handle() noexcept = default;
  /// The handle of element `index`.
  constexpr explicit Handle(std::uint32_t index) noexcept : index_(index) {}
  /// The element's position in its mesh array.
  [[nodiscard]] constexpr std::uint32_t index() const noexcept { return index_; }
  /// False for a default-constructed handle.
  [[nodiscard]] constexpr bool is_valid() const noexcept { return index_ != invalid_index; }
  /// Same index.
  friend constexpr bool operator==(Handle a, Handle b) noexcept { return a.index_ == b.index_; }
  /// Ordered by index.
  friend constexpr auto operator<=>(Handle a, Handle b) noexcept { return a.index_ <=> b.index_; }

 private:
  std::uint32_t index_ = invalid_index;
};

using VertexId = Handle<struct VertexTag>;      ///< a vertex of a Mesh
using HalfedgeId = Handle<struct HalfedgeTag>;  ///< a directed edge; twin is h ^ 1
using EdgeId = Handle<struct EdgeTag>;          ///< an undirected edge: halfedges 2e and 2e + 1
using FaceId = Handle<struct FaceTag>;          ///< a face (facet) of a Mesh

/// A range over the handles 0..n-1 of one kind, for range-for.
template <class Id>
class IdRange {
 public:
  /// Forward iterator yielding Id(0), Id(1), ...
  class iterator {
   public:
    using value_type = Id;                   ///< the handle type
    using difference_type = std::ptrdiff_t;  ///< for the iterator concepts
    iterator() = default;
    /// At handle i.
    explicit iterator(std::uint32_t i) : i_(i) {}
    /// The current handle.
    Id operator*() const { return Id(i_); }
    /// The next handle.
    iterator& operator++() {
      ++i_;
      return *this;
    }
    /// The next handle (postfix).
    iterator operator++(int) {
      iterator t = *this;
      ++i_;
      return t;
    }
    /// At the same handle.
    friend bool operator==(iterator a, iterator b) { return a.i_ == b.i_; }

   private:
    std::uint32_t i_ = 0;
  };
  /// The handles 0..n-1.
  explicit IdRange(std::uint32_t n) : n_(n) {}
  /// At handle 0.
  [[nodiscard]] iterator begin() const { return iterator(0); }
  /// Past the last handle.
  [[nodiscard]] iterator end() const { return iterator(n_); }
  /// The number of handles.
  [[nodiscard]] std::uint32_t size() const { return n_; }

 private:
  std::uint32_t n_;
};

class Mesh;

/// The halfedges around a face (following next), or the outgoing halfedges of
/// a vertex (following twin(prev(h)), i.e. counterclockwise seen from outside).
class HalfedgeCirculator {
 public:
  /// Which cycle to follow.
  enum class Kind {
    face,   ///< the halfedges of a face, by next
    vertex  ///< the halfedges leaving a vertex, by twin(prev(h))
  };
  /// Forward iterator over one cycle; it ends when the cycle is back at its start.
  class iterator {
   public:
    using value_type = HalfedgeId;           ///< the handle type
    using difference_type = std::ptrdiff_t;  ///< for the iterator concepts
    iterator() = default;
    /// At halfedge h of the cycle of `kind` that starts (and ends) at
    /// `start`; at_end marks the past-the-end position.
    iterator(const Mesh* mesh, HalfedgeId h, HalfedgeId start, Kind kind, bool at_end)
        : mesh_(mesh), h_(h), start_(start), kind_(kind), at_end_(at_end) {}
    /// The current halfedge.
    HalfedgeId operator*() const { return h_; }
    /// The next halfedge of the cycle.
    iterator& operator++();
    /// The next halfedge of the cycle (postfix).
    iterator operator++(int) {
      iterator t = *this;
      ++*this;
      return t;
    }
    /// Same position (both past the end, or both at the same halfedge).
    friend bool operator==(const iterator& a, const iterator& b) {
      return a.h_ == b.h_ && a.at_end_ == b.at_end_;
    }

   private:
    const Mesh* mesh_ = nullptr;
    HalfedgeId h_;
    // Kept rather than looked up again at every step: that was two
    // dependent loads per step on the searches' hottest loops.
    HalfedgeId start_;
    Kind kind_ = Kind::face;
    bool at_end_ = true;
  };
  /// The cycle of `kind` through `start`, from `start` around to just
  /// before it (Mesh::face_halfedges and Mesh::outgoing_halfedges start at
  /// the face's or the vertex's stored halfedge).
  HalfedgeCirculator(const Mesh* mesh, HalfedgeId start, Kind kind)
      : mesh_(mesh), start_(start), kind_(kind) {}
  /// At the start halfedge (empty range if start is invalid).
  [[nodiscard]] iterator begin() const { return {mesh_, start_, start_, kind_, !start_.is_valid()}; }
  /// Past the end.
  [[nodiscard]] iterator end() const { return {mesh_, start_, start_, kind_, true}; }

 private:
  const Mesh* mesh_;
  HalfedgeId start_;
  Kind kind_;
};

/// A closed, consistently oriented 2-manifold polygon mesh (see the file
/// comment). Immutable once built: copies share the arrays (a copy costs a
/// reference count, not the arrays), and a move leaves the source empty.
///
/// \pre Accessors taking a handle require a valid handle of this mesh
///   (index below the matching num_*()); this is not checked.
/// Thread-safety: const member functions may run concurrently.
class Mesh {
 public:
  /// The empty mesh (no vertices, halfedges or faces).
  Mesh() noexcept = default;
  /// Shares other's (immutable) arrays.
  Mesh(const Mesh& other) = default;
  /// Takes other's arrays and leaves it empty.
  Mesh(Mesh&& other) noexcept { swap_with(other); }
  /// Shares other's (immutable) arrays.
  Mesh& operator=(const Mesh& other) = default;
  /// Takes other's arrays and leaves it empty.
  Mesh& operator=(Mesh&& other) noexcept {
    Mesh taken(std::move(other));
    swap_with(taken);
    return *this;
  }
  ~Mesh() = default;

  /// Builds the half-edge structure of a closed, consistently oriented
  /// 2-manifold polygon mesh. Points are moved in (coordinates canonicalised,
  /// values unchanged); every point must be used by a face.
  /// \throw Error(topology) naming the offending element: a face with fewer
  ///   than 3 vertices or a repeated vertex, an index out of range, an edge
  ///   used by other than 2 faces, an edge used twice in the same direction
  ///   (inconsistent orientation), a boundary edge (open surface), a vertex
  ///   whose faces do not form one cycle (non-manifold vertex), an unreferenced
  ///   vertex, two vertices at the same point, or an empty soup.
  /// \throw Error(invalid_argument) if face_offsets is malformed (not starting
  ///   at 0, decreasing, or not ending at face_indices.size()).
  /// \throw Error(limit) if the counts do not fit the 32-bit handles.
  /// Numbering: vertices and faces keep their soup order; edges are sorted by
  /// their (smaller, larger) vertex pair and halfedge 2e runs from the smaller
  /// to the larger index; face f's stored halfedge leaves its first listed
  /// vertex; vertex v's stored halfedge is its lowest-numbered outgoing one.
  /// Complexity: O(n + V) in the number n of face corners and V of points.
  static Mesh from_soup(PolygonSoup soup);

  /// Number of vertices.
  [[nodiscard]] std::uint32_t num_vertices() const noexcept { return num_vertices_; }
  /// Number of halfedges (twice the number of edges).
  [[nodiscard]] std::uint32_t num_halfedges() const noexcept { return num_halfedges_; }
  /// Number of undirected edges.
  [[nodiscard]] std::uint32_t num_edges() const noexcept { return num_halfedges() / 2; }
  /// Number of faces.
  [[nodiscard]] std::uint32_t num_faces() const noexcept { return num_faces_; }

  /// All vertex handles, for range-for.
  [[nodiscard]] IdRange<VertexId> vertices() const { return IdRange<VertexId>(num_vertices()); }
  /// All halfedge handles, for range-for.
  [[nodiscard]] IdRange<HalfedgeId> halfedges() const { return IdRange<HalfedgeId>(num_halfedges()); }
  /// All edge handles, for range-for.
  [[nodiscard]] IdRange<EdgeId> edges() const { return IdRange<EdgeId>(num_edges()); }
  /// All face handles, for range-for.
  [[nodiscard]] IdRange<FaceId> faces() const { return IdRange<FaceId>(num_faces()); }

  /// The halfedges of face f in counterclockwise order (seen from outside).
  [[nodiscard]] HalfedgeCirculator face_halfedges(FaceId f) const {
    return {this, face_he_[f.index()], HalfedgeCirculator::Kind::face};
  }
  /// The halfedges leaving v, counterclockwise around v seen from outside.
  [[nodiscard]] HalfedgeCirculator outgoing_halfedges(VertexId v) const {
    return {this, vertex_he_[v.index()], HalfedgeCirculator::Kind::vertex};
  }

  /// The opposite halfedge: same edge, other direction, other face.
  [[nodiscard]] static HalfedgeId twin(HalfedgeId h) noexcept { return HalfedgeId(h.index() ^ 1u); }
  /// The undirected edge of h.
  [[nodiscard]] static EdgeId edge(HalfedgeId h) noexcept { return EdgeId(h.index() >> 1); }
  /// The first halfedge of e (from_soup: from the smaller to the larger vertex index).
  [[nodiscard]] static HalfedgeId halfedge(EdgeId e) noexcept { return HalfedgeId(e.index() << 1); }
  /// The halfedge after h in its face (counterclockwise from outside).
  [[nodiscard]] HalfedgeId next(HalfedgeId h) const noexcept { return he_next_[h.index()]; }
  /// The halfedge before h in its face.
  [[nodiscard]] HalfedgeId prev(HalfedgeId h) const noexcept { return he_prev_[h.index()]; }
  /// The vertex h points to.
  [[nodiscard]] VertexId to(HalfedgeId h) const noexcept { return he_to_[h.index()]; }
  /// The vertex h starts at.
  [[nodiscard]] VertexId from(HalfedgeId h) const noexcept { return he_to_[h.index() ^ 1u]; }
  /// The face on the left of h.
  [[nodiscard]] FaceId face(HalfedgeId h) const noexcept { return he_face_[h.index()]; }
  /// One halfedge of f.
  [[nodiscard]] HalfedgeId halfedge(FaceId f) const noexcept { return face_he_[f.index()]; }
  /// One halfedge leaving v.
  [[nodiscard]] HalfedgeId halfedge(VertexId v) const noexcept { return vertex_he_[v.index()]; }
  /// The number of vertices (and halfedges) of face f. O(degree).
  [[nodiscard]] std::uint32_t degree(FaceId f) const noexcept;

  /// The exact position of v. A mesh the library built from packed exact
  /// values (a sum's output) makes its Vec3s on the first call of this or
  /// positions(), once (safe from concurrent readers).
  /// \throw std::bad_alloc only then, if memory runs out.
  [[nodiscard]] const Vec3& position(VertexId v) const {
    return position_data_ != nullptr ? position_data_[v.index()] : made_positions()[v.index()];
  }
  /// All positions, indexed by vertex (made on first use, as for position()).
  [[nodiscard]] const std::vector<Vec3>& positions() const {
    return positions_ != nullptr ? *positions_ : made_positions();
  }

  /// Checks every stored reference (ranges, twin/next/prev/face/vertex
  /// consistency, face cycles, vertex fans) and closedness.
  /// \throw Error(topology) naming the first broken element.
  void validate() const;

  /// The mesh as points plus face index lists (faces in order, each starting
  /// at the face's stored halfedge).
  [[nodiscard]] PolygonSoup to_soup() const;

  /// The same connectivity with new vertex positions (one per vertex, in
  /// vertex order); no checks on the positions.
  /// \throw Error(invalid_argument) if the count differs from num_vertices().
  [[nodiscard]] Mesh with_positions(std::vector<Vec3> positions) const;

 private:
  // The library's own access: its unchecked constructors for outputs whose
  // points are distinct by construction, packed positions, raw arrays for
  // prefetching. Declared here only as a friend, so no user can name it;
  // defined inside the library (lib/mesh/mesh_access.hpp).
  friend struct MeshAccess;
  // The arrays, shared by copies; defined inside the library with MeshAccess.
  struct Storage;

  // positions() of a mesh that keeps its positions packed (made on first
  // use) or has none.
  [[nodiscard]] const std::vector<Vec3>& made_positions() const;
  void swap_with(Mesh& other) noexcept {
    storage_.swap(other.storage_);
    std::swap(positions_, other.positions_);
    std::swap(position_data_, other.position_data_);
    std::swap(vertex_he_, other.vertex_he_);
    std::swap(he_to_, other.he_to_);
    std::swap(he_next_, other.he_next_);
    std::swap(he_prev_, other.he_prev_);
    std::swap(he_face_, other.he_face_);
    std::swap(face_he_, other.face_he_);
    std::swap(num_vertices_, other.num_vertices_);
    std::swap(num_halfedges_, other.num_halfedges_);
    std::swap(num_faces_, other.num_faces_);
  }

  std::shared_ptr<const Storage> storage_;  // null for an empty mesh
  // Views into *storage_, so that every accessor is one load: the positions
  // (null when they are packed), and the connectivity.
  const std::vector<Vec3>* positions_ = nullptr;
  const Vec3* position_data_ = nullptr;
  const HalfedgeId* vertex_he_ = nullptr;  // one outgoing halfedge per vertex
  const VertexId* he_to_ = nullptr;
  const HalfedgeId* he_next_ = nullptr;
  const HalfedgeId* he_prev_ = nullptr;
  const FaceId* he_face_ = nullptr;
  const HalfedgeId* face_he_ = nullptr;
  std::uint32_t num_vertices_ = 0;
  std::uint32_t num_halfedges_ = 0;
  std::uint32_t num_faces_ = 0;
};

inline HalfedgeCirculator::iterator& HalfedgeCirculator::iterator::operator++() {
  h_ = (kind_ == Kind::face) ? mesh_->next(h_) : Mesh::twin(mesh_->prev(h_));
  if (h_ == start_) at_end_ = true;
  return *this;
}

}  // namespace cvms
