// SPDX-License-Identifier: MIT
// A convex polygon Q plus a polyhedron P, directly from Gaussian maps.
//
// Q's Gaussian map is its two facet normals +-m (the poles) and, for each
// edge e_i = q_{i+1} - q_i, the open great semicircle ("meridian") C_i from
// m to -m through the edge's in-plane outward normal o_i = e_i x m; the
// vertex q_j owns the open lune between the meridians of e_{j-1} and e_j.
// Seen from the pole, directions u have a longitude: the direction of u's
// projection on the plane orthogonal to m, here (m.m) u - (u.m) m in the
// plane's chart (plane_chart.hpp, orientation-preserving, so the o_i are in
// counterclockwise order and a binary search over them with orientation
// predicates finds the meridian or lune of any direction).
// The face of Q + P in direction u is F_Q(u) + F_P(u); the facets are:
//  - the poles: Q + F_P(m) and Q + F_P(-m), planar sums in the pole's chart
//    (F_P(+-m) a vertex, an edge or a facet of P);
//  - each facet f of P with n_f not +-m: f + q_j if n_f lies in the lune of
//    q_j, f + e_i (a stretched facet: a planar sum in f's plane) if it lies
//    on the meridian C_i;
//  - each edge g of P whose Gaussian arc crosses a meridian C_i at an
//    interior point of both: the parallelogram g + e_i. An arc not through a
//    pole spans a longitude interval of less than a half turn (the longitudes
//    of antipodal points differ by a half turn), monotonically, so it crosses
//    exactly the meridians whose longitudes are strictly inside the interval
//    from one end's longitude to the other's, a cyclic run of the sorted o_i
//    found by binary search. An arc through a pole or along a meridian
//    (g parallel to e_i) crosses none properly. The arc's ends are then on
//    strictly opposite sides of the plane u.e_i = 0 (a half turn of
//    longitude would be needed otherwise), so the parallelogram is oriented
//    as in segment_sum.cpp with e_i as the segment.
// Every vertex is q_j + p_v, named by the pair (distinct pairs used here are
// distinct points: a vertex of a sum has one decomposition). The facets'
// normals are pairwise different (the poles; facet normals of P other than
// the poles; interior points of arcs on meridians, where no two arcs and no
// two meridians meet), so no two facets are coplanar; each is a strictly
// convex polygon (a translate, a planar sum, a parallelogram of non-parallel
// edges) counterclockwise from outside. That is the guarantee of the trusted
// builder (polyhedron_builder.hpp), which checks the topology and computes
// the planes; re-verifying convexity (ConvexPolyhedron::from_soup) would
// cost four times the construction on a 1,000-gon + Sphere6. The tests
// compare every result with the exact hull of the pairwise vertex sums.
// The output facets are counted first, from the same binary searches
// (count_edge_facets), and checked against SumLimits before any is made.
// Cost: O((F + E) log |Q| + V) predicates plus the output and its check.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cvms/planar_sum.hpp"
#include "cvms/predicates.hpp"
#include "first_use.hpp"
#include "output_budget.hpp"
#include "plane_chart.hpp"
#include "polyhedron_builder.hpp"
#include "set_sum_parts.hpp"

namespace cvms::detail {

namespace {

// Longitudes around the polygon's normal and the meridians of its edges.
class Meridians {
 public:
  explicit Meridians(const ConvexSet& q) : m_(q.normal()), mm_(dot(m_, m_)), chart_(m_), q_(q.vertices()) {
    for (std::size_t i = 0; i < q_.size(); ++i) o_.push_back(chart_(cross(edge(i), m_)));
  }

  [[nodiscard]] std::size_t size() const { return q_.size(); }
  [[nodiscard]] const Vec3& vertex(std::size_t i) const { return q_[i % q_.size()]; }
  [[nodiscard]] Vec3 edge(std::size_t i) const { return vertex(i + 1) - vertex(i); }
  [[nodiscard]] const Vec2& meridian(std::size_t i) const { return o_[i % o_.size()]; }
  [[nodiscard]] const std::vector<Vec3>& cycle() const { return q_; }

  /// The longitude of u; zero iff u is parallel to m.
  [[nodiscard]] Vec2 longitude(const Vec3& u) const { return chart_(mm_ * u - dot(u, m_) * m_); }

  /// The first meridian strictly counterclockwise after d, counting from o_0
  /// (in 1..size(): every direction is at or after o_0).
  [[nodiscard]] std::size_t first_after(const Vec2& d) const {
    std::size_t lo = 0, hi = o_.size();  // o_[lo - 1] <= d < o_[hi] in turn order
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (before(d, o_[mid]))
        hi = mid;
      else
        lo = mid + 1;
    }
    return lo;
  }

