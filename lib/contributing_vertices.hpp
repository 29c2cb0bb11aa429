// SPDX-License-Identifier: MIT
// Contributing vertices (paper Section 4.2, Definition 1, Eq. 3): the vertices
// of a convex polyhedron that maximise <v, n> for the outward normal n of a
// facet of the other operand. Private to the library; shared by CVMS and the
// later slope-diagram algorithm.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cvms/convex_polyhedron.hpp"

namespace cvms::detail {

/// All vertices of q that maximise <v, n>, in increasing index order, by a
/// linear scan over the vertices of q (the paper-faithful search, O(v_q)
/// compare_dot predicates). The set is the vertex set of the face of q
/// supporting q in direction n: one vertex, the two ends of an edge
/// perpendicular to n, or the vertices of the facet of q whose outward
/// normal has the direction of n.
void maximising_vertices(const ConvexPolyhedron& q, Vec3Ref n, std::vector<VertexId>& out);

/// The facet of q incident to vertex v whose outward normal equals n, or an
/// invalid FaceId if there is none. Normals are primitive integer vectors, so
/// equal direction is equal vectors. Cost: the degree of v.
FaceId facet_with_normal(const ConvexPolyhedron& q, VertexId v, const Vec3& n);

/// The vertices of facet f of p, sorted by index.
void sorted_facet_vertices(const ConvexPolyhedron& p, FaceId f, std::vector<VertexId>& out);

/// Contributing vertices of every facet of one operand with respect to the
/// other, stored compactly (one sorted list per facet, facets in order).
class ContributingVertices {
 public:
  ContributingVertices() = default;
  explicit ContributingVertices(std::uint32_t num_facets) { offsets_.reserve(num_facets + 1u); }

  /// Appends the (sorted) list of the next facet.
  void append(std::span<const VertexId> sorted_vertices) {
    vertices_.insert(vertices_.end(), sorted_vertices.begin(), sorted_vertices.end());
    offsets_.push_back(static_cast<std::uint32_t>(vertices_.size()));
  }
  [[nodiscard]] std::span<const VertexId> of(FaceId f) const noexcept {
    return {vertices_.data() + offsets_[f.index()], offsets_[f.index() + 1u] - offsets_[f.index()]};
  }
  [[nodiscard]] std::uint32_t num_facets() const noexcept {
    return static_cast<std::uint32_t>(offsets_.size() - 1u);
  }

 private:
  std::vector<std::uint32_t> offsets_{0};
  std::vector<VertexId> vertices_;
};

/// True iff two sorted vertex lists have no vertex in common.
bool disjoint_sorted(std::span<const VertexId> x, std::span<const VertexId> y) noexcept;

/// Property 1 (paper Section 4.2), ties included: the edge of halfedge h of p
/// can produce edge facets only if its two facets have disjoint sets of
/// contributing vertices. (A common contributing vertex b means both facet
/// normals lie in the closed normal cone of b, hence the whole Gaussian arc of
/// the edge does, and a convex cone's interior and boundary arcs can only be
/// touched, never properly crossed, by an arc inside it.)
inline bool may_produce_edge_facets(const ConvexPolyhedron& p, const ContributingVertices& cv,
                                    HalfedgeId h) noexcept {
  const Mesh& m = p.mesh();
  return disjoint_sorted(cv.of(m.face(h)), cv.of(m.face(Mesh::twin(h))));
}

}  // namespace cvms::detail
