// SPDX-License-Identifier: MIT
// See interior_facets.hpp. Notation: for a convex polytope X and y in X,
// N_X(y) = {v : dot(v, w - y) <= 0 for all w in X} is X's normal cone at
// y; N_{X+Y}(y + z) = N_X(y) n N_Y(z), and a point whose normal cone is
// {0} is interior (a boundary point has a supporting plane, whose normal
// lies in the cone).
//
// The certificate. Let F be a facet of P = Q + B with outward normal n, S
// the corners of Q extreme in n and B_n the face of B extreme in n; then
// F = conv S + B_n and each x in the relative interior of F is y + z with
// y in relint conv S and z in relint B_n. Suppose |S| <= 2 and some face
// polygon Q' of A (Q' in dA, possibly Q) has every point of S among its
// corners, so y is in Q', and a corner w with dot(n, w - s) > 0 (s in S).
// Let v be in N_{Q'}(y) n N_B(z).
//  - |S| = 1: F = s + B_n is two-dimensional, so B_n is B's facet with
//    normal n and N_B(z) is the ray {t n : t >= 0}.
//  - |S| = 2: conv S is a segment e and y lies inside it, so v, making a
//    non-positive dot product with the two opposite vectors from y to e's
//    ends, is orthogonal to e. B_n is B's facet with normal n (as before)
//    or an edge e_B not parallel to e (F is two-dimensional; a vertex B_n
//    would make it a segment), with N_B(z) orthogonal to e_B. Then v is
//    orthogonal to e and e_B, so v = t n; and N_B(z) holds n but no line
//    (B is full-dimensional), so t >= 0.
// Either way v = t n with t >= 0, and dot(v, w - y) <= 0 with
// dot(n, w - y) = dot(n, w - s) > 0 forces t = 0. So x is interior to
// Q' + B, which lies in A + B. When the polygons do not meet edge to edge,
// a polygon may hold a point of S without having it as a corner: the
// certificate misses it there and is only found less often, never wrong.
// (|S| >= 3 is left alone: n is then +-Q's normal, or S holds a corner on
// the line of two others.)
//
// Nothing above asks more of Q' than to be a convex subset of A holding
// conv S, nor of B than to be convex and full-dimensional. So when the
// pieces are P_i + Q_j for convex decompositions of both operands, the
// same test certifies a facet from A's side (Q = P_i, Q' any piece of A's
// decomposition, Q_j in B's role) or from B's (the roles swapped).
//
// The inner translate (face polygons Q only, B convex). Let n_A be the
// outward normal of A where Q lies: Q's corners turn counterclockwise seen
// from its tip (facet_polygons.hpp), so a normal n of P = Q + B with every
// corner of Q extreme in it and the corners turning clockwise seen from n's
// tip points along -n_A. Its facet is F = Q + G, G the face of B least in
// n_A. Claim: x = y + z with z in G and y in relint Q on no side of A's
// triangles is interior to A + B.
//  - Near y, A is a closed half-ball on the side -n_A. y lies in A's
//    boundary (Q does), so inside one of A's triangles T and on no other
//    (A's triangles meet only along shared sides and at shared corners):
//    near y the boundary of A is T, and Q, two-dimensional at y and in
//    that boundary, lies in T's plane. Both open half-balls off that plane
//    miss the boundary, so each lies wholly inside or wholly outside A,
//    and A's outward normal there, n_A, puts A on the side -n_A. Nothing
//    is asked of Q's sides (they may run inside A's facet, Q need not meet
//    its neighbours edge to edge) nor of the sides and corners of A's
//    triangles, where A's parts may touch: y avoids them. So some r > 0
//    has y + a in A for every |a| < r with dot(a, n_A) <= 0.
//  - B rises from G: P is a convex polyhedron, full-dimensional, and Q is
//    flat, so B is not inside G's plane (a flat B would make P flat; the
//    road of solid_sum.cpp only takes a solid B, of positive volume).
//    Some p in B has u = p - z with dot(u, n_A) > 0, and z + t u is in B
//    for t in [0, 1] (B convex).
//  - For |d| small, t = max(0, dot(d, n_A) / dot(u, n_A)) is at most 1, and
//    a = d - t u has dot(a, n_A) <= 0 and |a| <= |d| (1 + |u| / dot(u, n_A)),
//    below r: x + d = (y + a) + (z + t u) lies in A + B.
// The points of relint F with no such y lie on finitely many segments. A
// point x of relint F is y + z for every y in the set Y = relint Q n
// (x - relint G) (relint F = relint Q + relint G), and Y must lie on the
// triangles' sides: it is open in Q's plane if G is a facet (never), an
// open segment parallel to G if G is an edge (then x is on s + G for a
// side s parallel to G), a point if G is a vertex (x on s + G for a side
// s). The outer translate, with normal +n_A, is left alone: there A and B
// both end on the side n_A, and the argument fails.
//
// The edge certificate (face polygons that are unions of A's triangles
// with all their corners, PolygonTiling::of_triangles). Let F be a facet
// of P = Q + B with outward normal n, S = {s0, s1} the corners of Q extreme
// in n (exactly two), so e = [s0, s1] is a side of Q with no corner of Q
// inside, and F = e + B_n; suppose exactly two polygons, Q and Q', have s0
// and s1 among their corners, and n points to the front of neither
// (dot(n, N) <= 0 for each one's outward normal N). Then relint F lies in
// the interior of A + B:
//  - Only two of A's triangles meet relint e, one in Q, one in Q', both
//    with side e. A triangle t of Q has side e (no corner of Q, hence of
//    its triangles, lies inside e). A's triangles (of positive area) meet
//    only along shared sides and at shared corners, so any triangle
//    meeting relint e there has side e, and its polygon has s0 and s1 among
//    its corners: it is Q or Q'. Q holds one such triangle (e is its side);
//    Q' one, or two if e were a diagonal of it; an edge of A has an even
//    number of triangles, so Q' holds one, e is a side of Q' too.
//  - So near y in relint e, A's boundary is two half-planes at the line of
//    e, Q's and Q''s, and A is the closed wedge W of points y + v with v in
//    one of the two sectors they bound (times the line of e), the one on
//    the back of both. n is orthogonal to e (F holds e) and lies in W: if
//    W is convex, it is the set of v with dot(v, N) <= 0 for both normals,
//    as n is; if not, the other sector without its rays is convex, the set
//    of v with dot(v, N) > 0 for both, and n is not in it.
//  - F is two-dimensional, so B_n is B's facet with normal n, or an edge
//    not parallel to e (a vertex would make F a segment): with z in
//    relint B_n, some g orthogonal to n and not parallel to e has z +- r g
//    in B for small r; and B is full-dimensional with B_n its face extreme
//    in n, so some w with dot(w, n) < 0 has z + r w in B (B convex).
//  - In the basis e' (along e), g, n, a step d from x = y + z is
//    a e' + b g + c n and w is w_e e' + w_g g + w_n n, w_n < 0. If c >= 0,
//    x + d = (y + a e' + c n) + (z + b g). If c < 0, with l = c / w_n > 0,
//    x + d = (y + (a - l w_e) e') + (z + (b - l w_g) g + l w). The steps
//    from y and z are O(|d|), so for |d| small the first point is in W,
//    hence in A, and the second in B (a convex combination of z, z +- r g
//    and z + r w): x + d lies in A + B.
// (Without the triangles' corners among the polygons' corners, a third
// polygon could hold part of e, as a side longer than e, unseen: then A's
// boundary near e is not known, and the certificate is not used.)
//
// Why skipping changes nothing. The pieces' covering regions are the same,
// so the only fragments lost are F's own: convex polygons of positive area
// in the boundary of the union U of the pieces, with relative interiors
// inside F's, so each holds points of the interior of A + B (all of it, or
// all but finitely many segments for an inner translate). Pieces of two
// decompositions: U is A + B, so F has no such fragment. Pieces f + B
// (solid_sum.cpp's road for a convex B): A + B = (A + b) u U, and a point x
// of dU inside A + B lies in A + b (the points near x outside U lie in it,
// and it is closed). dU never meets d(A + b), so the fragment, connected,
// lies wholly in the interior of A + b, where the sum drops it: the kept
// fragments, and the solid assembled from them, are the same.
//
// The incidence is by exact point: the corners of all polygons (or the
// vertices of all parts) sorted and numbered, each number listing the
// polygons that have it as a corner.
#include "interior_facets.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <numeric>