 private:
  // Turn from o_0: [0, half) or [half, full).
  [[nodiscard]] int half(const Vec2& x) const {
    const Sign c = sign_cross2(o_[0], x);
    return c == Sign::positive || (c == Sign::zero && sign_dot(o_[0], x) == Sign::positive) ? 0 : 1;
  }
  [[nodiscard]] bool before(const Vec2& x, const Vec2& y) const {
    const int hx = half(x), hy = half(y);
    return hx != hy ? hx < hy : sign_cross2(x, y) == Sign::positive;
  }

  Vec3 m_;
  Rational mm_;
  PlaneChart chart_;
  std::vector<Vec3> q_;
  std::vector<Vec2> o_;
};

// The soup of Q + P: vertex (j, v) is q_j + p_v. Faces are kept as keys
// j |P| + v and numbered by first use at the end, by sorting (first_use.hpp:
// hashed, the keys of one v collide when |P| is a multiple of the bucket
// count).
class SumSoup {
 public:
  SumSoup(const Meridians& q, const ConvexPolyhedron& p) : q_(q), p_(p) {}

  [[nodiscard]] std::uint64_t vertex(std::size_t j, VertexId v) const {
    return std::uint64_t{j % q_.size()} * p_.num_vertices() + v.index();
  }
  void add_face(std::initializer_list<std::uint64_t> face) { add_face(std::vector<std::uint64_t>(face)); }
  void add_face(const std::vector<std::uint64_t>& face) {
    keys_.insert(keys_.end(), face.begin(), face.end());
    offsets_.push_back(static_cast<std::uint32_t>(keys_.size()));
  }
  PolygonSoup take() {
    FirstUse numbered = first_use(keys_, std::less<>{});
    PolygonSoup soup;
    soup.points.reserve(numbered.first.size());
    const std::uint64_t n = p_.num_vertices();
    for (std::size_t i : numbered.first)
      soup.points.push_back(q_.vertex(keys_[i] / n) + p_.vertex(VertexId(static_cast<std::uint32_t>(keys_[i] % n))));
    soup.face_offsets = std::move(offsets_);
    soup.face_indices = std::move(numbered.index);
    return soup;
  }

