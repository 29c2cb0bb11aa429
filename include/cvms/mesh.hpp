// SPDX-License-Identifier: MIT
// Index-based half-edge mesh of a closed, consistently oriented 2-manifold
// polygon surface. Connectivity lives in plain arrays owned by the mesh;
// handles are typed 32-bit indices. Halfedges come in pairs: twin(h) = h ^ 1
// and the undirected edge of h is h >> 1. Faces are oriented counterclockwise
// seen from outside (for a closed surface: the orientation of the input).
#pragma once

#include <cstdint>
#include <iterator>
#include <limits>
#include <vector>

#include "cvms/polygon_soup.hpp"
#include "cvms/vec.hpp"

namespace cvms {

/// A typed 32-bit index, invalid by default.
template <class Tag>
class Handle {
 public:
  static constexpr std::uint32_t invalid_index = std::numeric_limits<std::uint32_t>::max();
  constexpr Handle() noexcept = default;
  constexpr explicit Handle(std::uint32_t index) noexcept : index_(index) {}
  [[nodiscard]] constexpr std::uint32_t index() const noexcept { return index_; }
  [[nodiscard]] constexpr bool is_valid() const noexcept { return index_ != invalid_index; }
  friend constexpr bool operator==(Handle a, Handle b) noexcept { return a.index_ == b.index_; }
  friend constexpr auto operator<=>(Handle a, Handle b) noexcept { return a.index_ <=> b.index_; }

 private:
  std::uint32_t index_ = invalid_index;
};

using VertexId = Handle<struct VertexTag>;
using HalfedgeId = Handle<struct HalfedgeTag>;
using EdgeId = Handle<struct EdgeTag>;
using FaceId = Handle<struct FaceTag>;

/// A range over the handles 0..n-1 of one kind, for range-for.
template <class Id>
class IdRange {
 public:
  class iterator {
   public:
    using value_type = Id;
    using difference_type = std::ptrdiff_t;
    iterator() = default;
    explicit iterator(std::uint32_t i) : i_(i) {}
    Id operator*() const { return Id(i_); }
    iterator& operator++() { ++i_; return *this; }
    iterator operator++(int) { iterator t = *this; ++i_; return t; }
    friend bool operator==(iterator a, iterator b) { return a.i_ == b.i_; }
   private:
    std::uint32_t i_ = 0;
  };
  explicit IdRange(std::uint32_t n) : n_(n) {}
  [[nodiscard]] iterator begin() const { return iterator(0); }
  [[nodiscard]] iterator end() const { return iterator(n_); }
  [[nodiscard]] std::uint32_t size() const { return n_; }
 private:
  std::uint32_t n_;
};

class Mesh;

/// The halfedges around a face (following next), or the outgoing halfedges of
/// a vertex (following twin(prev(h)), i.e. counterclockwise seen from outside).
class HalfedgeCirculator {
 public:
  enum class Kind { face, vertex };
  class iterator {
   public:
    using value_type = HalfedgeId;
    using difference_type = std::ptrdiff_t;
    iterator() = default;
    iterator(const Mesh* mesh, HalfedgeId h, Kind kind, bool at_end)
        : mesh_(mesh), h_(h), kind_(kind), at_end_(at_end) {}
    HalfedgeId operator*() const { return h_; }
    iterator& operator++();
    iterator operator++(int) { iterator t = *this; ++*this; return t; }
    friend bool operator==(const iterator& a, const iterator& b) {
      return a.h_ == b.h_ && a.at_end_ == b.at_end_;
    }
   private:
    const Mesh* mesh_ = nullptr;
    HalfedgeId h_;
    Kind kind_ = Kind::face;
    bool at_end_ = true;
  };
  HalfedgeCirculator(const Mesh* mesh, HalfedgeId start, Kind kind)
      : mesh_(mesh), start_(start), kind_(kind) {}
  [[nodiscard]] iterator begin() const { return {mesh_, start_, kind_, !start_.is_valid()}; }
  [[nodiscard]] iterator end() const { return {mesh_, start_, kind_, true}; }
 private:
  const Mesh* mesh_;
  HalfedgeId start_;
  Kind kind_;
};

class Mesh {
 public:
  Mesh() = default;

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
  /// Complexity: O(n log n) in the number of face corners.
  static Mesh from_soup(PolygonSoup soup);

  [[nodiscard]] std::uint32_t num_vertices() const noexcept { return static_cast<std::uint32_t>(positions_.size()); }
  [[nodiscard]] std::uint32_t num_halfedges() const noexcept { return static_cast<std::uint32_t>(he_to_.size()); }
  [[nodiscard]] std::uint32_t num_edges() const noexcept { return num_halfedges() / 2; }
  [[nodiscard]] std::uint32_t num_faces() const noexcept { return static_cast<std::uint32_t>(face_he_.size()); }

  [[nodiscard]] IdRange<VertexId> vertices() const { return IdRange<VertexId>(num_vertices()); }
  [[nodiscard]] IdRange<HalfedgeId> halfedges() const { return IdRange<HalfedgeId>(num_halfedges()); }
  [[nodiscard]] IdRange<EdgeId> edges() const { return IdRange<EdgeId>(num_edges()); }
  [[nodiscard]] IdRange<FaceId> faces() const { return IdRange<FaceId>(num_faces()); }

  /// The halfedges of face f in counterclockwise order (seen from outside).
  [[nodiscard]] HalfedgeCirculator face_halfedges(FaceId f) const {
    return {this, face_he_[f.index()], HalfedgeCirculator::Kind::face};
  }
  /// The halfedges leaving v, counterclockwise around v seen from outside.
  [[nodiscard]] HalfedgeCirculator outgoing_halfedges(VertexId v) const {
    return {this, vertex_he_[v.index()], HalfedgeCirculator::Kind::vertex};
  }

  [[nodiscard]] static HalfedgeId twin(HalfedgeId h) noexcept { return HalfedgeId(h.index() ^ 1u); }
  [[nodiscard]] static EdgeId edge(HalfedgeId h) noexcept { return EdgeId(h.index() >> 1); }
  [[nodiscard]] static HalfedgeId halfedge(EdgeId e) noexcept { return HalfedgeId(e.index() << 1); }
  [[nodiscard]] HalfedgeId next(HalfedgeId h) const noexcept { return he_next_[h.index()]; }
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
  [[nodiscard]] std::uint32_t degree(FaceId f) const noexcept;

  [[nodiscard]] const Vec3& position(VertexId v) const noexcept { return positions_[v.index()]; }
  [[nodiscard]] const std::vector<Vec3>& positions() const noexcept { return positions_; }

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
  std::vector<Vec3> positions_;
  std::vector<HalfedgeId> vertex_he_;  // one outgoing halfedge per vertex
  std::vector<VertexId> he_to_;
  std::vector<HalfedgeId> he_next_;
  std::vector<HalfedgeId> he_prev_;
  std::vector<FaceId> he_face_;
  std::vector<HalfedgeId> face_he_;
};

inline HalfedgeCirculator::iterator& HalfedgeCirculator::iterator::operator++() {
  HalfedgeId start = (kind_ == Kind::face) ? mesh_->halfedge(mesh_->face(h_)) : mesh_->halfedge(mesh_->from(h_));
  h_ = (kind_ == Kind::face) ? mesh_->next(h_) : Mesh::twin(mesh_->prev(h_));
  if (h_ == start) at_end_ = true;
  return *this;
}

}  // namespace cvms
