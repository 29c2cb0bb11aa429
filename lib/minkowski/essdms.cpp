// SPDX-License-Identifier: MIT
// ESSDMS: the Minkowski sum of two convex polyhedra by merging their slope
// diagrams, simplified with contributing vertices (paper Section 5.2), exact.
//
// Slope diagrams without a sphere. The slope diagram SD(P) is never built:
// the facet point of facet f is its exact outward normal n(f) (a primitive
// integer vector; only directions matter), the edge arc of an edge is the
// pair of facet points of its two facets, joined by the shorter great-circle
// arc (dihedral angles are below 180 degrees, so the two normals are never
// parallel), and the vertex region of a vertex is the spherical polygon of its
// facets' normals. Every test is the sign of a dot, cross or triple product
// of these vectors, decided by the predicates module.
//
// Arc convention (lib/minkowski/arc_crossing.hpp). For a halfedge h with
// d = to(h) - from(h), s = n(face(h)) and t = n(face(twin(h))), cross(s, t)
// is a positive multiple of d (checked by a test), so d serves as the pole n
// of Eqs. 8-9: the great circle of the arc is {x : <x, d> = 0} and x on it is
// strictly inside the arc iff det[s, x, d] > 0 and det[x, t, d] > 0.
//
// The merge handles the paper's four intersection cases in this order:
//  1. coincident facet points (Eq. 6: parallel normals, positive dot):
//     f_A + f_B (Eq. 7); the contributing vertices of each facet are the
//     vertices of the other.
//  2. a facet point strictly inside an edge arc of the other diagram (Eqs.
//     8-9): f + e (Eqs. 10-11); the contributing vertices of f are the ends
//     of e. A facet point at an end of an arc is a facet point of the other
//     diagram (case 1), hence the strict inequalities. A facet point lies
//     strictly inside at most one arc of the other diagram (the arcs of one
//     diagram meet only at facet points).
//  4. every other facet point lies strictly inside a vertex region: no
//     point-in-polygon query, its single contributing vertex (Eq. 3) is that
//     vertex, and the facet is translated by it. We do this before case 3
//     because case 3's pre-check needs the contributing vertices of every
//     facet, and case 3 never uses up a facet point, so the facets left after
//     cases 1-3 are exactly those left after cases 1-2.
//  3. two edge arcs crossing at a point interior to both: e_A + e_B (Eq. 12).
//     Pre-check (Property 1): an arc whose two facets share a contributing
//     vertex is dropped. Eq. 9 for a point on both arcs reduces to four
//     signs of dot products of facet points with the other arc's pole, which
//     also give the facet's outward normal sigma * cross(d_A, d_B)
//     (arc_crossing.hpp derives it): nothing is constructed per pair. Arcs
//     on one great circle give no facet, and an arc through a facet point of
//     the other diagram, or ending on the other arc, makes one of the four
//     signs zero: that contact is case 1 or 2, not an edge facet.
//
// Every facet of A yields a translated facet (case 1, 2 or 4), every facet of
// B not matched in case 1 a corner facet, and every crossing an edge facet;
// the facets go through the same planar sums and pair-keyed stitching as
// CVMS (stitch.hpp). Cost: O(f_A f_B + f_A e_B + f_B e_A + e_A' e_B' +
// f_A v_B + f_B v_A) predicates, e' counting the arcs that pass the
// pre-check (paper Section 6.2).
#include "essdms.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "arc_crossing.hpp"
#include "contributing_vertices.hpp"
#include "cvms/error.hpp"
#include "filtered_predicates.hpp"
#include "output_budget.hpp"
#include "polyhedron_builder.hpp"
#include "stitch.hpp"

namespace cvms::detail {
namespace {

// Where a facet point of one diagram lies in the other diagram.
enum class Location : std::uint8_t { unknown, on_facet_point, on_arc, in_vertex_region };

struct FacetPointLocation {
  Location where = Location::unknown;
  // The facet (on_facet_point), halfedge (on_arc) or vertex
  // (in_vertex_region) of the other operand.
  std::uint32_t feature = 0;
};

// The edge arcs of one slope diagram, one per edge (arc i is edge i): the
// arc of halfedges[i] runs from n(face(h)) to n(face(twin(h))) about its pole.
struct EdgeArcs {
  std::vector<HalfedgeId> halfedges;
  std::vector<Vec3> poles;
  std::vector<ApproxVec3> pole_approx;

