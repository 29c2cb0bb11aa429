// SPDX-License-Identifier: MIT
// intersection_polyhedron (intersection_polyhedron.hpp has the argument).
// The trusted builder takes the planes as they are; they equal the ones
// planes_from_first_corners would compute: the outward primitive integer normal of
// a plane is unique, and the offset is its value on the plane.
//
// Why the walk below runs counterclockwise. At a dual vertex q, a dual facet
// f holds q with its corners ... p, q, s ... counterclockwise seen from
// outside; the facet across the edge p–q holds it as ... q, p ..., and that
// facet follows f counterclockwise around q seen from outside (f lies to the
// left of p → q, the other one to its right). Around a vertex of a convex
// polytope, seen from outside, its facets and their outward normals turn
// the same way (the facets' cone at q and its normal cone are polar); the
// primal vertices of these facets are n_f / c_f (from_halfspaces.cpp), with
// c_f > 0, so seen along q — the primal facet's outward normal — they turn
// the same way too: the walk gives the primal facet counterclockwise.
#include "intersection_polyhedron.hpp"

#include <algorithm>
#include <limits>
#include <span>
#include <tuple>
#include <utility>

#include "cvms/error.hpp"
#include "polyhedron_builder.hpp"

namespace cvms::detail {
namespace {

// Dual vertex `row` as a corner of dual facet (= primal vertex) `vertex`,
// with its neighbours in the facet's counterclockwise cycle.
struct Corner {
  std::uint32_t row, next, previous, vertex;
};

bool before(const Corner& a, const Corner& b) { return std::tie(a.row, a.next) < std::tie(b.row, b.next); }
bool next_before(const Corner& a, const Corner& b) { return a.next < b.next; }

// Every corner of every dual facet, grouped by row (rows in increasing
// order) and, within a row, by the next corner: placed by row with a
// counting pass, then each row's few corners sorted, instead of sorting all
// corners (on Sphere5's 25,600 corners, 7.5 → 2 M instructions).
std::vector<Corner> sorted_corners(const DualVertices& v) {
  std::vector<std::uint32_t> start(v.dual.points.size() + 1, 0);
  for (const std::uint32_t row : v.tight) ++start[row + 1];
  for (std::size_t r = 1; r < start.size(); ++r) start[r] += start[r - 1];
  std::vector<Corner> corners(v.tight.size());
  std::vector<std::uint32_t> cursor(start.begin(), start.end() - 1);
  for (std::uint32_t vertex = 0; vertex + 1 < v.tight_offsets.size(); ++vertex) {
    const std::uint32_t begin = v.tight_offsets[vertex], end = v.tight_offsets[vertex + 1];
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t next = i + 1 == end ? begin : i + 1, previous = i == begin ? end - 1 : i - 1;
      corners[cursor[v.tight[i]]++] = {v.tight[i], v.tight[next], v.tight[previous], vertex};
    }
  }
  for (std::size_t r = 0; r + 1 < start.size(); ++r)
    std::sort(corners.begin() + start[r], corners.begin() + start[r + 1], next_before);
  return corners;
}

// The plane a·x == b of row r as an outward primitive integer normal and
// its offset, their limbs in arena: the primitive row divided by the gcd c
// of its normal (in `quotient`, whose limbs are reused from row to row).
// The offset b / c needs no reduction: the row is primitive, so gcd(b, c) =
// gcd(a_x, a_y, a_z, b) = 1. A content that is a power of two (rows with
// dyadic offsets, scaled to integers) divides by a shift.
void add_plane(const DualVertices& v, std::uint32_t r, FacetPlanes& planes, LimbArena& arena,
               mpz_class& quotient) {
  const HomogeneousPoint& a = v.dual.points[r];
  const mpz_srcptr content = v.dual.normal_contents[r].get_mpz_t();
  const bool reduce = mpz_cmp_ui(content, 1) != 0;
  const mp_bitcnt_t twos = reduce ? mpz_scan1(content, 0) : 0;
  const bool power_of_two = reduce && twos + 1 == mpz_sizeinbase(content, 2);
  const mp_limb_t one_limb = 1;
  mpz_t one;
  mpz_roinit_n(one, &one_limb, 1);
  Vec3& n = planes.normals.emplace_back();
  const mpz_class* row[3] = {&a.x, &a.y, &a.z};
  for (int m = 0; m < 3; ++m) {
    mpz_srcptr numerator = row[m]->get_mpz_t();
    if (reduce) {
      if (power_of_two)
        mpz_tdiv_q_2exp(quotient.get_mpz_t(), numerator, twos);
      else
        mpz_divexact(quotient.get_mpz_t(), numerator, content);
      numerator = quotient.get_mpz_t();
    }
    arena.store(n[m], numerator, one);
  }
  arena.store(planes.offsets.emplace_back(), v.dual.offsets[r].get_mpz_t(), content);
  planes.normal_approx.push_back(ApproxVec3::of(n));
}

// points[k] = the old points[order[k]] for every k, by swaps (a rational's swap
// exchanges pointers; its move would allocate a denominator). order is a
// permutation.
void gather(std::vector<Vec3>& points, const std::vector<std::uint32_t>& order) {
  std::vector<bool> placed(order.size(), false);
  for (std::size_t start = 0; start < order.size(); ++start) {
    // Along the cycle through start, each swap puts one point in place and
    // carries the displaced one on, until the point the cycle closes with
    // is the one that start held.
    std::size_t k = start;
    while (!placed[k] && order[k] != start) {
      for (int m = 0; m < 3; ++m) mpq_swap(points[k][m].get_mpq_t(), points[order[k]][m].get_mpq_t());
      placed[k] = true;
      k = order[k];
    }
    placed[k] = true;
  }
}

}  // namespace

