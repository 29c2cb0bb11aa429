// SPDX-License-Identifier: MIT
// Triangle planes, reflex edges and shells of a valid solid. An edge is
// reflex when the solid is locally non-convex there: the far vertex of one of
// its two triangles lies strictly in front of the other triangle's plane
// (orient3d, exact). Triangles of one plane that share an edge lie in one
// facet, and such an edge is no edge of the solid.
#include "boundary_planes.hpp"

#include <algorithm>
#include <array>
#include <numeric>
#include <tuple>

#include "cvms/predicates.hpp"

namespace cvms::decomposition {
namespace {

// The canonical plane of a triangle and the side its outward normal faces.
std::pair<Plane, int> triangle_plane(const Vec3& a, const Vec3& b, const Vec3& c) {
  return canonical_plane(cross(b - a, c - a), a);
}

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

}  // namespace

bool plane_less(const Plane& a, const Plane& b) {
  if (a.normal != b.normal) return a.normal < b.normal;
  return a.offset < b.offset;
}

bool plane_equal(const Plane& a, const Plane& b) { return a.normal == b.normal && a.offset == b.offset; }

std::pair<Plane, int> canonical_plane(const Vec3& normal, const Vec3& point) {
  Vec3 n = primitive_direction(normal);
  int side = 1;
  int first = sgn(n.x) != 0 ? sgn(n.x) : (sgn(n.y) != 0 ? sgn(n.y) : sgn(n.z));
  if (first < 0) {
    n = -n;
    side = -1;
  }
  Rational offset = dot(n, point);
  return {Plane{std::move(n), std::move(offset)}, side};
}

int oriented_side(const Plane& plane, int side, const Vec3& p) {
  return side * static_cast<int>(side_of_plane(p, plane.normal, plane.offset));
}

std::uint32_t plane_index(std::vector<Plane>& planes, std::uint32_t sorted_count, const Plane& plane) {
  auto end = planes.begin() + sorted_count;
  auto it = std::lower_bound(planes.begin(), end, plane, plane_less);
  if (it != end && plane_equal(*it, plane)) return static_cast<std::uint32_t>(it - planes.begin());
  for (std::size_t i = sorted_count; i < planes.size(); ++i)
    if (plane_equal(planes[i], plane)) return static_cast<std::uint32_t>(i);
  planes.push_back(plane);
  return static_cast<std::uint32_t>(planes.size() - 1);
}

BoundaryPlanes boundary_planes(const Solid& solid) {
  auto vertices = solid.vertices();
  auto triangles = solid.triangles();
  const std::size_t n = triangles.size();
  BoundaryPlanes result;

  std::vector<Plane> own(n);
  result.triangle_side.resize(n);
  for (std::size_t t = 0; t < n; ++t) {
    const auto& tri = triangles[t];
    auto [plane, side] = triangle_plane(vertices[tri[0]], vertices[tri[1]], vertices[tri[2]]);
    own[t] = std::move(plane);
    result.triangle_side[t] = static_cast<std::int8_t>(side);
  }
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return plane_less(own[a], own[b]); });
  result.triangle_plane.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (k == 0 || !plane_equal(own[order[k]], result.planes.back())) result.planes.push_back(own[order[k]]);
    result.triangle_plane[order[k]] = static_cast<std::uint32_t>(result.planes.size() - 1);
  }
  result.reflex_plane.assign(result.planes.size(), 0);

  // Edges as (low vertex, high vertex, triangle), sorted: a closed
  // 2-manifold lists each edge exactly twice.
  std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * n);
  for (std::uint32_t t = 0; t < n; ++t)
    for (int i = 0; i < 3; ++i) {
      std::uint32_t u = triangles[t][i], v = triangles[t][(i + 1) % 3];
      edges.emplace_back(std::min(u, v), std::max(u, v), t);
    }
  std::sort(edges.begin(), edges.end());
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  for (std::size_t k = 0; k + 1 < edges.size(); ++k) {
    auto [u0, v0, t0] = edges[k];
    auto [u1, v1, t1] = edges[k + 1];
    if (u0 != u1 || v0 != v1) continue;
    parent[find_root(parent, t0)] = find_root(parent, t1);
    if (result.triangle_plane[t0] == result.triangle_plane[t1] &&
        result.triangle_side[t0] == result.triangle_side[t1])
      continue;  // inside one facet
    std::uint32_t far = 0;
    for (std::uint32_t w : triangles[t1])
      if (w != u1 && w != v1) far = w;
    const Plane& plane = result.planes[result.triangle_plane[t0]];
    const bool reflex = oriented_side(plane, result.triangle_side[t0], vertices[far]) > 0;
    result.edges.push_back({u0, v0});
    result.edge_reflex.push_back(reflex ? 1 : 0);
    result.edge_planes.push_back({result.triangle_plane[t0], result.triangle_plane[t1]});
    if (reflex) {
      ++result.reflex_edges;
      result.reflex_plane[result.triangle_plane[t0]] = 1;
      result.reflex_plane[result.triangle_plane[t1]] = 1;
    }
  }
  for (std::uint32_t t = 0; t < n; ++t)
    if (find_root(parent, t) == t) ++result.shells;
  return result;
}

}  // namespace cvms::decomposition
