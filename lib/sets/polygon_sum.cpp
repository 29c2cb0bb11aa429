// SPDX-License-Identifier: MIT
// A convex polygon Q plus a polyhedron P, directly from Gaussian maps.
//
// Q's Gaussian map is its two facet normals +-m (the poles) and, for each
// edge e_i = q_{i+1} - q_i, the open great semicircle ("meridian") C_i from
// m to -m through the edge's in-plane outward normal o_i = e_i x m; the
// vertex q_j owns the open lune between the meridians of e_{j-1} and e_j.
// Seen from the pole m, the o_i turn counterclockwise with i (Q is
// counterclockwise seen from m); positions count around the pole: 2j for
// the lune of q_j, 2i + 1 for the meridian C_i.
// Where a direction u sits is decided by signs of dot products only, never
// by constructing its projection: F_Q(u) is the vertex or edge of Q farthest
// along u, and u lies on C_i iff dot(u, e_i) = 0 with q_i, q_{i+1} farthest
// (dot(u, q_j) is unimodal around the strictly convex cycle, so a climb from
// a neighbour's answer finds it; three corners at one level mean u = +-m).
// Each sign is compare_dot on the corners' and normals' cached
// approximations (a few flops; exact only when the filter cannot decide).
// The face of Q + P in direction u is F_Q(u) + F_P(u); the facets are:
//  - the poles: Q + F_P(m) and Q + F_P(-m), planar sums in the pole's chart
//    (F_P(+-m) a vertex, an edge or a facet of P);
//  - each facet f of P with n_f not +-m: f + q_j if n_f lies in the lune of
//    q_j, f + e_i (a stretched facet: a planar sum in f's plane) if it lies
//    on the meridian C_i;
//  - each edge g of P whose Gaussian arc crosses a meridian C_i at an
//    interior point of both: the parallelogram g + e_i. The arc from n_f to
//    n_g (the facets of a halfedge h of g and of its twin) turns around m
//    with the sign of dot(n_f x n_g, m), and n_f x n_g is a positive multiple
//    of h's direction: the sign of dot(to(h) - from(h), m). Zero means an arc
//    through a pole or along a meridian (g parallel to e_i), which crosses
//    none properly. Otherwise the arc spans less than a half turn (the
//    longitudes of antipodal points differ by a half turn), monotonically,
//    so it crosses exactly the meridians whose positions are strictly
//    between its ends' positions, counterclockwise: a run of consecutive i.
//    The arc's ends are then on strictly opposite sides of the plane
//    u.e_i = 0 (a half turn would be needed otherwise), so the parallelogram
//    is oriented as in segment_sum.cpp with e_i as the segment.
// Every vertex is q_j + p_v, named by the pair (distinct pairs used here are
// distinct points: a vertex of a sum has one decomposition). The facets'
// normals are pairwise different (the poles; facet normals of P other than
// the poles; interior points of arcs on meridians, where no two arcs and no
// two meridians meet), so no two facets are coplanar; each is a strictly
// convex polygon (a translate, a planar sum, a parallelogram of non-parallel
// edges) counterclockwise from outside. That is the guarantee of the
// builder (polyhedron_builder.hpp: assemble), which checks the topology;
// re-verifying convexity (ConvexPolyhedron::from_soup) would cost four times
// the construction on a 1,000-gon + Sphere6. The planes the construction
// knows are given to it (the poles' +-m, P's facet normals on the facets
// f + q_j and f + e_i: both primitive outward normals, the values
// planes_from_first_corners would make): only the parallelograms' normals
// are made from their corners, which keeps the gcds of a small polygon + P
// to a fifth. The tests compare every result with the exact hull of the
// pairwise vertex sums.
// The output facets are counted first, from the same positions, and
// checked against SumLimits before any is made.
// Cost: O(F + E + V) predicates plus the climbs (O(|Q|) each, less when
// neighbouring facets of P sit close on Q's map) plus the output.
#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/planar_sum.hpp"
#include "cvms/predicates.hpp"
#include "dyadic.hpp"
#include "filtered_predicates.hpp"
#include "first_use.hpp"
#include "output_budget.hpp"
#include "plane_chart.hpp"
#include "polyhedron_builder.hpp"
#include "set_sum_parts.hpp"
#include "small_direction.hpp"