  explicit EdgeArcs(const ConvexPolyhedron& p) {
    halfedges.reserve(p.num_edges());
    poles.reserve(p.num_edges());
    pole_approx.reserve(p.num_edges());
    for (EdgeId e : p.mesh().edges()) {
      const HalfedgeId h = Mesh::halfedge(e);
      halfedges.push_back(h);
      poles.push_back(p.edge_vector(h));
      pole_approx.push_back(ApproxVec3::of(poles.back()));
    }
  }
  [[nodiscard]] std::size_t size() const noexcept { return halfedges.size(); }
  [[nodiscard]] Vec3Ref pole(std::size_t i) const noexcept { return {poles[i], pole_approx[i]}; }
};

// Progress through the quadratic loops (cvms/progress.hpp): one stage whose
// units are the outer loops' iterations, case after case; `base` is where a
// case's iterations start. Each iteration scans `inner` features of the
// other polyhedron (a few nanoseconds each), so a report every
// pairs_per_report / inner iterations is a report every millisecond or so.
struct PairProgress {
  PairProgress(ProgressReporter& r, std::uint64_t b, std::uint64_t inner)
      : reporter(r),
        base(b),
        every(std::max<std::uint64_t>(1, pairs_per_report / std::max<std::uint64_t>(inner, 1))) {}
  void at(std::uint64_t i) const {
    if (i % every == 0) reporter.reach(base + i);
  }
  static constexpr std::uint64_t pairs_per_report = 1 << 16;
  ProgressReporter& reporter;
  std::uint64_t base;
  std::uint64_t every;
};

// Case 1 (Eqs. 6-7).
void coincident_facet_points(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                             std::vector<FacetPointLocation>& loc_a, std::vector<FacetPointLocation>& loc_b,
                             SumFacetBuilder& out, SumCounters& stats, PairProgress progress) {
  for (FaceId fa : a.mesh().faces()) {
    progress.at(fa.index());
    const Vec3Ref na = detail::normal_ref(a, fa);
    for (FaceId fb : b.mesh().faces()) {
      // The facet normals of one polyhedron are pairwise distinct, so a
      // matched facet of B cannot match again.
      if (loc_b[fb.index()].where != Location::unknown) continue;
      const Vec3Ref nb = detail::normal_ref(b, fb);
      if (!is_parallel(na, nb) || sign_dot(na, nb) != Sign::positive) continue;
      loc_a[fa.index()] = {Location::on_facet_point, fb.index()};
      loc_b[fb.index()] = {Location::on_facet_point, fa.index()};
      out.add_facet_plus_facet(fa, fb);
      stats.contributing_ties += 2;
      ++stats.translated_facets;
      break;
    }
  }
}

// Case 2 (Eqs. 8-11) for the facet points of p against the arcs of q.
void facet_points_on_arcs(Operand which, const ConvexPolyhedron& p, std::vector<FacetPointLocation>& loc,
                          const ConvexPolyhedron& q, const EdgeArcs& arcs_q, SumFacetBuilder& out,
                          SumCounters& stats, PairProgress progress) {
  const Mesh& mq = q.mesh();
  for (FaceId f : p.mesh().faces()) {
    progress.at(f.index());
    if (loc[f.index()].where != Location::unknown) continue;
    const Vec3Ref n = detail::normal_ref(p, f);
    for (std::size_t i = 0; i < arcs_q.size(); ++i) {
      const Vec3Ref pole = arcs_q.pole(i);
      if (sign_dot(n, pole) != Sign::zero) continue;  // Eq. 8: not on the great circle
      const HalfedgeId h = arcs_q.halfedges[i];
      const Vec3Ref s = detail::normal_ref(q, mq.face(h));
      const Vec3Ref t = detail::normal_ref(q, mq.face(Mesh::twin(h)));
      if (sign_triple(s, n, pole) != Sign::positive || sign_triple(n, t, pole) != Sign::positive)
        continue;  // Eq. 9
      loc[f.index()] = {Location::on_arc, h.index()};
      out.add_facet_plus_edge(which, f, mq.from(h), mq.to(h));
      ++stats.contributing_ties;
      ++(which == Operand::a ? stats.translated_facets : stats.corner_facets);
      break;
    }
  }
}

// Case 4: the facet points of p left over lie inside vertex regions of q.
void facet_points_in_vertex_regions(Operand which, const ConvexPolyhedron& p,
                                    std::vector<FacetPointLocation>& loc, const ConvexPolyhedron& q,
                                    SumFacetBuilder& out, SumCounters& stats, PairProgress progress) {
  std::vector<VertexId> cv;
  for (FaceId f : p.mesh().faces()) {
    progress.at(f.index());
    if (loc[f.index()].where != Location::unknown) continue;
    // One maximiser: two or more would put the facet point on an arc or a
    // facet point of q (the directions maximised by an edge of q are its
    // open arc, by a facet its facet point), where case 1 or 2 located it.
    maximising_vertices(q, detail::normal_ref(p, f), cv);
    loc[f.index()] = {Location::in_vertex_region, cv[0].index()};
    out.add_facet_plus_vertex(which, f, cv[0]);
    ++(which == Operand::a ? stats.translated_facets : stats.corner_facets);
  }
}

// The contributing vertices of every facet of p (in q), read off the
// locations found by cases 1, 2 and 4.
ContributingVertices contributing_vertices(const ConvexPolyhedron& p,
                                           const std::vector<FacetPointLocation>& loc,
                                           const ConvexPolyhedron& q) {
  const Mesh& mq = q.mesh();
  ContributingVertices cv(p.num_facets());
  std::vector<VertexId> list;
  for (FaceId f : p.mesh().faces()) {
    const FacetPointLocation l = loc[f.index()];
    switch (l.where) {
      case Location::on_facet_point:
        sorted_facet_vertices(q, FaceId(l.feature), list);
        break;
      case Location::on_arc: {
        const HalfedgeId h(l.feature);
        list = {mq.from(h), mq.to(h)};
        std::sort(list.begin(), list.end());
        break;
      }
      case Location::in_vertex_region:
        list = {VertexId(l.feature)};
        break;
      case Location::unknown:
        list.clear();  // unreachable: case 4 locates every remaining facet point
        break;
    }
    cv.append(list);
  }
  return cv;
}

// The arcs of p that pass the pre-check of case 3 (Property 1).
std::vector<std::uint32_t> arcs_passing_precheck(const ConvexPolyhedron& p, const EdgeArcs& arcs,
                                                 const ContributingVertices& cv) {
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < arcs.size(); ++i) {
    if (may_produce_edge_facets(p, cv, arcs.halfedges[i])) out.push_back(static_cast<std::uint32_t>(i));
  }
  return out;
}

// The pair tests of the quadratic loops, against SumLimits::max_pair_tests:
// checked before a loop starts, so a refused sum costs no pair test.
class PairWork {
 public:
  explicit PairWork(const SumLimits& limits) : max_(limits.max_pair_tests) {}