 private:
  const Meridians& q_;
  const ConvexPolyhedron& p_;
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> offsets_{0};
};

std::vector<Vec2> charted(const std::vector<Vec3>& points, const PlaneChart& chart) {
  std::vector<Vec2> flat;
  for (const Vec3& p : points) flat.push_back(chart(p));
  return flat;
}

// F_P(u): the facet with outward normal u if there is one (its cycle),
// else the one or two vertices with the largest dot product.
std::vector<VertexId> extreme_face(const ConvexPolyhedron& p, const Vec3& u) {
  const Mesh& m = p.mesh();
  const Vec3 n = primitive_direction(u);
  std::vector<VertexId> face;
  for (FaceId f : m.faces())
    if (p.normal(f) == n) {
      for (HalfedgeId h : m.face_halfedges(f)) face.push_back(m.from(h));
      return face;
    }
  VertexId best(0);
  for (VertexId v : m.vertices())
    if (compare_dot(p.vertex(v), p.vertex(best), u) == Sign::positive) best = v;
  for (VertexId v : m.vertices())
    if (compare_dot(p.vertex(v), p.vertex(best), u) == Sign::zero) face.push_back(v);
  return face;
}

// Q + F_P(pole) for pole = +-m, counterclockwise from the pole.
void add_pole_facet(SumSoup& soup, const Meridians& q, const ConvexPolyhedron& p, const Vec3& pole, bool reversed) {
  const std::vector<VertexId> face = extreme_face(p, pole);
  std::vector<Vec3> face_points, cycle = q.cycle();
  for (VertexId v : face) face_points.push_back(p.vertex(v));
  if (reversed) std::reverse(cycle.begin(), cycle.end());
  const PlaneChart chart(pole);
  std::vector<std::uint64_t> out;
  for (const auto& [i, j] : planar_sum_indices(charted(cycle, chart), charted(face_points, chart)))
    out.push_back(soup.vertex(reversed ? q.size() - 1 - i : i, face[j]));
  soup.add_face(out);
}

// f + F_Q(n_f) for a facet whose normal is not +-m.
void add_facet(SumSoup& soup, const Meridians& q, const ConvexPolyhedron& p, FaceId f, const Vec2& longitude) {
  const Mesh& m = p.mesh();
  const std::size_t last = q.first_after(longitude) - 1;  // the last meridian at or before n_f
  const bool on_meridian = sign_cross2(q.meridian(last), longitude) == Sign::zero;
  std::vector<std::uint64_t> out;
  if (!on_meridian) {
    for (HalfedgeId h : m.face_halfedges(f)) out.push_back(soup.vertex(last + 1, m.from(h)));
  } else {  // stretched along the edge e_last
    for (const auto& [v, end] : stretched_facet(p, f, q.vertex(last), q.vertex(last + 1)))
      out.push_back(soup.vertex(last + end, v));
  }
  soup.add_face(out);
}

// The longitudes of the ends of e's arc, counterclockwise; none if the arc
// turns by zero (through a pole, along a meridian, or a pole at an end).
std::optional<std::pair<Vec2, Vec2>> ccw_arc(const Mesh& m, EdgeId e, const std::vector<Vec2>& longitudes) {
  const HalfedgeId h0 = Mesh::halfedge(e);
  const Vec2& a = longitudes[m.face(h0).index()];
  const Vec2& b = longitudes[m.face(Mesh::twin(h0)).index()];
  const Sign turn = sign_cross2(a, b);
  if (turn == Sign::zero) return std::nullopt;
  return turn == Sign::positive ? std::pair{a, b} : std::pair{b, a};
}

// The parallelograms g + e_i for the meridians the arc of g's edge crosses.
void add_edge_facets(SumSoup& soup, const Meridians& q, const ConvexPolyhedron& p, EdgeId e,
                     const std::vector<Vec2>& longitudes) {
  const Mesh& m = p.mesh();
  const auto arc = ccw_arc(m, e, longitudes);
  if (!arc) return;
  const auto& [a, b] = *arc;
  const HalfedgeId h0 = Mesh::halfedge(e);
  for (std::size_t i = q.first_after(a), steps = 0; steps < q.size(); ++i, ++steps) {
    if (!ccw_in_between(q.meridian(i), a, b)) break;
    // h runs u -> w in the facet on the side of q_i (dot(n, e_i) < 0).
    const HalfedgeId h = sign_dot(p.normal(m.face(h0)), q.edge(i)) == Sign::negative ? h0 : Mesh::twin(h0);
    const VertexId u = m.from(h), w = m.to(h);
    soup.add_face({soup.vertex(i, w), soup.vertex(i, u), soup.vertex(i + 1, u), soup.vertex(i + 1, w)});
  }
}

// How many parallelograms add_edge_facets makes for e, without making them
// (the output is counted before it is built, SumLimits): the
// meridians strictly inside the arc's longitude interval (a, b) are the
// cyclic run from the first after a to the last at or before b, less the
// last if it is at b. Two binary searches.
std::uint64_t count_edge_facets(const Meridians& q, const Mesh& m, EdgeId e, const std::vector<Vec2>& longitudes) {
  const auto arc = ccw_arc(m, e, longitudes);
  if (!arc) return 0;
  const auto& [a, b] = *arc;
  const std::size_t n = q.size(), first = q.first_after(a), end = q.first_after(b);
  std::size_t count = (end % n + n - first % n) % n;  // meridians in (a, b]
  if (count > 0 && sign_cross2(q.meridian(end - 1), b) == Sign::zero) --count;
  return count;
}

}  // namespace

ConvexSet polygon_polyhedron_sum(const ConvexSet& polygon, const ConvexPolyhedron& p, const OutputBudget& budget,
                                 const std::string& what) {
  const Meridians q(polygon);
  const Mesh& m = p.mesh();
  std::vector<Vec2> longitudes;
  longitudes.reserve(m.num_faces());
  for (FaceId f : m.faces()) longitudes.push_back(q.longitude(p.normal(f)));
  const auto is_pole = [&](FaceId f) { return sgn(longitudes[f.index()].x) == 0 && sgn(longitudes[f.index()].y) == 0; };
  // The facets, counted before any is made: the two poles, P's facets that
  // are not poles, and the parallelograms.
  std::uint64_t facets = 2;
  for (FaceId f : m.faces()) facets += is_pole(f) ? 0 : 1;
  for (EdgeId e : m.edges()) facets = saturating_sum(facets, count_edge_facets(q, m, e, longitudes));
  budget.check_count(facets, "minkowski_sum (" + what + "): the sum has " + std::to_string(facets) + " facets");
  SumSoup soup(q, p);
  add_pole_facet(soup, q, p, polygon.normal(), false);
  add_pole_facet(soup, q, p, -polygon.normal(), true);
  for (FaceId f : m.faces())
    if (!is_pole(f)) add_facet(soup, q, p, f, longitudes[f.index()]);
  for (EdgeId e : m.edges()) add_edge_facets(soup, q, p, e, longitudes);
  return ConvexSet(detail::trusted_polyhedron(soup.take()));
}

}  // namespace cvms::detail
