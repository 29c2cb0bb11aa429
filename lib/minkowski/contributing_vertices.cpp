// SPDX-License-Identifier: MIT
// Contributing vertices (paper Section 4.2, Eq. 3): by linear scan (the
// paper's search) and by walking (hill-climbing from a neighbour's answer).
#include "contributing_vertices.hpp"

#include <algorithm>

#include "filtered_predicates.hpp"
#include "polyhedron_builder.hpp"

namespace cvms::detail {

void maximising_vertices(const ConvexPolyhedron& q, Vec3Ref n, std::vector<VertexId>& out) {
  out.clear();
  for (VertexId v : q.mesh().vertices()) {
    if (out.empty()) {
      out.push_back(v);
      continue;
    }
    // Compare with the current maximiser only: all kept vertices tie with it.
    const Sign s = compare_dot(detail::vertex_ref(q, v), detail::vertex_ref(q, out.front()), n);
    if (s == Sign::positive) {
      out.clear();
      out.push_back(v);
    } else if (s == Sign::zero) {
      out.push_back(v);
    }
  }
}

FaceId facet_with_normal(const ConvexPolyhedron& q, VertexId v, const Vec3& n) {
  const Mesh& m = q.mesh();
  for (HalfedgeId h : m.outgoing_halfedges(v)) {
    const FaceId f = m.face(h);
    if (q.normal(f) == n) return f;
  }
  return {};
}

void sorted_facet_vertices(const ConvexPolyhedron& p, FaceId f, std::vector<VertexId>& out) {
  out.clear();
  const Mesh& m = p.mesh();
  for (HalfedgeId h : m.face_halfedges(f)) out.push_back(m.from(h));
  std::sort(out.begin(), out.end());
}

bool disjoint_sorted(std::span<const VertexId> x, std::span<const VertexId> y) noexcept {
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < x.size() && j < y.size()) {
    if (x[i] == y[j]) return false;
    if (x[i] < y[j]) {
      ++i;
    } else {
      ++j;
    }
  }
  return true;
}

namespace {

// The contributing vertices of q for direction n (the normal of a facet of
// the other operand), climbing from `start`. Leaves the sorted list in `out`.
//
// A vertex v has at most two neighbours tied with it: they lie with v in the
// plane H = {x : <x, n> = <v, n>}, and an edge of q from v inside H is a
// side, at its corner v, of the section of q by H (a polygon, or the face of
// q in H where H supports q). At the maximiser, two ties make v a corner of
// the facet of q in H, whose primitive normal is n: facet_with_normal finds
// it.
void climb(const ConvexPolyhedron& q, Vec3Ref n, VertexId start, std::vector<VertexId>& out) {
  const Mesh& m = q.mesh();
  VertexId v = start;
  VertexId tied[2];
  std::size_t num_tied = 0;
  for (bool improved = true; improved;) {
    improved = false;
    num_tied = 0;
    for (HalfedgeId h : m.outgoing_halfedges(v)) {
      const VertexId w = m.to(h);
      const Sign s = compare_dot(detail::vertex_ref(q, w), detail::vertex_ref(q, v), n);
      if (s == Sign::positive) {
        v = w;  // strictly higher: <., n> increases at every move, so the climb ends
        improved = true;
        break;
      }
      if (s == Sign::zero) tied[num_tied++] = w;
    }
  }
  out.clear();
  if (num_tied <= 1) {
    out.push_back(v);
    if (num_tied == 1) out.push_back(tied[0]);
    std::sort(out.begin(), out.end());
    return;
  }
  sorted_facet_vertices(q, facet_with_normal(q, v, n.exact), out);
}

}  // namespace

void contributing_vertices_walk(const ConvexPolyhedron& p, const ConvexPolyhedron& q,
                                std::span<const FaceId> partner, ContributingVertices& out) {
  const Mesh& mp = p.mesh();
  const std::uint32_t nf = p.num_facets();
  // seed[f]: a vertex of q to climb from, set when f is queued; the queue is
  // the BFS order itself.
  std::vector<VertexId> seed(nf);
  std::vector<FaceId> queue;
  queue.reserve(nf);
  std::vector<VertexId> list;
  seed[0] = VertexId(0);
  queue.push_back(FaceId(0));
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const FaceId f = queue[head];
    const FaceId g = partner.empty() ? FaceId() : partner[f.index()];
    if (g.is_valid()) {
      sorted_facet_vertices(q, g, list);
    } else {
      climb(q, detail::normal_ref(p, f), seed[f.index()], list);
    }
    out.assign(f, list);
    for (HalfedgeId h : mp.face_halfedges(f)) {
      const FaceId next = mp.face(Mesh::twin(h));
      if (seed[next.index()].is_valid()) continue;  // queued already (facet 0 has seed 0)
      seed[next.index()] = list.front();
      queue.push_back(next);
    }
  }
  // The queue reaches every facet: a ConvexPolyhedron's surface is connected.
}

}  // namespace cvms::detail