  // Adds the `pairs` of the next loop (`what` names them) and throws
  // Error(limit) if the total passes the limit.
  void add(std::uint64_t pairs, const char* what) {
    total_ = saturating_sum(total_, pairs);
    if (total_ <= max_) return;
    throw Error(ErrorCategory::limit, "minkowski_sum (essdms): " + std::string(what) + " bring its pair tests to " +
                                          std::to_string(total_) + ", beyond the limit of " +
                                          std::to_string(max_) + " (SumLimits::max_pair_tests)");
  }

 private:
  std::uint64_t max_;
  std::uint64_t total_ = 0;
};

// The pair tests of cases 1, 2 and 4: every facet of one operand against the
// facets, the arcs and the vertices of the other (in the worst case).
std::uint64_t location_pair_tests(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  const std::uint64_t fa = a.num_facets(), fb = b.num_facets();
  std::uint64_t total = saturating_product(fa, fb);
  total = saturating_sum(total, saturating_product(fa, b.num_edges()));
  total = saturating_sum(total, saturating_product(fb, a.num_edges()));
  total = saturating_sum(total, saturating_product(fa, b.num_vertices()));
  return saturating_sum(total, saturating_product(fb, a.num_vertices()));
}

// Case 3 (Eq. 12), by the reduction of Eq. 9 in arc_crossing.hpp. Stops
// once the edge facets found pass what the budget leaves them (checked per
// arc of A, so at most e_B' beyond it).
void crossing_edge_arcs(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const EdgeArcs& arcs_a,
                        const EdgeArcs& arcs_b, const std::vector<std::uint32_t>& ia,
                        const std::vector<std::uint32_t>& ib, const OutputBudget& budget, SumFacetBuilder& out,
                        SumCounters& stats, PairProgress progress) {
  const Mesh& ma = a.mesh();
  const std::uint64_t translated = stats.translated_facets, corner = stats.corner_facets;
  std::uint64_t found = 0;
  auto check = [&] { budget.check(translated, corner, found); };
  for (std::uint32_t i : ia) {
    check();
    progress.at(i);
    const HalfedgeId ha = arcs_a.halfedges[i];
    const ArcRef arc_a{detail::normal_ref(a, ma.face(ha)), detail::normal_ref(a, ma.face(Mesh::twin(ha))),
                       arcs_a.pole(i)};
    for (std::uint32_t j : ib) {
      const HalfedgeId hb = arcs_b.halfedges[j];
      ++stats.edge_candidates;
      const Sign sigma = proper_crossing(arc_a, b, hb, arcs_b.pole(j));
      if (sigma == Sign::zero) continue;
      out.add_edge_plus_edge(ha, hb, sigma);
      ++stats.edge_facets;
      ++found;
    }
  }
  check();
}

}  // namespace

