// SPDX-License-Identifier: MIT
// When a cell of the auto-partition holds a convex part of the solid.
//
// Let C be a convex cell with nonempty interior, G the union of its
// fragments (the parts of the solid's boundary triangles in C, each a convex
// polygon of positive area with an outward side), and K the intersection of
// C with the closed half-spaces behind the fragments' planes. Suppose every
// fragment lies in K. Then the solid S meets C in K (as closed regular
// sets: their interiors agree):
//
// (1) int(S) n int(C) lies in K. Take x in int(S) n int(C) outside K: x is
//     strictly in front of the plane H of some fragment f. The open region R
//     of int(C) strictly in front of H is convex, so connected, and it meets
//     no boundary of S: that boundary lies, within int(C), in G, and G lies
//     in K, on or behind H. So R lies wholly inside or wholly outside S. It
//     holds x, inside; and it holds points just in front of a generic point
//     of f, outside (f is part of an outward boundary triangle): a
//     contradiction.
// (2) int(K) lies in S. int(K) is convex, so connected, and meets no
//     boundary of S (that lies in G, in the boundary of K), so it is wholly
//     inside or wholly outside S. A fragment f has positive area on its
//     plane and lies in K, so its relative interior lies in the relative
//     interior of the facet of K on that plane, and points just behind a
//     generic point of f are in int(K); they are inside S.
//
// K's vertices are fragment points or vertices of C: a vertex v of K inside
// int(C) lies on the boundary of S, so in a fragment (a convex polygon in
// K), and being extreme in K it is extreme in that fragment: a vertex of
// it. A vertex v of K on the boundary of C is a vertex of C if K equals C
// near v; otherwise a facet of K on a fragment plane passes through v, that
// facet's part in int(C) is covered by fragments, and v, a limit of
// fragment points and extreme in K, is a vertex of a fragment (fragments
// are closed). So K is the hull of the fragments' points and C's vertices
// in K.
//
// The test "every fragment lies in K" is: each fragment's plane, with its
// outward side, is the plane of a facet of P = hull(fragment points) with
// the same outward normal. If all fragment points are on or behind the
// plane H of a fragment f, H supports P, and P n H holds f, of positive
// area, so it is a facet; conversely a facet plane of P has P behind it.
// Fragments lie in C, so then every fragment lies in K. One exact hull and a
// sorted lookup per fragment.
#include "convex_part.hpp"

#include <algorithm>
#include <utility>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"

namespace cvms::decomposition {
namespace {

struct SidedPlane {
  Plane plane;
  int side = 1;
};

bool sided_less(const SidedPlane& a, const SidedPlane& b) {
  if (plane_less(a.plane, b.plane)) return true;
  if (plane_less(b.plane, a.plane)) return false;
  return a.side < b.side;
}

// The hull's facet planes in the table's canonical form, with the side of
// their outward normals, sorted.
std::vector<SidedPlane> facet_planes(const ConvexPolyhedron& hull) {
  std::vector<SidedPlane> result;
  result.reserve(hull.num_facets());
  for (FaceId f : hull.mesh().faces()) {
    SidedPlane p{Plane{hull.normal(f), hull.plane_offset(f)}, 1};
    const Vec3& n = p.plane.normal;
    const int first = sgn(n.x) != 0 ? sgn(n.x) : (sgn(n.y) != 0 ? sgn(n.y) : sgn(n.z));
    if (first < 0) {
      p.plane.normal = -p.plane.normal;
      p.plane.offset = -p.plane.offset;
      p.side = -1;
    }
    result.push_back(std::move(p));
  }
  std::sort(result.begin(), result.end(), sided_less);
  return result;
}

bool on_or_behind_all(const Vec3& point, const std::vector<SidedPlane>& bounds) {
  for (const SidedPlane& b : bounds)
    if (oriented_side(b.plane, b.side, point) > 0) return false;
  return true;
}

}  // namespace

std::optional<std::vector<Vec3>> convex_part(const Cell& cell, const std::vector<Fragment>& fragments,
                                             const std::vector<Plane>& planes, const ProgressCallback& progress) {
  std::vector<Vec3> points;
  for (const Fragment& f : fragments) points.insert(points.end(), f.points.begin(), f.points.end());
  // Neighbouring fragments share their corners: the hull takes each once.
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  std::optional<ConvexPolyhedron> hull;
  try {
    hull.emplace(convex_hull(points, progress));
  } catch (const Error& e) {
    if (e.category() != ErrorCategory::degenerate) throw;
    return std::nullopt;  // flat: the partition goes on with facet planes
  }
  const std::vector<SidedPlane> facets = facet_planes(*hull);
  // The distinct fragment planes with their sides.
  std::vector<std::pair<std::uint32_t, int>> used;
  used.reserve(fragments.size());
  for (const Fragment& f : fragments) used.emplace_back(f.plane, f.side);
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::vector<SidedPlane> bounds;
  bounds.reserve(used.size());
  for (const auto& [index, side] : used) {
    SidedPlane wanted{planes[index], side};
    if (!std::binary_search(facets.begin(), facets.end(), wanted, sided_less)) return std::nullopt;
    bounds.push_back(std::move(wanted));
  }
  points.clear();
  for (VertexId v : hull->mesh().vertices()) points.push_back(hull->vertex(v));
  for (const CellVertex& v : cell.vertices)
    if (on_or_behind_all(v.point, bounds)) points.push_back(v.point);
  return points;
}

}  // namespace cvms::decomposition
