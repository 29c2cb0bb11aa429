// SPDX-License-Identifier: MIT
// The derivations of solid_properties.hpp.
//  - Facets: triangles joined across an edge when their primitive outward
//    normals are equal (two triangles on one edge with equal normals lie in
//    one plane), then closed under connection (union-find).
//  - Reflex edge: between two facets, where the far corner of one triangle is
//    strictly in front of the other's plane (the solid is locally the
//    intersection of two half-spaces there only when it is not).
//  - Shells: the connected components of the triangles; a closed orientable
//    surface of Euler characteristic V - E + F = 2 - 2g has genus g, with
//    E = 3F/2 on a closed triangulated surface.
//  - Volume: the divergence theorem on the triangles, sum of det[a, b, c] / 6,
//    per shell (its sign is the shell's orientation); det[a, b, c] =
//    dot(a, cross(b - a, c - a)), so the triangle's area vector serves both
//    its plane and its volume.
#include "solid_properties.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/predicates.hpp"
#include "union_find.hpp"

namespace cvms::detail {

namespace {

// Pairs of (triangle, corner) half-edges on the same edge: the half-edge
// 3t + i runs from corner i to corner i + 1 of triangle t.
std::vector<std::pair<std::uint32_t, std::uint32_t>> edge_pairs(
    std::span<const std::array<std::uint32_t, 3>> tris) {
  const std::size_t n = tris.size() * 3;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(n);
  for (std::uint32_t h = 0; h < n; ++h) {
    const auto& t = tris[h / 3];
    const std::uint64_t a = t[h % 3];
    const std::uint64_t b = t[(h + 1) % 3];
    keyed[h] = {(std::min(a, b) << 32) | std::max(a, b), h};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  pairs.reserve(n / 2);
  for (std::size_t k = 0; k < n;) {
    std::size_t e = k;
    while (e < n && keyed[e].first == keyed[k].first) ++e;
    if (e - k == 2) pairs.emplace_back(keyed[k].second, keyed[k + 1].second);
    k = e;
  }
  return pairs;
}

void derive_facets(SolidAccess::Impl& impl, std::span<const std::pair<std::uint32_t, std::uint32_t>> pairs,
                   std::span<const Vec3> areas) {
  const auto& tris = impl.triangles;
  const auto& pts = impl.vertices;
  std::vector<Vec3> normals;
  normals.reserve(tris.size());
  for (const Vec3& area : areas) normals.push_back(primitive_direction(area));
  UnionFind facets(tris.size());
  for (const auto& [h, g] : pairs)
    if (normals[h / 3] == normals[g / 3]) facets.join(h / 3, g / 3);
  std::uint32_t count = 0;
  impl.triangle_facets = facets.numbering(count);
  impl.facet_normals.assign(count, Vec3{});
  impl.facet_offsets.assign(count, Rational{});
  for (std::uint32_t t = 0; t < tris.size(); ++t) {
    const std::uint32_t f = impl.triangle_facets[t];
    if (facets.find(t) != t) continue;  // the facet's smallest triangle sets its plane
    impl.facet_offsets[f] = dot(normals[t], pts[tris[t][0]]);
    impl.facet_normals[f] = std::move(normals[t]);
  }
  impl.reflex_edges = 0;
  for (const auto& [h, g] : pairs) {
    const auto& t = tris[h / 3];
    const auto& u = tris[g / 3];
    if (impl.triangle_facets[h / 3] == impl.triangle_facets[g / 3]) continue;
    const std::uint32_t far = u[(g % 3 + 2) % 3];  // the corner of u off the shared edge
    if (orient3d(pts[t[0]], pts[t[1]], pts[t[2]], pts[far]) == Sign::positive) ++impl.reflex_edges;
  }
}

Shells derive_shells(SolidAccess::Impl& impl, std::span<const std::pair<std::uint32_t, std::uint32_t>> pairs,
                     std::span<const Vec3> areas) {
  const auto& tris = impl.triangles;
  const auto& pts = impl.vertices;
  UnionFind components(tris.size());
  for (const auto& [h, g] : pairs) components.join(h / 3, g / 3);
  Shells shells;
  std::uint32_t count = 0;
  shells.of_triangle = components.numbering(count);
  shells.first_triangle.assign(count, 0);
  shells.signed_volumes.assign(count, Rational{});
  std::vector<std::int64_t> euler(count, 0);
  std::vector<std::uint32_t> vertex_shell(pts.size(), count);
  for (std::uint32_t t = 0; t < tris.size(); ++t) {
    const std::uint32_t s = shells.of_triangle[t];
    if (components.find(t) == t) shells.first_triangle[s] = t;
    const auto& tri = tris[t];
    // F - E = F - 3F/2 = -F/2: add 2 for each triangle, then halve.
    euler[s] -= 1;
    for (std::uint32_t v : tri)
      if (vertex_shell[v] != s) {
        vertex_shell[v] = s;
        euler[s] += 2;
      }
    shells.signed_volumes[s] += dot(pts[tri[0]], areas[t]);
  }
  impl.genus = 0;
  impl.cavities = 0;
  impl.volume = 0;
  for (std::uint32_t s = 0; s < count; ++s) {
    const std::int64_t chi = euler[s] / 2;
    if (chi < 2) impl.genus += static_cast<std::uint32_t>((2 - chi) / 2);
    shells.signed_volumes[s] /= 6;
    if (sgn(shells.signed_volumes[s]) < 0) ++impl.cavities;
    impl.volume += shells.signed_volumes[s];
  }
  impl.shells = count;
  return shells;
}

}  // namespace

Shells derive_properties(SolidAccess::Impl& impl, std::vector<Vec3> areas) {
  if (areas.empty()) {
    areas.reserve(impl.triangles.size());
    for (const auto& t : impl.triangles) {
      const Vec3& a = impl.vertices[t[0]];
      areas.push_back(cross(impl.vertices[t[1]] - a, impl.vertices[t[2]] - a));
    }
  }
  const auto pairs = edge_pairs(impl.triangles);
  derive_facets(impl, pairs, areas);
  return derive_shells(impl, pairs, areas);
}

}  // namespace cvms::detail