namespace cvms::detail {

namespace {

// A positive integer multiple of to - from in machine words: from the
// doubles when both points are doubles, else from one-word fractions; none
// when neither fits (the caller then takes the rational path).
std::optional<SmallDirection> small_direction(Vec3Ref from, Vec3Ref to) {
  if (auto d = small_integer_direction(from.approx, to.approx)) return d;
  return small_fraction_direction(from.exact, to.exact);
}

// Q's cycle with the approximations of its corners and of its normal m, and
// the walk that finds F_Q(u). Positions around the pole, counterclockwise:
// 2j for the open lune of q_j, 2i + 1 for the meridian C_i.
class Cycle {
 public:
  explicit Cycle(const ConvexSet& q)
      : m_(q.normal()),
        m_approx_(ApproxVec3::of(m_)),
        minus_m_(-m_),
        minus_m_approx_(ApproxVec3::of(minus_m_)),
        q_(q.vertices()) {
    approx_.reserve(q_.size());
    for (const Vec3& v : q_) approx_.push_back(ApproxVec3::of(v));
    directions_.reserve(q_.size());
    for (std::size_t i = 0; i < q_.size(); ++i) directions_.push_back(small_direction(ref(i), ref(i + 1)));
  }

  /// A positive integer multiple of e_i in machine words, if there is one.
  [[nodiscard]] const std::optional<SmallDirection>& direction(std::size_t i) const {
    return directions_[i % directions_.size()];
  }

  [[nodiscard]] std::size_t size() const { return q_.size(); }
  [[nodiscard]] const Vec3& vertex(std::size_t i) const { return q_[i % q_.size()]; }
  [[nodiscard]] const std::vector<Vec3>& cycle() const { return q_; }
  [[nodiscard]] Vec3Ref normal() const { return {m_, m_approx_}; }
  [[nodiscard]] Vec3Ref pole(bool reversed) const {
    return reversed ? Vec3Ref{minus_m_, minus_m_approx_} : Vec3Ref{m_, m_approx_};
  }

  /// Sign of dot(u, e_i): positive iff q_{i+1} is farther than q_i along u.
  [[nodiscard]] Sign rise(std::size_t i, Vec3Ref u) const { return compare_dot(ref(i + 1), ref(i), u); }

  /// The position of u, by climbing from the lune of q_start; none if u is a
  /// pole (parallel to m).
  [[nodiscard]] std::optional<std::size_t> position(Vec3Ref u, std::size_t start) const {
    const std::size_t k = q_.size();
    std::size_t j = start % k;
    // dot(u, q_j) is unimodal around the cycle (its level sets are lines
    // of Q's plane, each meeting the strictly convex boundary at most
    // twice), so every step strictly climbs and the walk ends at the top:
    // a vertex, or the first end of a top edge.
    for (std::size_t steps = 0; steps <= k; ++steps) {
      const Sign ahead = rise(j, u);
      if (ahead == Sign::positive) {
        j = (j + 1) % k;
        continue;
      }
      const Sign behind = rise(j + k - 1, u);
      if (behind == Sign::negative) {
        j = (j + k - 1) % k;
        continue;
      }
      // Three corners at one level: u is orthogonal to Q's plane.
      if (ahead == Sign::zero && behind == Sign::zero) return std::nullopt;
      return ahead == Sign::zero ? 2 * j + 1 : (behind == Sign::zero ? 2 * ((j + k - 1) % k) + 1 : 2 * j);
    }
    throw Error(ErrorCategory::invalid_argument, "polygon + polyhedron: the polygon is not strictly convex");
  }