ConvexPolyhedron intersection_polyhedron(DualVertices v) {
  const std::vector<Corner> corners = sorted_corners(v);
  constexpr std::uint32_t unnumbered = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> number(v.vertices.size(), unnumbered);
  std::vector<std::uint32_t> order;  // the vertices as numbered
  order.reserve(v.vertices.size());
  PolygonSoup soup;
  // Reserved up front: a reallocation would copy every rational (Vec3's
  // move is not noexcept).
  std::size_t facets = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) facets += i == 0 || corners[i].row != corners[i - 1].row;
  FacetPlanes planes;
  planes.normals.reserve(facets);
  planes.normal_approx.reserve(facets);
  planes.offsets.reserve(facets);
  soup.face_offsets.reserve(facets + 1);
  soup.face_indices.reserve(corners.size());
  std::vector<std::uint32_t> face;
  mpz_class quotient;
  for (auto group = corners.begin(); group != corners.end();) {
    const auto group_end =
        std::find_if(group, corners.end(), [&](const Corner& c) { return c.row != group->row; });
    face.clear();
    auto c = group;
    do {
      if (number[c->vertex] == unnumbered) {
        number[c->vertex] = static_cast<std::uint32_t>(order.size());
        order.push_back(c->vertex);
      }
      face.push_back(number[c->vertex]);
      // The facet across the edge previous–row holds row just before previous.
      const std::uint32_t previous = c->previous;
      c = std::lower_bound(group, group_end, Corner{c->row, previous, 0, 0}, before);
      if (c == group_end || c->next != previous || face.size() > v.vertices.size())
        throw Error(ErrorCategory::invalid_argument,
                    "intersection_polyhedron: an open ring of facets");  // unreachable
    } while (c != group);
    soup.add_face(face);
    add_plane(v, group->row, planes, v.limbs, quotient);
    group = group_end;
  }
  // Every vertex is a corner of the three or more facets of its tight rows.
  if (order.size() != v.vertices.size())
    throw Error(ErrorCategory::invalid_argument,
                "intersection_polyhedron: a vertex on no facet");  // unreachable
  gather(v.vertices, order);
  soup.points = std::move(v.vertices);
  VertexApproximations approx;
  approx.reserve(soup.points.size());
  for (const Vec3& p : soup.points) approx.push_back(ApproxVec3::of(p));
  return assemble(output_mesh(std::move(soup)), std::move(approx), std::move(planes), std::move(v.limbs));
}

}  // namespace cvms::detail
