// SPDX-License-Identifier: MIT
// The support walk: the vertex of a convex set that maximises <x, u>, found by
// hill-climbing on its vertex graph ("walk, don't scan", DESIGN.md).
//
// Why the climb ends at a global maximum. Let P be a convex polytope, f(x) =
// <x, u>, and v a vertex with f(w) <= f(v) for every neighbour w of v. The
// cone at v spanned by the edges leaving v contains P (P is convex and v is a
// vertex: P - v lies in the cone of its edge directions), so every x in P is
// v + sum c_i (w_i - v) with c_i >= 0, and f(x) - f(v) = sum c_i (f(w_i) -
// f(v)) <= 0. Each step strictly increases f over a finite vertex set, so the
// climb ends; its length is at most the number of vertices and in practice
// the few steps between a nearby direction's answer and this one's.
//
// The walk is written against a vertex graph (exact positions with their
// approximations, and the neighbours of each vertex), not against the mesh,
// so that lower-dimensional convex sets (a polygon: its cycle; a segment: its
// two ends; a point) can use the same code: see VertexGraph below.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "filtered_predicates.hpp"
#include "polyhedron_builder.hpp"

namespace cvms::detail {

// What the walk needs of a convex set: `ref(v)`, the position of v with its
// approximation, and `for_each_neighbour(v, f)`, calling f(w) for every w
// joined to v by an edge. A polyhedron's graph is its mesh's edge graph.
struct PolyhedronGraph {
  const ConvexPolyhedron& p;
  // Not noexcept: a sum's vertices are made into Vec3s on first use (may throw bad_alloc).
  [[nodiscard]] Vec3Ref ref(VertexId v) const { return vertex_ref(p, v); }
  template <class F>
  void for_each_neighbour(VertexId v, F&& f) const {
    const Mesh& m = p.mesh();
    for (HalfedgeId h : m.outgoing_halfedges(v)) f(m.to(h));
  }
};

// The graph of a lower-dimensional set: a point (no edge), a segment (its
// two ends joined) or a polygon (its cycle, each vertex joined to the next
// and the previous). The climb's argument holds within the set's affine
// hull: the set minus a vertex lies in the cone of that vertex's one or two
// edges. `approx` approximates `points`, entry by entry.
struct CycleGraph {
  const std::vector<Vec3>& points;
  const std::vector<ApproxVec3>& approx;
  [[nodiscard]] Vec3Ref ref(VertexId v) const noexcept { return {points[v.index()], approx[v.index()]}; }
  template <class F>
  void for_each_neighbour(VertexId v, F&& f) const {
    const auto n = static_cast<std::uint32_t>(points.size());
    if (n < 2) return;
    f(VertexId((v.index() + 1) % n));
    if (n > 2) f(VertexId((v.index() + n - 1) % n));
  }
};

// The climb: from `start`, move to the first strictly better neighbour until
// none is. Returns a maximiser of <x, u>, or with `better` = negative a
// minimiser (a maximiser of <x, -u>, without building -u).
template <class Graph>
VertexId climb_to_maximum(const Graph& g, Vec3Ref u, VertexId start, Sign better_sign = Sign::positive) {
  VertexId v = start;
  for (bool improved = true; improved;) {
    improved = false;
    const Vec3Ref here = g.ref(v);
    VertexId better;
    g.for_each_neighbour(v, [&](VertexId w) {
      if (!better.is_valid() && compare_dot(g.ref(w), here, u) == better_sign) better = w;
    });
    if (better.is_valid()) {
      v = better;
      improved = true;
    }
  }
  return v;
}

// All maximisers, given one of them: the maximising face's vertices, sorted.
// The face is convex and its edges are edges of the set, so its vertices are
// connected through tied neighbours: a search over ties from the maximiser
// finds them all.
template <class Graph>
std::vector<VertexId> maximising_face(const Graph& g, Vec3Ref u, VertexId maximiser) {
  std::vector<VertexId> face{maximiser};
  for (std::size_t i = 0; i < face.size(); ++i) {
    const VertexId v = face[i];
    g.for_each_neighbour(v, [&](VertexId w) {
      if (std::find(face.begin(), face.end(), w) == face.end() &&
          compare_dot(g.ref(w), g.ref(v), u) == Sign::zero)
        face.push_back(w);
    });
  }
  std::sort(face.begin(), face.end());
  return face;
}

}  // namespace cvms::detail
