// SPDX-License-Identifier: MIT
// See facet_polygons.hpp. Why the grown polygon stays convex: it is convex
// and the triangle (u, w, v) added across its edge u -> v lies on the outer
// side of that edge (the triangles of a facet are oriented alike and do not
// overlap), so w is a new point strictly beyond the line uv and the corner
// at w is strictly convex; the corners at u and v are tested (a straight
// corner is allowed). A convex polygon with one more vertex beyond one edge
// and all corners convex is convex.
#include "facet_polygons.hpp"

#include <cstddef>
#include <cstdint>
#include <unordered_map>

#include "cvms/predicates.hpp"

namespace cvms::detail {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

std::uint64_t edge_key(std::uint32_t from, std::uint32_t to) { return (std::uint64_t{from} << 32) | to; }

class PolygonGrower {
 public:
  explicit PolygonGrower(const Solid& solid)
      : solid_(solid),
        points_(solid.vertices()),
        triangles_(solid.triangles()),
        facets_(solid.triangle_facets()),
        used_(triangles_.size(), false) {
    edges_.reserve(3 * triangles_.size());
    for (std::size_t t = 0; t < triangles_.size(); ++t)
      for (int i = 0; i < 3; ++i)
        edges_.emplace(edge_key(triangles_[t][i], triangles_[t][(i + 1) % 3]), static_cast<std::uint32_t>(t));
  }

  std::vector<std::vector<Vec3>> polygons() {
    std::vector<std::vector<Vec3>> out;
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      if (used_[t]) continue;
      used_[t] = true;
      if (flat(triangles_[t])) continue;
      std::vector<std::uint32_t> cycle(triangles_[t].begin(), triangles_[t].end());
      grow(cycle, facets_[t]);
      std::vector<Vec3> corners;
      corners.reserve(cycle.size());
      for (std::uint32_t v : cycle) corners.push_back(points_[v]);
      out.push_back(std::move(corners));
    }
    return out;
  }

 private:
  // Adds neighbouring triangles of `facet` while the polygon stays convex.
  void grow(std::vector<std::uint32_t>& cycle, std::uint32_t facet) {
    const Vec3& normal = solid_.facet_normal(facet);
    for (bool grown = true; grown;) {
      grown = false;
      for (std::size_t i = 0; i < cycle.size(); ++i) {
        const std::size_t k = cycle.size();
        const std::uint32_t u = cycle[i], v = cycle[(i + 1) % k];
        const auto it = edges_.find(edge_key(v, u));
        if (it == edges_.end() || used_[it->second] || facets_[it->second] != facet ||
            flat(triangles_[it->second]))
          continue;
        const std::uint32_t w = third_vertex(triangles_[it->second], u, v);
        const std::uint32_t before = cycle[(i + k - 1) % k], after = cycle[(i + 2) % k];
        if (!convex_corner(before, u, w, normal) || !convex_corner(w, v, after, normal)) continue;
        cycle.insert(cycle.begin() + static_cast<std::ptrdiff_t>(i + 1), w);
        used_[it->second] = true;
        grown = true;
      }
    }
  }

  // A triangle of zero area (the solid's own triangulations make none, but
  // a solid built otherwise might) covers only a segment that its
  // neighbours' sums cover already: it starts no polygon.
  bool flat(const Triangle& t) const {
    return is_parallel(points_[t[1]] - points_[t[0]], points_[t[2]] - points_[t[0]]);
  }

  static std::uint32_t third_vertex(const Triangle& t, std::uint32_t u, std::uint32_t v) {
    for (std::uint32_t x : t)
      if (x != u && x != v) return x;
    return t[0];  // unreachable for a triangle with the edge (v, u)
  }

  // The turn a -> b -> c, seen from the tip of `normal`, is left or straight.
  bool convex_corner(std::uint32_t a, std::uint32_t b, std::uint32_t c, const Vec3& normal) const {
    return sign_triple(normal, points_[b] - points_[a], points_[c] - points_[b]) != Sign::negative;
  }

  const Solid& solid_;
  std::span<const Vec3> points_;
  std::span<const Triangle> triangles_;
  std::span<const std::uint32_t> facets_;
  std::vector<bool> used_;
  std::unordered_map<std::uint64_t, std::uint32_t> edges_;
};

}  // namespace

std::vector<std::vector<Vec3>> facet_polygons(const Solid& solid) { return PolygonGrower(solid).polygons(); }

}  // namespace cvms::detail