#include "approx.hpp"
#include "filtered_predicates.hpp"
#include "polyhedron_access.hpp"
#include "worker.hpp"

namespace cvms::detail {
namespace {

// The polygons' corners numbered by exact point, and the polygons at each.
class CornerIncidence {
 public:
  explicit CornerIncidence(std::span<const std::vector<Vec3>> polygons) {
    start_.push_back(0);
    std::vector<const Vec3*> all;
    for (const std::vector<Vec3>& polygon : polygons) {
      for (const Vec3& p : polygon) all.push_back(&p);
      start_.push_back(static_cast<std::uint32_t>(all.size()));
    }
    std::vector<std::uint32_t> order(all.size());
    std::iota(order.begin(), order.end(), 0U);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return *all[a] < *all[b]; });
    ids_.resize(all.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
      if (k == 0 || *all[order[k]] != *all[order[k - 1]]) {
        points_.push_back(all[order[k]]);
        approx_.push_back(ApproxVec3::of(*all[order[k]]));
      }
      ids_[order[k]] = static_cast<std::uint32_t>(points_.size() - 1);
    }
    polygons_at(polygons.size());
  }

  [[nodiscard]] std::span<const std::uint32_t> corners(std::size_t polygon) const {
    return {ids_.data() + start_[polygon], ids_.data() + start_[polygon + 1]};
  }
  [[nodiscard]] std::span<const std::uint32_t> polygons(std::uint32_t point) const {
    return {around_.data() + around_start_[point], around_.data() + around_start_[point + 1]};
  }
  [[nodiscard]] Vec3Ref point(std::uint32_t id) const { return {*points_[id], approx_[id]}; }