 private:
  [[nodiscard]] Vec3Ref ref(std::size_t i) const { return {q_[i % q_.size()], approx_[i % q_.size()]}; }

  Vec3 m_;
  ApproxVec3 m_approx_;
  Vec3 minus_m_;
  ApproxVec3 minus_m_approx_;
  std::vector<Vec3> q_;
  std::vector<ApproxVec3> approx_;
  std::vector<std::optional<SmallDirection>> directions_;
};

// Where the facets of P sit on Q's Gaussian map: each facet's position (none
// for a pole); the arcs of P's edges and the meridians they cross follow
// from them.
struct GaussPlacement {
  std::vector<std::optional<std::size_t>> facet;  // by FaceId

  // The arc of e's edge, the facet at its counterclockwise start first; none
  // if it turns by zero (through a pole, along a meridian, or a pole at an
  // end). The turn from n_f to n_g (the faces of h and of its twin) has the
  // sign of dot(n_f x n_g, m) = dot(to(h) - from(h), m) up to a positive
  // factor, as n_f x n_g is a positive multiple of h's direction.
  [[nodiscard]] static std::optional<std::pair<FaceId, FaceId>> arc(const Cycle& q, const ConvexPolyhedron& p,
                                                                    EdgeId e) {
    const Mesh& m = p.mesh();
    const HalfedgeId h0 = Mesh::halfedge(e);
    const Sign turn = compare_dot(vertex_ref(p, m.to(h0)), vertex_ref(p, m.from(h0)), q.normal());
    if (turn == Sign::zero) return std::nullopt;
    const FaceId f = m.face(h0), g = m.face(Mesh::twin(h0));
    return turn == Sign::positive ? std::pair{f, g} : std::pair{g, f};
  }

  // The meridians strictly inside the arc from position a to position b
  // (neither a pole): the first, and how many (consecutive from it). Ends
  // in one lune cross none; ends on one meridian would not turn.
  [[nodiscard]] static std::pair<std::size_t, std::size_t> crossed(std::size_t a, std::size_t b,
                                                                   std::size_t k) {
    const std::size_t span = (b + 2 * k - a) % (2 * k);
    if (span == 0) return {0, 0};
    return {(a + 1) / 2, (span - a % 2) / 2};
  }
};

// Every facet's position, each climb starting from a neighbour's (the facets
// visited breadth first over P's edges): a climb then walks about as far as
// the arc between the two normals crosses meridians, so the climbs cost
// O(F + E) plus the output's parallelograms, not O(F |Q|).
GaussPlacement place(const Cycle& q, const ConvexPolyhedron& p) {
  GaussPlacement placement;
  const Mesh& m = p.mesh();
  placement.facet.assign(m.num_faces(), std::nullopt);
  std::vector<std::size_t> start(m.num_faces(), 0);
  std::vector<bool> seen(m.num_faces(), false);
  std::vector<FaceId> queue;
  queue.reserve(m.num_faces());
  for (FaceId root : m.faces()) {
    if (seen[root.index()]) continue;
    seen[root.index()] = true;
    queue.push_back(root);
    for (std::size_t next = queue.size() - 1; next < queue.size(); ++next) {
      const FaceId f = queue[next];
      auto& position = placement.facet[f.index()];
      position = q.position(normal_ref(p, f), start[f.index()]);
      const std::size_t from = position ? *position / 2 : start[f.index()];
      for (HalfedgeId h : m.face_halfedges(f)) {
        const FaceId g = m.face(Mesh::twin(h));
        if (seen[g.index()]) continue;
        seen[g.index()] = true;
        start[g.index()] = from;
        queue.push_back(g);
      }
    }
  }
  return placement;
}

// A face's outward primitive normal when the construction knows it: a
// normal of P or a pole (given), or a parallelogram's cross product of two
// small edge directions (small); neither: made from the face's corners.
struct FaceNormal {
  std::optional<Vec3Ref> given;
  std::optional<SmallNormal> small;
};

// The soup of Q + P: vertex (j, v) is q_j + p_v. Faces are kept as keys
// j |P| + v and numbered by first use at the end, by sorting (first_use.hpp:
// hashed, the keys of one v collide when |P| is a multiple of the bucket
// count).
class SumSoup {
 public:
  SumSoup(const Cycle& q, const ConvexPolyhedron& p) : q_(q), p_(p) {}

