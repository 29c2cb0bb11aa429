// SPDX-License-Identifier: MIT
// Edge facets by tracing Gaussian arcs (output-sensitive CVMS, step 3 of
// paper Section 4.3; the "walk, don't scan" idea of DESIGN.md).
//
// The arc of an edge e_A runs from n1 = n(face(ha)) to n2 = n(face(twin(ha)))
// counterclockwise about d_A (cross(n1, n2) is a positive multiple of d_A),
// on the great circle G of directions perpendicular to d_A. Moving along G
// the point x has velocity d_A x x. For every x on G the face of B maximising
// <., x> is a vertex, except at finitely many events:
//  - G properly crosses the arc of an edge of B: the maximiser changes from
//    one end of the edge to the other. This is an edge facet when it happens
//    strictly inside the arc of e_A; these are what we report.
//  - G passes through the facet point n_F of a facet F of B parallel to d_A
//    (sign <n_F, d_A> = 0): the maximiser jumps across F. Strictly inside
//    the arc of e_A this is the corner facet F + e_A (step 2 built it), not
//    an edge facet.
//  - G runs along the arc of an edge of B parallel to d_A, between two such
//    facet points: that edge is the maximiser; parallel edges give no facet.
// Classify each facet F of B by s(F) = sign <n_F, d_A> (+ invisible,
// - visible, 0 parallel). Around a vertex u the facet normals form the
// convex spherical polygon P_u (u's normal cone), counterclockwise in the
// order of the facets around u seen from outside: for an outgoing halfedge h
// of u, face(twin(h)) comes just before face(h). G has the side s > 0 on its
// left, so it leaves a polygon it passes through where the boundary goes from
// the right side (-) to the left side (+): through the polygon edge of an
// outgoing halfedge h with s(face(twin(h))) = - and s(face(h)) = + (then the
// maximiser moves to to(h), and the edge facet is e_A + e_B with the outward
// normal cross(d_A, d_g), g = twin(h), oriented as in the paper's search), or
// through a polygon vertex n_F with s(F) = 0, F = face(h), after a - (a facet
// point event). Since G passes through the interior of P_u, the signs around
// u are one run of +, one run of -, and at most one 0 between them, so the
// exit is unique.
//
// At a facet point n_F the walk continues with the face of F maximising the
// tangent t = d_A x n_F: a vertex of F (whose polygon G then enters), or an
// edge of F parallel to d_A (G runs along its arc to the facet point of the
// facet on its other side, again parallel to d_A).
//
// Start: the maximiser at n1 is given by c1: one vertex (n1 inside its
// polygon), an edge (n1 inside its arc: start at the end that is higher in
// the direction of the tangent d_A x n1, or run along the arc if the edge is
// parallel to d_A), or a facet F (start at the event n_F). Stop: the face
// maximising n2 is given by c2, and the walk stops at the first vertex (or
// edge along G) that belongs to c2. It cannot stop early: c1 and c2 are
// disjoint (Property 1), and the walk moves forward from n1, so the first
// time it meets the region containing n2 is the one containing n2; every
// event before that lies strictly between n1 and n2 (an edge crossing at n2
// itself would need n2 in the interior of an arc, i.e. an edge in c2 whose
// first end the walk would have stopped at).
#include "arc_trace.hpp"

#include <algorithm>
#include <cstdint>
#include <string>

#include "contributing_vertices.hpp"
#include "cvms/error.hpp"
#include "dot_order_filter.hpp"
#include "dyadic.hpp"
#include "filtered_predicates.hpp"
#include "polyhedron_builder.hpp"