 private:
  // around_ lists the polygons at each point, in polygon order.
  void polygons_at(std::size_t count) {
    around_start_.assign(points_.size() + 1, 0);
    for (const std::uint32_t id : ids_) ++around_start_[id + 1];
    std::partial_sum(around_start_.begin(), around_start_.end(), around_start_.begin());
    std::vector<std::uint32_t> fill(around_start_.begin(), around_start_.end() - 1);
    around_.resize(ids_.size());
    for (std::uint32_t k = 0; k < count; ++k)
      for (const std::uint32_t id : corners(k)) around_[fill[id]++] = k;
  }

  std::vector<const Vec3*> points_;
  std::vector<ApproxVec3> approx_;
  std::vector<std::uint32_t> start_, ids_;
  std::vector<std::uint32_t> around_start_, around_;
};

// The corners of polygon k extreme in n, if at most two (else count 3),
// and whether every corner is extreme (n is normal to the polygon).
struct Extreme {
  std::array<std::uint32_t, 2> ids{};
  std::size_t count = 0;
  bool every = false;
};

Extreme extreme_corners(const CornerIncidence& incidence, std::size_t k, Vec3Ref n) {
  Extreme out;
  std::size_t tied = 0;
  for (const std::uint32_t id : incidence.corners(k)) {
    if (out.count == 0) {
      out.ids[0] = id;
      out.count = tied = 1;
      continue;
    }
    const Sign farther = compare_dot(incidence.point(id), incidence.point(out.ids[0]), n);
    if (farther == Sign::positive) {
      out.ids[0] = id;
      out.count = tied = 1;
    } else if (farther == Sign::zero) {
      if (out.count < 2) out.ids[out.count] = id;
      out.count = std::min<std::size_t>(out.count + 1, 3);
      ++tied;
    }
  }
  out.every = tied == incidence.corners(k).size();
  return out;
}

// The sign of dot(n, N) for polygon k's outward normal N, its corners
// turning counterclockwise seen from N's tip (facet_polygons.hpp): for the
// first corner c with c0, c1, c not on one line, det[n, c1 - c0, c - c0]
// has that sign (c0 -> c1 is a side of the convex polygon, so
// cross(c1 - c0, c - c0) is a positive multiple of N).
Sign facing(const CornerIncidence& incidence, std::size_t k, Vec3Ref n) {
  const std::span<const std::uint32_t> corners = incidence.corners(k);
  const Vec3Ref c0 = incidence.point(corners[0]), c1 = incidence.point(corners[1]);
  for (std::size_t i = 2; i < corners.size(); ++i) {
    const Vec3Ref c = incidence.point(corners[i]);
    if (!collinear(c0, c1, c)) return sign_triple_of_differences(n, c0, c1, c0, c);
  }
  return Sign::zero;  // unreachable for a polygon with three corners not on one line
}