ConvexPolyhedron essdms_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const SumLimits& limits,
                            SumCounters& stats, const ProgressCallback& callback) {
  PairWork work(limits);
  work.add(location_pair_tests(a, b), "the facet point locations (f_A f_B + f_A e_B + f_B e_A + f_A v_B + f_B v_A)");
  const OutputBudget budget(limits, "essdms");
  SumFacetBuilder out(a, b);
  std::vector<FacetPointLocation> loc_a(a.num_facets());
  std::vector<FacetPointLocation> loc_b(b.num_facets());
  const EdgeArcs arcs_a(a);
  const EdgeArcs arcs_b(b);

  ProgressReporter reporter(callback_of(callback));
  const std::uint64_t fa = a.num_facets(), fb = b.num_facets();
  reporter.begin("sum: pairs", 3 * fa + 2 * fb + arcs_a.size());
  // Case 4 walks to one maximiser: a few dozen steps an iteration.
  constexpr std::uint64_t walk = 64;
  // Case 1; case 2, f_A + e_B and f_B + e_A; case 4, f_A + v_B and f_B + v_A.
  coincident_facet_points(a, b, loc_a, loc_b, out, stats, {reporter, 0, fb});
  facet_points_on_arcs(Operand::a, a, loc_a, b, arcs_b, out, stats, {reporter, fa, arcs_b.size()});
  facet_points_on_arcs(Operand::b, b, loc_b, a, arcs_a, out, stats, {reporter, 2 * fa, arcs_a.size()});
  facet_points_in_vertex_regions(Operand::a, a, loc_a, b, out, stats, {reporter, 2 * fa + fb, walk});
  facet_points_in_vertex_regions(Operand::b, b, loc_b, a, out, stats, {reporter, 3 * fa + fb, walk});

  // Every facet of A and every unmatched facet of B is a facet of the sum:
  // counted before case 3, whose pairs are counted before it starts.
  budget.check(stats.translated_facets, stats.corner_facets, 0);
  const ContributingVertices cv_a = contributing_vertices(a, loc_a, b);
  const ContributingVertices cv_b = contributing_vertices(b, loc_b, a);
  const std::vector<std::uint32_t> ia = arcs_passing_precheck(a, arcs_a, cv_a);
  const std::vector<std::uint32_t> ib = arcs_passing_precheck(b, arcs_b, cv_b);
  work.add(saturating_product(ia.size(), ib.size()), "the arc pairs that pass the pre-check (e_A' e_B')");
  crossing_edge_arcs(a, b, arcs_a, arcs_b, ia, ib, budget, out, stats,
                     {reporter, 3 * fa + 2 * fb, ib.size()});  // case 3
  reporter.end();
  return out.build(1, &reporter);
}

}  // namespace cvms::detail
