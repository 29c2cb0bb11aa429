// SPDX-License-Identifier: MIT
// Contributing vertices (paper Section 4.2, Definition 1, Eq. 3): the vertices
// of a convex polyhedron that maximise <v, n> for the outward normal n of a
// facet of the other operand. Private to the library; shared by CVMS and the
// later slope-diagram algorithm.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "polyhedron_builder.hpp"

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
/// equal direction is equal vectors. Cost: the degree of v comparisons of
/// approximations, and exact ones only where those cannot tell.
FaceId facet_with_normal(const ConvexPolyhedron& q, VertexId v, Vec3Ref n);

/// The vertices of facet f of p, sorted by index.
void sorted_facet_vertices(const ConvexPolyhedron& p, FaceId f, std::vector<VertexId>& out);

/// Contributing vertices of every facet of one operand with respect to the
/// other, stored compactly (one sorted list per facet). Lists are appended
/// in facet order (append) or assigned to facets in any order (assign).
class ContributingVertices {
 public:
  ContributingVertices() = default;
  explicit ContributingVertices(std::uint32_t num_facets) { ranges_.reserve(num_facets); }

  /// Appends the (sorted) list of the next facet.
  void append(std::span<const VertexId> sorted_vertices) { ranges_.push_back(push(sorted_vertices)); }
  /// Sets the (sorted) list of facet f; facets below f not yet set get empty lists.
  void assign(FaceId f, std::span<const VertexId> sorted_vertices) {
    if (f.index() >= ranges_.size()) ranges_.resize(f.index() + 1u);
    ranges_[f.index()] = push(sorted_vertices);
  }
  [[nodiscard]] std::span<const VertexId> of(FaceId f) const noexcept {
    const Range r = ranges_[f.index()];
    return {vertices_.data() + r.begin, r.size};
  }
  [[nodiscard]] std::uint32_t num_facets() const noexcept {
    return static_cast<std::uint32_t>(ranges_.size());
  }

 private:
  struct Range {
    std::uint32_t begin = 0;
    std::uint32_t size = 0;
  };
  Range push(std::span<const VertexId> sorted_vertices) {
    const Range r{static_cast<std::uint32_t>(vertices_.size()),
                  static_cast<std::uint32_t>(sorted_vertices.size())};
    vertices_.insert(vertices_.end(), sorted_vertices.begin(), sorted_vertices.end());
    return r;
  }
  std::vector<Range> ranges_;
  std::vector<VertexId> vertices_;
};

/// How contributing_vertices_walk shares its work: the breadth-first order
/// is cut into `pieces` runs of facets, each climbing from its own seeds, so
/// that the lists and the predicates evaluated depend on the pieces alone;
/// up to `threads` threads walk them.
struct WalkSplit {
  unsigned pieces = 1;
  unsigned threads = 1;
};
/// The most pieces walk_pieces gives.
inline constexpr std::uint32_t max_walk_pieces = 8;
/// The pieces for num_facets facets: one per facets_per_piece (at least
/// one, at most max_walk_pieces), a function of the input alone.
[[nodiscard]] unsigned walk_pieces(std::uint32_t num_facets, std::uint32_t facets_per_piece) noexcept;
/// The contributing vertices of every facet of p with respect to q, found by
/// walking instead of scanning (output-sensitive CVMS): the facets of p are
/// visited in breadth-first order over their adjacency, and each facet's
/// maximiser is found by hill-climbing on the vertex graph of q from the
/// maximiser of a neighbouring facet done before it (in the same piece of
/// `split`). A linear function on a convex
/// polyhedron has no local maximum that is not global, so the climb (move to
/// any strictly better neighbour) ends at a maximiser v; the ties are then
/// v's neighbours with the same value: none (one contributing vertex), one
/// (an edge of q perpendicular to the normal) or two (then v lies on the
/// facet of q with the same normal, whose vertices are the list).
/// partner[f], if valid (and partner is non-empty), is a facet of q known to
/// have the normal of f: its vertices are taken without climbing.
/// The lists equal those of maximising_vertices exactly.
/// Cost: O(sum over facets of the climb length times the degrees met) predicates,
/// in practice O(f_p + v_q) for operands of similar resolution.
void contributing_vertices_walk(const ConvexPolyhedron& p, const ConvexPolyhedron& q,
                                std::span<const FaceId> partner, ContributingVertices& out,
                                WalkSplit split = {});

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