  [[nodiscard]] std::uint64_t vertex(std::size_t j, VertexId v) const {
    return std::uint64_t{j % q_.size()} * p_.num_vertices() + v.index();
  }
  /// Adds a face with what is known of its outward normal (FaceNormal).
  void add_face(std::initializer_list<std::uint64_t> face, const FaceNormal& normal) {
    add_face(std::vector<std::uint64_t>(face), normal);
  }
  void add_face(const std::vector<std::uint64_t>& face, const FaceNormal& normal) {
    keys_.insert(keys_.end(), face.begin(), face.end());
    offsets_.push_back(static_cast<std::uint32_t>(keys_.size()));
    normals_.push_back(normal);
  }
  [[nodiscard]] const std::vector<FaceNormal>& normals() const { return normals_; }
  /// The soup, its points' limbs kept in arena (in machine words when the
  /// coordinates allow: store_sum), each denominator's own limb given back
  /// as the point is made, so that the points cost no heap block each.
  PolygonSoup take(LimbArena& arena) {
    FirstUse numbered = first_use(keys_, std::less<>{});
    PolygonSoup soup;
    soup.points.reserve(numbered.first.size());
    const std::uint64_t n = p_.num_vertices();
    Rational scratch;
    for (std::size_t i : numbered.first) {
      const Vec3& a = q_.vertex(keys_[i] / n);
      const Vec3& b = p_.vertex(VertexId(static_cast<std::uint32_t>(keys_[i] % n)));
      Vec3& point = soup.points.emplace_back();
      for (int k = 0; k < 3; ++k) {
        LimbArena::give_back_denominator(point[k]);
        store_sum(arena, point[k], a[k], b[k], scratch);
      }
    }
    soup.face_offsets = std::move(offsets_);
    soup.face_indices = std::move(numbered.index);
    return soup;
  }