namespace cvms::detail {
namespace {

// The halfedge of f's boundary from u to w, or invalid.
HalfedgeId halfedge_between(const Mesh& m, FaceId f, VertexId u, VertexId w) {
  for (HalfedgeId h : m.face_halfedges(f)) {
    if (m.from(h) == u && m.to(h) == w) return h;
    if (m.from(h) == w && m.to(h) == u) return h;
  }
  return {};
}

// Where the walk is: at the maximiser u, or at the facet point event when
// that is valid. entered, when valid, is the outgoing halfedge of u through
// whose edge the walk came into u's cone: its facet is visible (-) and the
// facet on its other side invisible (+).
struct WalkPosition {
  VertexId u;
  FaceId event;
  HalfedgeId entered;
};

// Start (see the file comment): the maximiser at n1, given by c1.
WalkPosition start_of_walk(const ConvexPolyhedron& a, HalfedgeId ha, const ConvexPolyhedron& b,
                           std::span<const VertexId> c1, Vec3Ref da) {
  const Mesh& mb = b.mesh();
  const FaceId f1 = a.mesh().face(ha);
  WalkPosition at;
  if (c1.size() == 1) {
    at.u = c1[0];
  } else if (c1.size() == 2) {
    const Vec3 d = b.vertex(c1[1]) - b.vertex(c1[0]);
    const ApproxVec3 d_approx = ApproxVec3::of(d);
    // sign <d_A x n1, d> = det[d_A, n1, d].
    const Sign s = sign_triple(da, detail::normal_ref(a, f1), Vec3Ref{d, d_approx});
    if (s == Sign::positive) {
      at.u = c1[1];
    } else if (s == Sign::negative) {
      at.u = c1[0];
    } else {
      // The edge is parallel to d_A: G runs along its arc, from its facet
      // point on the left towards the end reached moving ccw about d_A.
      // (Two maximisers are the ends of the edge of B supporting B in
      // direction n1, so h is found.)
      HalfedgeId h;
      for (HalfedgeId g : mb.outgoing_halfedges(c1[0]))
        if (mb.to(g) == c1[1]) h = g;
      // The arc of h runs from n(face(h)) to n(face(twin(h))) ccw about d_h.
      at.event = sign_dot(Vec3Ref{d, d_approx}, da) == Sign::positive ? mb.face(Mesh::twin(h)) : mb.face(h);
    }
  } else {
    // Three or more maximisers span the facet of B supporting B in direction
    // n1 (an edge has only two vertices, all being extreme): its primitive
    // normal is n1's, and it is incident to c1[0].
    at.event = facet_with_normal(b, c1[0], detail::normal_ref(a, f1));
  }
  return at;
}

// The vertices of F maximising <., t> for the tangent t = d_A x n_F at the
// facet point n_F of F (parallel to d_A): best, and tie if an edge of F
// ties with it.
struct FacetMaximisers {
  VertexId best;
  VertexId tie;
};

FacetMaximisers maximisers_along_tangent(const ConvexPolyhedron& b, FaceId f, const Vec3& da) {
  const Vec3 t = cross(da, b.normal(f));
  const ApproxVec3 t_approx = ApproxVec3::of(t);
  const Vec3Ref t_ref{t, t_approx};
  FacetMaximisers m;
  for (HalfedgeId h : b.mesh().face_halfedges(f)) {
    const VertexId w = b.mesh().from(h);
    if (!m.best.is_valid()) {
      m.best = w;
      continue;
    }
    const Sign s = compare_dot(detail::vertex_ref(b, w), detail::vertex_ref(b, m.best), t_ref);
    if (s == Sign::positive) {
      m.best = w;
      m.tie = VertexId();
    } else if (s == Sign::zero) {
      m.tie = w;
    }
  }
  return m;
}

// The side of each facet F of b from d_A, s(F) = sign <n_F, d_A>: from the
// semi-static filter over b's normals (dot_order_filter.hpp: three products
// and a comparison) when it proves the sign, else from sign_dot. Both count
// as this thread's predicates, as the climbs' do.
class FacetSides {
 public:
  FacetSides(const ConvexPolyhedron& b, const PlaneFilterExtent& normals_extent, Vec3Ref da)
      : b_(b), da_(da), filter_(da.approx, normals_extent), counters_(predicate_counters()) {}

  Sign operator()(FaceId f) const {
    if (const std::optional<Sign> proved = filter_.sign(filter_.value(detail::normal_approx(b_, f)))) {
      ++counters_.filtered;
      return *proved;
    }
    return sign_dot(detail::normal_ref(b_, f), da_);
  }

