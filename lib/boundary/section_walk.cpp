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