 private:
  const Cycle& q_;
  const ConvexPolyhedron& p_;
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> offsets_{0};
  std::vector<FaceNormal> normals_;
};

// The polyhedron of the soup with the normals the construction knows: the
// poles' +-m and P's facet normals stored as they are, the parallelograms'
// from the small edge directions, the rest from their first corners (each
// the unique primitive outward normal, the value planes_from_first_corners
// would make).
ConvexPolyhedron with_known_normals(PolygonSoup soup, const std::vector<FaceNormal>& known, LimbArena arena) {
  Mesh mesh = output_mesh(std::move(soup));
  VertexApproximations vertex_approx;
  vertex_approx.reserve(mesh.num_vertices());
  for (VertexId v : mesh.vertices()) vertex_approx.push_back(ApproxVec3::of(mesh.position(v)));
  const auto ref = [&](VertexId v) { return Vec3Ref{mesh.position(v), vertex_approx[v.index()]}; };
  FacetPlanes planes;
  planes.normal_approx.resize(mesh.num_faces());
  planes.normals.reserve(mesh.num_faces());
  Vec3 general;  // keeps its limbs from facet to facet
  for (FaceId f : mesh.faces()) {
    Vec3& normal = planes.normals.emplace_back();
    const FaceNormal& n = known[f.index()];
    if (n.given) {
      arena.store(normal, n.given->exact);
      planes.normal_approx[f.index()] = n.given->approx;
    } else if (n.small) {
      n.small->store(arena, normal);
      planes.normal_approx[f.index()] = n.small->approx();
    } else {
      const std::array<VertexId, 3> t = first_corners(mesh, f);
      primitive_normal(ref(t[0]), ref(t[1]), ref(t[2]), arena, general, normal,
                       planes.normal_approx[f.index()]);
    }
  }
  return assemble(std::move(mesh), std::move(vertex_approx), std::move(planes), std::move(arena));
}

std::vector<Vec2> charted(const std::vector<Vec3>& points, const PlaneChart& chart) {
  std::vector<Vec2> flat;
  for (const Vec3& p : points) flat.push_back(chart(p));
  return flat;
}

// F_P(u) for u = +-m: the facet with outward normal u if there is one (its
// cycle; a pole facet whose normal points along u), else the one or two
// vertices with the largest dot product.
std::vector<VertexId> extreme_face(const Cycle& q, const ConvexPolyhedron& p, const GaussPlacement& placement,
                                   bool reversed) {
  const Mesh& m = p.mesh();
  const Sign along = reversed ? Sign::negative : Sign::positive;
  std::vector<VertexId> face;
  for (FaceId f : m.faces())
    if (!placement.facet[f.index()] && sign_dot(normal_ref(p, f), q.normal()) == along) {
      for (HalfedgeId h : m.face_halfedges(f)) face.push_back(m.from(h));
      return face;
    }
  // compare_dot along -m is the opposite of compare_dot along m.
  const auto farther = [&](VertexId v, VertexId w) {
    const Sign s = compare_dot(vertex_ref(p, v), vertex_ref(p, w), q.normal());
    return reversed ? -s : s;
  };
  // Walk, don't scan: a linear function on a convex polyhedron has no
  // local maximum but the global one, so climbing along edges ends on the
  // farthest face, here a vertex or an edge (a facet was found above); an
  // edge's other end is the one neighbour at the same level.
  VertexId best(0);
  for (bool climbed = true; climbed;) {
    climbed = false;
    for (HalfedgeId h : m.outgoing_halfedges(best))
      if (farther(m.to(h), best) == Sign::positive) {
        best = m.to(h);
        climbed = true;
        break;
      }
  }
  face.push_back(best);
  for (HalfedgeId h : m.outgoing_halfedges(best))
    if (farther(m.to(h), best) == Sign::zero) face.push_back(m.to(h));
  // In index order, as the face's corners are listed for the planar sum.
  std::sort(face.begin(), face.end());
  return face;
}

// Q + F_P(pole) for pole = +-m, counterclockwise from the pole.
void add_pole_facet(SumSoup& soup, const Cycle& q, const ConvexPolyhedron& p, const GaussPlacement& placement,
                    bool reversed) {
  const std::vector<VertexId> face = extreme_face(q, p, placement, reversed);
  std::vector<Vec3> face_points, cycle = q.cycle();
  for (VertexId v : face) face_points.push_back(p.vertex(v));
  if (reversed) std::reverse(cycle.begin(), cycle.end());
  const Vec3Ref pole = q.pole(reversed);
  const PlaneChart chart(pole.exact);
  std::vector<std::uint64_t> out;
  for (const auto& [i, j] : planar_sum_indices(charted(cycle, chart), charted(face_points, chart)))
    out.push_back(soup.vertex(reversed ? q.size() - 1 - i : i, face[j]));
  soup.add_face(out, FaceNormal{pole, std::nullopt});
}

// f + F_Q(n_f) for a facet at `position` (not a pole).
void add_facet(SumSoup& soup, const Cycle& q, const ConvexPolyhedron& p, FaceId f, std::size_t position) {
  const Mesh& m = p.mesh();
  std::vector<std::uint64_t> out;
  if (position % 2 == 0) {  // in the lune of q_j
    for (HalfedgeId h : m.face_halfedges(f)) out.push_back(soup.vertex(position / 2, m.from(h)));
  } else {  // on the meridian C_i: stretched along the edge e_i
    const std::size_t i = position / 2;
    for (const auto& [v, end] : stretched_facet(p, f, q.vertex(i), q.vertex(i + 1)))
      out.push_back(soup.vertex(i + end, v));
  }
  const Vec3Ref normal = normal_ref(p, f);
  soup.add_face(out, FaceNormal{normal, std::nullopt});
}

// The meridians the arc of e's edge crosses: the first and how many.
std::pair<std::size_t, std::size_t> crossings(const Cycle& q, const ConvexPolyhedron& p,
                                              const GaussPlacement& placement, EdgeId e) {
  const auto arc = GaussPlacement::arc(q, p, e);
  if (!arc) return {0, 0};
  return GaussPlacement::crossed(*placement.facet[arc->first.index()], *placement.facet[arc->second.index()],
                                 q.size());
}

// The parallelograms g + e_i for the meridians the arc of g's edge crosses,
// counterclockwise from its start.
void add_edge_facets(SumSoup& soup, const Cycle& q, const ConvexPolyhedron& p,
                     const GaussPlacement& placement, EdgeId e) {
  const Mesh& m = p.mesh();
  const auto [first, count] = crossings(q, p, placement, e);
  const HalfedgeId h0 = Mesh::halfedge(e);
  if (count == 0) return;
  const std::optional<SmallDirection> d = small_direction(vertex_ref(p, m.from(h0)), vertex_ref(p, m.to(h0)));
  for (std::size_t i = first; i < first + count; ++i) {
    // h runs u -> w in the facet on the side of q_i (dot(n, e_i) < 0).
    const bool h0_on_q_i_side = q.rise(i, normal_ref(p, m.face(h0))) == Sign::negative;
    const HalfedgeId h = h0_on_q_i_side ? h0 : Mesh::twin(h0);
    const VertexId u = m.from(h), w = m.to(h);
    // The first corners q_i + p_w, q_i + p_u, q_{i+1} + p_u turn around
    // cross(p_u - p_w, e_i) = cross(e_i, w - u): the outward normal.
    FaceNormal normal;
    if (d && q.direction(i)) {
      normal.small = primitive_cross(*q.direction(i), *d);
      if (!h0_on_q_i_side) normal.small->negate();
    }
    soup.add_face({soup.vertex(i, w), soup.vertex(i, u), soup.vertex(i + 1, u), soup.vertex(i + 1, w)},
                  normal);
  }
}

}  // namespace

ConvexPolyhedron polygon_polyhedron_sum(const ConvexSet& polygon, const ConvexPolyhedron& p,
                                        const OutputBudget& budget, const std::string& what) {
  const Cycle q(polygon);
  const Mesh& m = p.mesh();
  const GaussPlacement placement = place(q, p);
  // The facets, counted before any is made: the two poles, P's facets that
  // are not poles, and the parallelograms.
  std::uint64_t facets = 2;
  for (FaceId f : m.faces()) facets += placement.facet[f.index()] ? 1 : 0;
  for (EdgeId e : m.edges()) facets = saturating_sum(facets, crossings(q, p, placement, e).second);
  budget.check_count(facets,
                     "minkowski_sum (" + what + "): the sum has " + std::to_string(facets) + " facets");
  SumSoup soup(q, p);
  add_pole_facet(soup, q, p, placement, false);
  add_pole_facet(soup, q, p, placement, true);
  for (FaceId f : m.faces())
    if (placement.facet[f.index()]) add_facet(soup, q, p, f, *placement.facet[f.index()]);
  for (EdgeId e : m.edges()) add_edge_facets(soup, q, p, placement, e);
  const std::vector<FaceNormal> normals = soup.normals();
  LimbArena arena;
  PolygonSoup sum = soup.take(arena);
  return with_known_normals(std::move(sum), normals, std::move(arena));
}

}  // namespace cvms::detail
