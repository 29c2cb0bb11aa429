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

FaceId facet_with_normal(const ConvexPolyhedron& q, VertexId v, Vec3Ref n) {
  const Mesh& m = q.mesh();
  for (HalfedgeId h : m.outgoing_halfedges(v)) {
    const FaceId f = m.face(h);
    if (provably_different(detail::normal_approx(q, f), n.approx)) continue;
    if (q.normal(f) == n.exact) return f;
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
  sorted_facet_vertices(q, facet_with_normal(q, v, n), out);
}

}  // namespace

void contributing_vertices_walk(const ConvexPolyhedron& p, const ConvexPolyhedron& q,
                                std::span<const FaceId> partner, ContributingVertices& out) {
  const Mesh& mp = p.mesh();
  const std::uint32_t nf = p.num_facets();
  // Facets in breadth-first order (the queue is the order itself). Each
  // climbs from the answer of its neighbour that was done last, not of the
  // one that queued it: all the neighbours of a facet of high degree are
  // queued by it, and climbing each from its answer would cross half the
  // operand every time (two n-gon prisms with perpendicular axes: the n side
  // facets of A, queued by a cap, climbed n/4 vertices of B each, O(n^2)).
  // The neighbour done last is usually the previous facet around that cap.
  std::vector<std::uint32_t> done_at(nf, 0);  // 1 + position in the order; 0: not done
  std::vector<VertexId> answer(nf);           // the first contributing vertex, once done
  std::vector<bool> queued(nf, false);
  std::vector<FaceId> queue;
  queue.reserve(nf);
  std::vector<VertexId> list;
  queue.push_back(FaceId(0));
  queued[0] = true;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const FaceId f = queue[head];
    const FaceId g = partner.empty() ? FaceId() : partner[f.index()];
    if (g.is_valid()) {
      sorted_facet_vertices(q, g, list);
    } else {
      VertexId seed(0);
      std::uint32_t latest = 0;
      for (HalfedgeId h : mp.face_halfedges(f)) {
        const std::uint32_t k = mp.face(Mesh::twin(h)).index();
        if (done_at[k] > latest) {
          latest = done_at[k];
          seed = answer[k];
        }
      }
      climb(q, detail::normal_ref(p, f), seed, list);
    }
    out.assign(f, list);
    answer[f.index()] = list.front();
    done_at[f.index()] = static_cast<std::uint32_t>(head + 1);
    for (HalfedgeId h : mp.face_halfedges(f)) {
      const FaceId next = mp.face(Mesh::twin(h));
      if (queued[next.index()]) continue;
      queued[next.index()] = true;
      queue.push_back(next);
    }
  }
  // The queue reaches every facet: a ConvexPolyhedron's surface is connected.
}

}  // namespace cvms::detail
