// SPDX-License-Identifier: MIT
// Planar facets of a triangulated surface, certified so that the
// self-intersection test (self_intersection.hpp) may skip the pairs of
// triangles they prove apart. A big face cut into long thin triangles would
// otherwise give a quadratic number of candidate pairs: every thin triangle's
// box overlaps nearly every other, and every triangle along the face's rim.
//
// A facet is a class of triangles joined across edges that exactly two
// triangles share, in opposite directions, with the fourth point in the
// plane of the first three and on the other side of the edge: one plane, and
// one orientation of all its triangles in any chart of it. The unjoined edges
// of its triangles, directed as in their triangles, are its boundary. A facet
// is *certified* when it is one triangle, or when its boundary is one simple
// closed polygon (each vertex starts and ends one boundary edge, one cycle,
// closed edges meeting only where consecutive, and there only in their
// shared vertex). Proof of what a certified facet F gives:
//  - Winding: summing the boundaries of F's triangles, each joined edge
//    cancels (once each way), leaving the boundary polygon. So for a point p
//    on no edge of F, the winding number of the boundary about p is the sum
//    of the triangles' winding numbers, +-(the number of triangles containing
//    p) as all have one orientation; a simple polygon winds 0 or +-1 times
//    about p. Hence (1) the triangles' interiors are pairwise disjoint.
//  - (2) No vertex w of F lies inside an edge e of F (a T-junction). If e is
//    joined, the two triangles on it cover both sides of e near w, and the
//    interior of a triangle with corner w covers points near w a second
//    time. If e is a boundary edge and w is on the boundary, the polygon is
//    not simple. Otherwise every edge at w is joined, so the triangles around
//    w turn about it a whole number of full turns and cover both sides of e
//    near w, while beyond e (a simple polygon's edge, no other boundary edge
//    near its interior) the winding number is 0: covered and not, a
//    contradiction.
//  - (a) Two triangles of F meet only in shared vertices and edges: a common
//    point off their common ids would, by (1), lie on both boundaries: a
//    vertex of one inside an edge of the other, or two collinear edges
//    overlapping, which puts an endpoint of one inside the other; both are
//    T-junctions, excluded by (2) (equal points are one vertex).
//  - (b) A triangle t not in F's plane, in one closed half-space of it,
//    meets that plane in the hull of its corners on it: none, one vertex w
//    of F, or an edge [w1, w2] of F (these are the cases the test accepts).
//    By (1) and (2), a triangle s of F contains a point of an edge e of F
//    only if that point is a corner of s or s has e; so s and t have in
//    common only shared corners and a shared edge: they do not intersect in
//    the sense of triangle_intersection.hpp.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "cvms/vec.hpp"

namespace cvms::detail {

class PlanarFacets {
 public:
  /// The facets of the triangles (each of positive area, corners indices
  /// into points), each certified or not.
  PlanarFacets(std::span<const Vec3> points, std::span<const std::array<std::uint32_t, 3>> triangles);

  /// The facet of triangle t.
  [[nodiscard]] std::uint32_t of(std::uint32_t t) const { return of_triangle_[t]; }
  /// Whether facet f is certified (see the file header): then its triangles
  /// pairwise meet only in shared vertices and edges.
  [[nodiscard]] bool certified(std::uint32_t f) const { return certified_[f]; }
  /// The number of triangles of facet f.
  [[nodiscard]] std::uint32_t size(std::uint32_t f) const { return size_[f]; }
  /// For a certified facet f: true if triangle t provably meets no triangle
  /// of f other than in shared vertices and edges (case (b) of the header);
  /// false when undecided.
  [[nodiscard]] bool clears(std::uint32_t f, std::uint32_t t) const;

 private:
  [[nodiscard]] bool has_vertex(std::uint32_t f, std::uint32_t v) const;
  [[nodiscard]] bool has_edge(std::uint32_t f, std::uint32_t v, std::uint32_t w) const;

  std::span<const Vec3> points_;
  std::span<const std::array<std::uint32_t, 3>> triangles_;
  std::vector<std::uint32_t> of_triangle_;
  std::vector<std::uint32_t> first_triangle_;  // per facet: the triangle giving its plane
  std::vector<std::uint32_t> size_;
  std::vector<bool> certified_;
  std::vector<std::array<std::uint32_t, 2>> vertices_;  // sorted (facet, vertex)
  std::vector<std::array<std::uint32_t, 3>> edges_;     // sorted (facet, smaller id, larger id)
};

}  // namespace cvms::detail
