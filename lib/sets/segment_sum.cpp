// SPDX-License-Identifier: MIT
// A segment S = [s, s + d] plus a polyhedron P, directly from P.
//
// The face of S + P in direction u is F_S(u) + F_P(u), and F_S(u) is s, s + d
// or all of S as dot(u, d) is negative, positive or zero. So the facets are:
//  - each facet f of P with dot(n_f, d) < 0, translated by s; with > 0, by
//    s + d; with = 0, f + S (a "stretched" facet: the planar sum of f's
//    polygon and S in f's plane);
//  - for each edge e of P between a facet with dot(n, d) < 0 and one with
//    dot(n, d) > 0 (the silhouette of P seen along d), the parallelogram
//    e + S: the normals between the two facets' sweep through dot(u, d) = 0
//    exactly once, at a normal of e orthogonal to d.
// Every vertex is the sum of a vertex of P and an endpoint of S, named by
// the pair (v, endpoint); distinct pairs used here are distinct points (a
// vertex of a sum has one decomposition). An edge between a facet of each
// sign is shared by its two translates and the parallelogram; an edge
// between a stretched facet and another facet lies in both with the same
// endpoints (its in-plane outward normal has the other facet's sign), and an
// edge between two stretched facets is parallel to d and stretched in both.
// Consecutive silhouette edges whose parallelograms are coplanar (e, e' and d
// coplanar) are merged, and the vertices between them kept or dropped, by
// ConvexPolyhedron's checked construction; without such a pair every facet
// is maximal and strictly convex, and the trusted builder
// (polyhedron_builder.hpp) only checks the topology.
// Cost: O(size of P) predicates plus the planar sums and the check.
#include <cstdint>
#include <string>
#include <vector>

#include "cvms/predicates.hpp"
#include "output_budget.hpp"
#include "polyhedron_builder.hpp"
#include "set_sum_parts.hpp"

namespace cvms::detail {

namespace {

// The soup of S + P under construction: vertex (v, endpoint) is point
// index_of[2 v + endpoint], made on first use (an array, not a hash map,
// which an input could make quadratic).
class SweptSoup {
 public:
  SweptSoup(const ConvexPolyhedron& p, const Vec3& start, const Vec3& direction)
      : p_(p), start_(start), end_(start + direction), index_of_(2 * std::size_t{p.num_vertices()}, unused) {}

  std::uint32_t vertex(VertexId v, int endpoint) {
    std::uint32_t& index = index_of_[2 * std::size_t{v.index()} + static_cast<std::size_t>(endpoint)];
    if (index == unused) {
      index = static_cast<std::uint32_t>(soup_.points.size());
      soup_.points.push_back(p_.vertex(v) + (endpoint == 0 ? start_ : end_));
    }
    return index;
  }

  void add_face(const std::vector<std::uint32_t>& face) { soup_.add_face(face); }
  PolygonSoup take() { return std::move(soup_); }

 private:
  const ConvexPolyhedron& p_;
  Vec3 start_, end_;
  static constexpr std::uint32_t unused = ~std::uint32_t{0};
  std::vector<std::uint32_t> index_of_;
  PolygonSoup soup_;
};

void add_stretched_facet(SweptSoup& soup, const ConvexPolyhedron& p, FaceId f, const Vec3& direction) {
  std::vector<std::uint32_t> face;
  for (const auto& [v, end] : stretched_facet(p, f, Vec3{0, 0, 0}, direction)) face.push_back(soup.vertex(v, int(end)));
  soup.add_face(face);
}

}  // namespace

ConvexSet segment_polyhedron_sum(const Vec3& start, const Vec3& direction, const ConvexPolyhedron& p,
                                 const OutputBudget& budget) {
  const Mesh& m = p.mesh();
  std::vector<Sign> side(m.num_faces());
  for (FaceId f : m.faces()) side[f.index()] = sign_dot(p.normal(f), direction);
  const auto on_silhouette = [&](HalfedgeId h) {
    return side[m.face(h).index()] == Sign::negative && side[m.face(Mesh::twin(h)).index()] == Sign::positive;
  };
  // Counted before the output is made (SumLimits): one facet per
  // facet of P and per silhouette edge, fewer once coplanar ones merge.
  std::uint64_t facets = m.num_faces();
  for (HalfedgeId h : m.halfedges()) facets += on_silhouette(h) ? 1 : 0;
  budget.check_count(facets, "minkowski_sum (segment + polyhedron): the sum has up to " + std::to_string(facets) +
                                 " facets");
  SweptSoup soup(p, start, direction);
  for (FaceId f : m.faces()) {
    const Sign s = side[f.index()];
    if (s == Sign::zero) {
      add_stretched_facet(soup, p, f, direction);
      continue;
    }
    std::vector<std::uint32_t> face;
    for (HalfedgeId h : m.face_halfedges(f)) face.push_back(soup.vertex(m.from(h), s == Sign::negative ? 0 : 1));
    soup.add_face(face);
  }
  // The silhouette edges at each vertex, to find coplanar neighbours.
  std::vector<std::vector<Vec3>> silhouette_at(m.num_vertices());
  bool coplanar_neighbours = false;
  for (HalfedgeId h : m.halfedges()) {
    if (!on_silhouette(h)) continue;
    // h runs u -> w in the facet kept in place; the parallelogram runs the
    // other way along it, then up d, back, and down.
    const VertexId u = m.from(h), w = m.to(h);
    soup.add_face({soup.vertex(w, 0), soup.vertex(u, 0), soup.vertex(u, 1), soup.vertex(w, 1)});
    const Vec3 e = p.edge_vector(h);
    for (VertexId x : {u, w}) {
      for (const Vec3& other : silhouette_at[x.index()])
        coplanar_neighbours = coplanar_neighbours || sign_triple(e, other, direction) == Sign::zero;
      silhouette_at[x.index()].push_back(e);
    }
  }
  // Without coplanar parallelograms every facet is maximal (the others have
  // pairwise different normals: P's, and e x d for silhouette edges e), so
  // the trusted builder applies; otherwise the checked construction merges.
  if (!coplanar_neighbours) return ConvexSet(trusted_polyhedron(soup.take()));
  return ConvexSet(ConvexPolyhedron::from_soup(soup.take()));
}

ConvexPolyhedron prism(const ConvexSet& polygon, const Vec3& start, const Vec3& direction) {
  const std::vector<Vec3> cycle = polygon.vertices();
  const auto n = static_cast<std::uint32_t>(cycle.size());
  PolygonSoup soup;
  for (const Vec3& v : cycle) soup.points.push_back(v + start);
  for (const Vec3& v : cycle) soup.points.push_back(v + start + direction);
  // Consistently oriented; from_soup turns an inward orientation outward.
  std::vector<std::uint32_t> bottom, top;
  for (std::uint32_t i = 0; i < n; ++i) {
    bottom.push_back(n - 1 - i);
    top.push_back(n + i);
    const std::uint32_t j = (i + 1) % n;
    soup.add_face({i, j, n + j, n + i});
  }
  soup.add_face(bottom);
  soup.add_face(top);
  return ConvexPolyhedron::from_soup(std::move(soup));
}

}  // namespace cvms::detail