 private:
  const ConvexPolyhedron& b_;
  Vec3Ref da_;
  DotOrderFilter filter_;
  PredicateCounters& counters_;
};

// The extent of b's normals' approximations, gathered once per scratch.
const PlaneFilterExtent& normals_extent(const ConvexPolyhedron& b, ArcTraceScratch& scratch) {
  if (scratch.normals_of != &b) {
    scratch.normals_extent = {};
    for (const ApproxVec3& n : PolyhedronAccess::planes(b).normal_approx) scratch.normals_extent.add(n);
    scratch.normals_of = &b;
  }
  return scratch.normals_extent;
}

// The way out of u's normal cone forwards (see the file comment): an
// outgoing halfedge h with s(face(twin(h))) = - and s(face(h)) = + (a
// crossing) or 0 (a facet point event); h is invalid if there is none.
struct ConeExit {
  HalfedgeId h;
  bool crossing = false;
};

//
// Each facet's side is worked out once: around u (h, then twin(prev(h))) the
// facet left of one halfedge is the facet right of the next. Where the walk
// came in through an edge, the sides of that edge's two facets are known and
// the search starts just after it, where the exit cannot be.
ConeExit leave_normal_cone(const ConvexPolyhedron& b, const WalkPosition& at, const FacetSides& side) {
  const Mesh& mb = b.mesh();
  HalfedgeId start;
  Sign right;
  if (at.entered.is_valid()) {
    start = Mesh::twin(mb.prev(at.entered));
    right = Sign::negative;  // the entered edge's own facet
  } else {
    start = mb.halfedge(at.u);
    right = side(mb.face(Mesh::twin(start)));
  }
  HalfedgeId h = start;
  do {
    const Sign left = side(mb.face(h));
    if (right == Sign::negative && left != Sign::negative) return {h, left == Sign::positive};
    right = left;
    h = Mesh::twin(mb.prev(h));
  } while (h != start);
  return {};
}

}  // namespace

void trace_edge_facets(const ConvexPolyhedron& a, HalfedgeId ha, const ConvexPolyhedron& b,
                       std::span<const VertexId> c1, std::span<const VertexId> c2, ArcTraceScratch& scratch,
                       std::uint64_t& steps) {
  const Mesh &ma = a.mesh(), &mb = b.mesh();
  Vec3& da = scratch.edge_direction;  // a.edge_vector(ha), in the scratch's limbs
  for (int i = 0; i < 3; ++i) subtract_into(da[i], a.vertex(ma.to(ha))[i], a.vertex(ma.from(ha))[i]);
  const ApproxVec3 da_approx = ApproxVec3::of(da);
  const Vec3Ref da_ref{da, da_approx};
  const FacetSides side(b, normals_extent(b, scratch), da_ref);
  auto in_c2 = [&](VertexId v) { return std::binary_search(c2.begin(), c2.end(), v); };

  // The walk ends: it only moves forward along G (each exit is unique, see
  // the file comment), past finitely many events, and stops in c2's region.
  // The bound on its steps costs one comparison a step and turns a bug into
  // an error instead of a hang.
  WalkPosition at = start_of_walk(a, ha, b, c1, da_ref);
  const std::uint64_t limit = std::uint64_t{mb.num_halfedges()} + mb.num_faces() + 4u;
  for (std::uint64_t step = 0;; ++step) {
    if (step > limit)
      throw Error(ErrorCategory::invalid_argument,
                  "minkowski_sum: internal error: the Gaussian arc walk of edge " +
                      std::to_string(Mesh::edge(ha).index()) + " of A did not end within " + std::to_string(limit) +
                      " steps");
    ++steps;
    if (at.event.is_valid()) {
      const FacetMaximisers m = maximisers_along_tangent(b, at.event, da);
      if (!m.tie.is_valid()) {
        at = {m.best, FaceId(), HalfedgeId()};
      } else {
        // An edge of F parallel to d_A: G runs along its arc to the facet
        // point of the facet on its other side. (A linear function on the
        // strictly convex polygon F is maximal at a corner or on a side, so
        // best and tie are the ends of a side and h is found.)
        if (in_c2(m.best) || in_c2(m.tie)) return;
        const HalfedgeId h = halfedge_between(mb, at.event, m.best, m.tie);
        at.event = mb.face(Mesh::twin(h));
        continue;
      }
    }
    if (in_c2(at.u)) return;
    // G passes through the interior of u's normal cone here, so the exit
    // exists (file comment).
    const ConeExit exit = leave_normal_cone(b, at, side);
    if (exit.crossing) {
      scratch.crossed.push_back(Mesh::twin(exit.h));
      at = {mb.to(exit.h), FaceId(), Mesh::twin(exit.h)};
    } else {
      at = {at.u, mb.face(exit.h), HalfedgeId()};
    }
  }
}

}  // namespace cvms::detail
