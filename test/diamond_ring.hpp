// SPDX-License-Identifier: MIT
// A ring (or an open bent bar) of convex segments, for the tests of the
// decomposition's cuts at joints that hold no facet, with its segments
// built by hand (each the hull of two consecutive cross sections), so that
// the tests' oracles never run the decomposition.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/predicates.hpp"
#include "cvms/solid.hpp"
#include "cvms/vec.hpp"

namespace cvms::test {

// A diamond cross section (outer, top, inner, bottom corners at 3 d,
// 2 d + z, d, 2 d - z) at each integer direction d of `directions`,
// consecutive sections joined by planar quads (two triangles each), the
// ends of an open bar closed by the end sections. The joints between
// segments are reflex along the inner side and hold no facet.
struct DiamondRing {
  std::vector<Vec2> directions;
  bool closed = true;

  [[nodiscard]] std::array<Vec3, 4> section(std::size_t k) const {
    const Vec2& d = directions[k];
    return {Vec3{3 * d.x, 3 * d.y, 0}, Vec3{2 * d.x, 2 * d.y, 1}, Vec3{d.x, d.y, 0}, Vec3{2 * d.x, 2 * d.y, -1}};
  }
  [[nodiscard]] std::size_t segments() const { return closed ? directions.size() : directions.size() - 1; }

  // Each segment: the hull of its two end sections.
  [[nodiscard]] std::vector<ConvexPolyhedron> segment_hulls() const {
    std::vector<ConvexPolyhedron> hulls;
    for (std::size_t k = 0; k < segments(); ++k) {
      std::vector<Vec3> points;
      for (const Vec3& q : section(k)) points.push_back(q);
      for (const Vec3& q : section((k + 1) % directions.size())) points.push_back(q);
      hulls.push_back(convex_hull(points));
    }
    return hulls;
  }

  // Closed membership: in some segment.
  [[nodiscard]] bool contains(const Vec3& p) const {
    for (const ConvexPolyhedron& hull : segment_hulls()) {
      bool inside = true;
      for (FaceId f : hull.mesh().faces())
        inside = inside && side_of_plane(p, hull.normal(f), hull.plane_offset(f)) != Sign::positive;
      if (inside) return true;
    }
    return false;
  }

  // The solid, validated by Solid::from_soup (closed, 2-manifold, outward).
  [[nodiscard]] Solid solid() const {
    PolygonSoup soup;
    for (std::size_t k = 0; k < directions.size(); ++k)
      for (const Vec3& q : section(k)) soup.points.push_back(q);
    auto face = [&soup](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
      soup.face_indices.insert(soup.face_indices.end(), {a, b, c});
      soup.face_offsets.push_back(static_cast<std::uint32_t>(soup.face_indices.size()));
    };
    const auto n = static_cast<std::uint32_t>(directions.size());
    for (std::uint32_t k = 0; k < segments(); ++k) {
      const std::uint32_t a = 4 * k, b = 4 * ((k + 1) % n);
      for (std::uint32_t i = 0; i < 4; ++i) {
        const std::uint32_t j = (i + 1) % 4;
        face(a + i, b + i, b + j);
        face(a + i, b + j, a + j);
      }
    }
    if (!closed) {
      const std::uint32_t last = 4 * (n - 1);
      face(0, 1, 2);
      face(0, 2, 3);
      face(last, last + 2, last + 1);
      face(last, last + 3, last + 2);
    }
    return Solid::from_soup(std::move(soup));
  }
};

}  // namespace cvms::test