// The certificates of the header that look at the polygons holding S.
struct Rules {
  bool at_edges = false;  // the edge certificate (polygons of A's triangles only)
};

// Whether some polygon has all of s among its corners and a corner farther
// than them in n or, with rules.at_edges and |S| = 2, exactly two polygons
// hold S and n points to the front of neither (the certificates of the
// header).
bool certified(const CornerIncidence& incidence, const Extreme& s, Vec3Ref n, Rules rules) {
  if (s.count > 2) return false;
  const Vec3Ref first = incidence.point(s.ids[0]);
  std::array<std::uint32_t, 2> holders{};
  std::size_t count = 0;
  for (const std::uint32_t q : incidence.polygons(s.ids[0])) {
    const std::span<const std::uint32_t> corners = incidence.corners(q);
    if (s.count == 2 && std::find(corners.begin(), corners.end(), s.ids[1]) == corners.end()) continue;
    if (count < 2) holders[count] = q;
    ++count;
    for (const std::uint32_t w : corners) {
      if (compare_dot(incidence.point(w), first, n) == Sign::positive) return true;
    }
  }
  return rules.at_edges && s.count == 2 && count == 2 && facing(incidence, holders[0], n) != Sign::positive &&
         facing(incidence, holders[1], n) != Sign::positive;
}

// The facets of one piece whose summand from A's side (parts of A) or,
// when `b` is given, from B's side (parts of B) certifies them; without
// `b`, A's parts are face polygons, and their inner translates are
// certified too.
std::vector<char> piece_mask(const ConvexPolyhedron& piece, const CornerIncidence& a, std::size_t a_part,
                             const CornerIncidence* b, std::size_t b_part, Rules rules) {
  const FacetPlanes& planes = PolyhedronAccess::planes(piece);
  const std::span<const Vec3> normals = planes.exact_normals();
  std::vector<char> mask(piece.num_facets(), 0);
  for (std::size_t f = 0; f < mask.size(); ++f) {
    const Vec3Ref n{normals[f], planes.normal_approx[f]};
    const Extreme s = extreme_corners(a, a_part, n);
    const bool inside = certified(a, s, n, rules) || (b == nullptr && s.every && facing(a, a_part, n) == Sign::negative) ||
                        (b != nullptr && certified(*b, extreme_corners(*b, b_part, n), n, rules));
    mask[f] = inside ? 1 : 0;
  }
  return mask;
}

// mask_of(k) for every piece k, over options.threads threads, each piece's
// mask in its own slot.
template <class MaskOf>
FacetMask masks_on_threads(std::size_t pieces, const Options& options, MaskOf&& mask_of) {
  FacetMask masks(pieces);
  constexpr std::size_t chunk = 64;
  std::atomic<std::size_t> next{0};
  run_on_threads(thread_count(options.threads, pieces / chunk + 1), [&](unsigned) {
    for (std::size_t begin = next.fetch_add(chunk); begin < pieces; begin = next.fetch_add(chunk)) {
      const std::size_t end = std::min(pieces, begin + chunk);
      for (std::size_t k = begin; k < end; ++k) masks[k] = mask_of(k);
    }
  });
  return masks;
}

}  // namespace

FacetMask interior_facets(std::span<const std::vector<Vec3>> polygons, std::span<const ConvexPolyhedron> pieces,
                          const Options& options, PolygonTiling tiling) {
  const CornerIncidence incidence(polygons);
  const Rules rules{tiling == PolygonTiling::of_triangles};
  return masks_on_threads(pieces.size(), options,
                          [&](std::size_t k) { return piece_mask(pieces[k], incidence, k, nullptr, 0, rules); });
}

FacetMask interior_facets_of_pairs(std::span<const std::vector<Vec3>> a_parts,
                                   std::span<const std::vector<Vec3>> b_parts,
                                   std::span<const ConvexPolyhedron> pieces, const Options& options) {
  const CornerIncidence a(a_parts), b(b_parts);
  const std::size_t m = b_parts.size();
  return masks_on_threads(pieces.size(), options,
                          [&](std::size_t k) { return piece_mask(pieces[k], a, k / m, &b, k % m, Rules{}); });
}

}  // namespace cvms::detail
