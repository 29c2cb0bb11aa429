// SPDX-License-Identifier: MIT
// See section_walk.hpp.
#include "section_walk.hpp"

#include <algorithm>

#include "filtered_predicates.hpp"

namespace cvms::detail {
namespace {

class SectionWalk {
 public:
  SectionWalk(const PieceGeometry& q_geometry, const ClipPlane& plane, SectionScratch& scratch)
      : q_(*q_geometry.piece), mesh_(q_.mesh()), plane_(plane), scratch_(scratch) {
    const std::size_t n = q_.num_vertices();
    if (scratch_.stamps.size() < n) {
      scratch_.stamps.resize(n, 0);
      scratch_.sides.resize(n, 0);
    }
    if (++scratch_.stamp == 0) {
      std::fill(scratch_.stamps.begin(), scratch_.stamps.end(), 0);
      scratch_.stamp = 1;
    }
    scratch_.met = VertexId();
  }

  // The side of v, evaluated once per walk.
  int side_of(VertexId v) { return static_cast<int>(walked_side(scratch_, q_, v, plane_)); }

  // A halfedge from a vertex strictly inside the half-space to one
  // strictly outside; invalid if the piece is strictly on one side, or
  // nothing if a vertex on the plane was met.
  std::optional<HalfedgeId> crossing_edge(VertexId v) {
    const int sv = side_of(v);
    if (sv == 0) return met(v);
    for (std::uint32_t steps = 0; steps <= q_.num_vertices(); ++steps) {
      for (HalfedgeId h : mesh_.outgoing_halfedges(v)) {
        const VertexId u = mesh_.to(h);
        const int su = side_of(u);
        if (su == 0) return met(u);
        if (su != sv) return sv < 0 ? h : Mesh::twin(h);
      }
      const VertexId nearer = nearer_neighbour(v, sv);
      if (!nearer.is_valid()) return HalfedgeId();
      v = nearer;
    }
    return std::nullopt;
  }

  // A neighbour of v strictly nearer to the plane than v, v on side sv
  // (inside, sv < 0: nearer means farther along the normal); invalid if
  // none is. Any nearer neighbour serves the climb (it ends at the same
  // section whatever path it takes), so one the filter alone proves nearer
  // is taken first: an edge of v parallel to the plane, common where pieces
  // share directions, is an exact tie that only exact arithmetic decides,
  // and it is decided only if no other edge is proven to lead nearer.
  VertexId nearer_neighbour(VertexId v, int sv) {
    const Vec3Ref normal{*plane_.normal, *plane_.normal_approx};
    bool undecided = false;
    for (HalfedgeId h : mesh_.outgoing_halfedges(v)) {
      const VertexId u = mesh_.to(h);
      const std::optional<Sign> s = compare_dot_if_certain(vertex_ref(q_, u), vertex_ref(q_, v), normal);
      if (!s) undecided = true;
      else if (static_cast<int>(*s) == -sv) return u;
    }
    if (!undecided) return VertexId();
    for (HalfedgeId h : mesh_.outgoing_halfedges(v)) {
      const VertexId u = mesh_.to(h);
      if (static_cast<int>(compare_dot(vertex_ref(q_, u), vertex_ref(q_, v), normal)) == -sv) return u;
    }
    return VertexId();
  }

  // Goes round the section from `first` (inside to outside); false if a
  // vertex on the plane was met.
  bool go_round(HalfedgeId first) {
    scratch_.facets.clear();
    HalfedgeId e = first;
    for (std::uint32_t faces = 0; faces <= q_.num_facets(); ++faces) {
      scratch_.facets.push_back(mesh_.face(e).index());
      HalfedgeId out;
      for (HalfedgeId h = mesh_.next(e); h != e; h = mesh_.next(h)) {
        const int from = side_of(mesh_.from(h));
        const int to = side_of(mesh_.to(h));
        if (from == 0 || to == 0) {
          met(from == 0 ? mesh_.from(h) : mesh_.to(h));
          return false;
        }
        if (from > 0 && to < 0) out = h;
      }
      if (!out.is_valid()) return false;
      e = Mesh::twin(out);
      if (mesh_.face(e) == mesh_.face(first)) {
        std::sort(scratch_.facets.begin(), scratch_.facets.end());
        return true;
      }
    }
    return false;
  }

