// SPDX-License-Identifier: MIT
// Contributing vertices (paper Section 4.2, Eq. 3): by linear scan (the
// paper's search) and by walking (hill-climbing from a neighbour's answer).
#include "contributing_vertices.hpp"

#include <algorithm>
#include <atomic>

#include "dot_order_filter.hpp"
#include "filtered_predicates.hpp"
#include "polyhedron_builder.hpp"
#include "prefetch_exact.hpp"
#include "worker.hpp"

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
//
// Each comparison is first tried by the semi-static filter over q's
// vertices (dot_order_filter.hpp, counted as a filtered decision like the
// running-error filter's), then by compare_dot.
void climb(const ConvexPolyhedron& q, const PlaneFilterExtent& extent, Vec3Ref n, VertexId start,
           std::vector<VertexId>& out, PredicateCounters& counters) {
  const Mesh& m = q.mesh();
  const DotOrderFilter by_dot(n.approx, extent);
  VertexId v = start;
  double v_value = by_dot.value(detail::vertex_approx(q, v));
  VertexId tied[2];
  std::size_t num_tied = 0;
  for (bool improved = true; improved;) {
    improved = false;
    num_tied = 0;
    for (HalfedgeId h : m.outgoing_halfedges(v)) {
      const VertexId w = m.to(h);
      const double w_value = by_dot.value(detail::vertex_approx(q, w));
      Sign s;
      if (const std::optional<Sign> proved = by_dot.compare(w_value, v_value)) {
        ++counters.filtered;
        s = *proved;
      } else {
        s = compare_dot(detail::vertex_ref(q, w), detail::vertex_ref(q, v), n);
      }
      if (s == Sign::positive) {
        v = w;  // strictly higher: <., n> increases at every move, so the climb ends
        v_value = w_value;
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

// The facets of p in breadth-first order from facet 0 over their adjacency
// (the queue is the order itself) and, for the facet at each position i, the
// latest position before i of a neighbour of it. Every facet but the first
// has one (the facet that queued it). The walk needs only these positions;
// finding them here, where the neighbours' positions are already loaded,
// spares it a second pass over every facet's neighbours (a third of the
// walk's samples on Cube + Sphere6, waiting on the random loads).
struct FacetOrder {
  static constexpr std::uint32_t none = UINT32_MAX;
  std::vector<FaceId> facets;
  std::vector<std::uint32_t> latest_neighbour;
};

FacetOrder breadth_first_facets(const Mesh& mp, std::uint32_t num_facets) {
  FacetOrder order;
  order.facets.reserve(num_facets);
  order.latest_neighbour.reserve(num_facets);
  std::vector<std::uint32_t> position(num_facets, FacetOrder::none);  // none: not queued yet
  order.facets.push_back(FaceId(0));
  position[0] = 0;
  for (std::uint32_t head = 0; head < order.facets.size(); ++head) {
    std::uint32_t latest = FacetOrder::none;
    for (HalfedgeId h : mp.face_halfedges(order.facets[head])) {
      const FaceId next = mp.face(Mesh::twin(h));
      const std::uint32_t at = position[next.index()];
      if (at == FacetOrder::none) {
        position[next.index()] = static_cast<std::uint32_t>(order.facets.size());
        order.facets.push_back(next);
      } else if (at < head && (latest == FacetOrder::none || at > latest)) {
        latest = at;
      }
    }
    order.latest_neighbour.push_back(latest);
  }
  // The queue reaches every facet: a ConvexPolyhedron's surface is connected.
  return order;
}

// Walks the facets order.facets[begin, end), handing each facet and its list
// to record(f, list) in that order. Each climbs from the answer of its
// neighbour in the same piece that was done last, not of the one that queued
// it: all the neighbours of a facet of high degree are queued by it, and
// climbing each from its answer would cross half the operand every time (two
// n-gon prisms with perpendicular axes: the n side facets of A, queued by a
// cap, climbed n/4 vertices of B each, O(n^2)). The neighbour done last is
// usually the previous facet around that cap. A facet with no such neighbour
// (all its neighbours done are in earlier pieces) climbs from the previous
// facet's answer; the piece's first facet from vertex 0. answer[i], the
// first vertex of the list of the facet at position i, is written for the
// piece's positions only, so pieces may run at once.
template <class Record>
void walk_piece(const ConvexPolyhedron& p, const ConvexPolyhedron& q, const PlaneFilterExtent& q_extent,
                std::span<const FaceId> partner, const FacetOrder& order, std::size_t begin, std::size_t end,
                std::span<VertexId> answer, Record&& record) {
  PredicateCounters& counters = predicate_counters();  // of the thread that walks the piece
  std::vector<VertexId> list;
  for (std::size_t i = begin; i < end; ++i) {
    // Breadth-first order visits p's normals out of index order: a climb
    // started by waiting for its direction's approximation (a third of the
    // climbs' time on Sphere6 + rot. Sphere6).
    if (i + prefetch_near < end) {
      const FaceId ahead = order.facets[i + prefetch_near];
      if (partner.empty() || !partner[ahead.index()].is_valid())
        prefetch_bytes(&detail::normal_approx(p, ahead), sizeof(ApproxVec3));
    }
    const FaceId f = order.facets[i];
    const FaceId g = partner.empty() ? FaceId() : partner[f.index()];
    if (g.is_valid()) {
      sorted_facet_vertices(q, g, list);
    } else {
      const std::uint32_t latest = order.latest_neighbour[i];  // positions [begin, i) are this piece's
      VertexId seed(0);
      if (latest != FacetOrder::none && latest >= begin) {
        seed = answer[latest];
      } else if (i > begin) {
        seed = answer[i - 1];
      }
      climb(q, q_extent, detail::normal_ref(p, f), seed, list, counters);
    }
    record(f, std::span<const VertexId>(list));
    answer[i] = list.front();
  }
}

}  // namespace

unsigned walk_pieces(std::uint32_t num_facets, std::uint32_t facets_per_piece) noexcept {
  const std::uint32_t pieces = facets_per_piece == 0 ? 1 : num_facets / facets_per_piece;
  return std::clamp<std::uint32_t>(pieces, 1, max_walk_pieces);
}

void contributing_vertices_walk(const ConvexPolyhedron& p, const ConvexPolyhedron& q,
                                std::span<const FaceId> partner, ContributingVertices& out, WalkSplit split) {
  const std::uint32_t nf = p.num_facets();
  if (nf == 0) return;
  const FacetOrder order = breadth_first_facets(p.mesh(), nf);
  PlaneFilterExtent q_extent;
  for (const ApproxVec3& a : PolyhedronAccess::approximations(q).vertices) q_extent.add(a);
  std::vector<VertexId> answer(nf);  // by position in the order: the first contributing vertex, once done
  const unsigned pieces = std::clamp(split.pieces, 1u, nf);
  if (pieces == 1) {
    walk_piece(p, q, q_extent, partner, order, 0, nf, answer,
               [&](FaceId f, std::span<const VertexId> list) { out.assign(f, list); });
    return;
  }
  std::vector<ContributingVertices> lists(pieces);
  const auto piece_begin = [&](unsigned k) { return std::size_t{nf} * k / pieces; };
  // Pieces handed out in order by an atomic counter: any number of threads
  // walks the same pieces from the same seeds, so the lists and the
  // predicates evaluated do not depend on it.
  std::atomic<unsigned> next{0};
  run_on_threads(std::min(split.threads, pieces), [&](unsigned) {
    for (unsigned k = next.fetch_add(1); k < pieces; k = next.fetch_add(1))
      walk_piece(p, q, q_extent, partner, order, piece_begin(k), piece_begin(k + 1), answer,
                 [&list = lists[k]](FaceId, std::span<const VertexId> vertices) { list.append(vertices); });
  });
  for (unsigned k = 0; k < pieces; ++k) {
    const std::size_t begin = piece_begin(k);
    for (std::size_t i = begin; i < piece_begin(k + 1); ++i)
      out.assign(order.facets[i], lists[k].of(FaceId(static_cast<std::uint32_t>(i - begin))));
  }
}

}  // namespace cvms::detail
