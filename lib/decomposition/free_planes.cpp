// SPDX-License-Identifier: MIT
// Free cutting planes from the solid's reflex edges (see free_planes.hpp).
// Every plane is computed exactly from three vertices of the solid: a
// primitive integer normal and a rational offset, as the facet planes.
#include "free_planes.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "cvms/vec.hpp"

namespace cvms::decomposition {
namespace {

// The canonical plane through x, y and w, or nothing if they are collinear.
bool plane_through(const Vec3& x, const Vec3& y, const Vec3& w, Plane& out) {
  const Vec3 normal = cross(y - x, w - x);
  if (is_zero(normal)) return false;
  out = canonical_plane(normal, x).first;
  return true;
}

bool on_plane(const Plane& plane, const Vec3& p) { return oriented_side(plane, 1, p) == 0; }

// Per vertex, the indices of the edges at it.
std::vector<std::vector<std::uint32_t>> edges_at(std::size_t vertices,
                                                 const std::vector<std::array<std::uint32_t, 2>>& edges) {
  std::vector<std::vector<std::uint32_t>> at(vertices);
  for (std::uint32_t e = 0; e < edges.size(); ++e)
    for (std::uint32_t v : edges[e]) at[v].push_back(e);
  return at;
}

}  // namespace

std::vector<Plane> free_planes(const Solid& solid, const BoundaryPlanes& planes) {
  const auto vertices = solid.vertices();
  const std::vector<std::vector<std::uint32_t>> at = edges_at(vertices.size(), planes.edges);
  std::vector<Plane> found;
  for (std::uint32_t e = 0; e < planes.edges.size(); ++e) {
    if (planes.edge_reflex[e] == 0) continue;
    for (int end = 0; end < 2; ++end) {
      const std::uint32_t x = planes.edges[e][end], y = planes.edges[e][1 - end];
      for (std::uint32_t f : at[x]) {
        const std::uint32_t w = planes.edges[f][0] == x ? planes.edges[f][1] : planes.edges[f][0];
        // On a plane of e's triangles, the pair spans that facet plane.
        if (w == y || on_plane(planes.planes[planes.edge_planes[e][0]], vertices[w]) ||
            on_plane(planes.planes[planes.edge_planes[e][1]], vertices[w]))
          continue;
        Plane plane;
        if (!plane_through(vertices[x], vertices[y], vertices[w], plane)) continue;
        if (std::binary_search(planes.planes.begin(), planes.planes.end(), plane, plane_less)) continue;
        found.push_back(std::move(plane));
      }
    }
  }
  std::sort(found.begin(), found.end(), plane_less);
  // Distinct planes with the number of edge pairs that gave each.
  std::vector<std::pair<std::size_t, Plane>> counted;
  for (std::size_t i = 0; i < found.size();) {
    std::size_t j = i + 1;
    while (j < found.size() && plane_equal(found[i], found[j])) ++j;
    counted.emplace_back(j - i, std::move(found[i]));
    i = j;
  }
  std::stable_sort(counted.begin(), counted.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<Plane> result;
  for (std::size_t i = 0; i < counted.size() && i < kMaxFreePlanes; ++i) result.push_back(std::move(counted[i].second));
  return result;
}

}  // namespace cvms::decomposition