 private:
  // Remembers v, a vertex on the plane, for the caller; gives up the walk.
  std::nullopt_t met(VertexId v) {
    scratch_.met = v;
    return std::nullopt;
  }

  const ConvexPolyhedron& q_;
  const Mesh& mesh_;
  const ClipPlane& plane_;
  SectionScratch& scratch_;
};

}  // namespace

Sign walked_side(SectionScratch& scratch, const ConvexPolyhedron& q, VertexId v, const ClipPlane& plane) {
  const std::uint32_t i = v.index();
  if (scratch.stamps[i] != scratch.stamp) {
    scratch.stamps[i] = scratch.stamp;
    scratch.sides[i] = static_cast<std::int8_t>(side(vertex_ref(q, v), plane));
  }
  return static_cast<Sign>(scratch.sides[i]);
}

namespace {

// Queues the face of h unless it was queued since the last stamp.
void queue_face(SectionScratch& scratch, const Mesh& mesh, HalfedgeId h) {
  std::uint32_t& stamp = scratch.face_stamps[mesh.face(h).index()];
  if (stamp == scratch.face_stamp) return;
  stamp = scratch.face_stamp;
  scratch.queue.push_back(h);
}

// Whether face g meets the plane in a segment of positive length.
bool holds_segment(SectionScratch& scratch, const ConvexPolyhedron& q, FaceId g, const ClipPlane& plane) {
  bool outer = false;
  bool inner = false;
  std::uint32_t zeros = 0;
  std::uint32_t corners = 0;
  for (HalfedgeId h : q.mesh().face_halfedges(g)) {
    const Sign s = walked_side(scratch, q, q.mesh().to(h), plane);
    outer = outer || s == Sign::positive;
    inner = inner || s == Sign::negative;
    zeros += s == Sign::zero ? 1 : 0;
    ++corners;
  }
  return (outer && inner) || (zeros >= 2 && zeros < corners);
}

}  // namespace

void section_through_vertex(const PieceGeometry& q_geometry, VertexId v, const ClipPlane& plane,
                            SectionScratch& scratch) {
  const ConvexPolyhedron& q = *q_geometry.piece;
  const Mesh& mesh = q.mesh();
  if (scratch.face_stamps.size() < q.num_facets()) scratch.face_stamps.resize(q.num_facets(), 0);
  if (++scratch.face_stamp == 0) {
    std::fill(scratch.face_stamps.begin(), scratch.face_stamps.end(), 0);
    scratch.face_stamp = 1;
  }
  scratch.facets.clear();
  scratch.queue.clear();
  for (HalfedgeId out : mesh.outgoing_halfedges(v)) queue_face(scratch, mesh, out);
  for (std::size_t i = 0; i < scratch.queue.size(); ++i) {
    const FaceId g = mesh.face(scratch.queue[i]);
    if (!holds_segment(scratch, q, g, plane)) continue;
    scratch.facets.push_back(g.index());
    for (HalfedgeId h : mesh.face_halfedges(g)) {
      const Sign from = walked_side(scratch, q, mesh.from(h), plane);
      const Sign to = walked_side(scratch, q, mesh.to(h), plane);
      if ((from == Sign::positive && to == Sign::negative) || (from == Sign::negative && to == Sign::positive))
        queue_face(scratch, mesh, Mesh::twin(h));
      if (to == Sign::zero) {
        for (HalfedgeId out : mesh.outgoing_halfedges(mesh.to(h))) queue_face(scratch, mesh, out);
      }
    }
  }
  std::sort(scratch.facets.begin(), scratch.facets.end());
}

std::optional<bool> walk_section(const PieceGeometry& q_geometry, std::uint32_t piece_index, const ClipPlane& plane,
                                 SectionScratch& scratch) {
  SectionWalk walk(q_geometry, plane, scratch);
  std::uint32_t& start = scratch.start[piece_index];
  if (start >= q_geometry.piece->num_vertices()) start = 0;
  const std::optional<HalfedgeId> edge = walk.crossing_edge(VertexId(start));
  if (!edge) return std::nullopt;
  if (!edge->is_valid()) return false;
  if (!walk.go_round(*edge)) return std::nullopt;
  start = q_geometry.piece->mesh().from(*edge).index();
  return true;
}

}  // namespace cvms::detail
