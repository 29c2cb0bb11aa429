// SPDX-License-Identifier: MIT
// Hand-built solids as polygon soups for mesh and polyhedron tests, and soup
// manipulations (subdivision, reversal, triangulation, vertex shuffling) that
// keep the described solid unchanged. Plain rational arithmetic only.
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "cvms/polygon_soup.hpp"
#include "cvms/vec.hpp"

namespace cvms::test {

inline PolygonSoup make_soup(std::vector<Vec3> points, const std::vector<std::vector<std::uint32_t>>& faces) {
  PolygonSoup s;
  s.points = std::move(points);
  for (const auto& f : faces) s.add_face(f);
  return s;
}

inline Vec3 v3(long x, long y, long z) { return {Rational(x), Rational(y), Rational(z)}; }

/// Unit tetrahedron (0,0,0), e_x, e_y, e_z, outward.
inline PolygonSoup tetrahedron() {
  return make_soup({v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 1)}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
}

/// Cube [0,s]^3 as 6 quads; vertex i = (x, y, z) with bits x + 2y + 4z.
inline PolygonSoup cube_quads(long s = 1) {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.push_back(v3((i & 1) ? s : 0, (i & 2) ? s : 0, (i & 4) ? s : 0));
  return make_soup(p, {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}});
}

/// Every face split into a fan from its first vertex.
inline PolygonSoup fan_triangulated(const PolygonSoup& in) {
  PolygonSoup s;
  s.points = in.points;
  for (std::size_t f = 0; f < in.num_faces(); ++f) {
    auto face = in.face(f);
    for (std::size_t i = 1; i + 1 < face.size(); ++i) s.add_face({face[0], face[i], face[i + 1]});
  }
  return s;
}

inline PolygonSoup cube_triangles() { return fan_triangulated(cube_quads()); }

/// Octahedron with vertices +-e_i: 8 triangles, outward.
inline PolygonSoup octahedron() {
  std::vector<Vec3> p{v3(1, 0, 0), v3(-1, 0, 0), v3(0, 1, 0), v3(0, -1, 0), v3(0, 0, 1), v3(0, 0, -1)};
  PolygonSoup s;
  s.points = p;
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz) {
        std::uint32_t a = sx, b = 2 + sy, c = 4 + sz;
        Vec3 n = cross(p[b] - p[a], p[c] - p[a]);
        if (dot(n, p[a]) < 0) std::swap(b, c);
        s.add_face({a, b, c});
      }
  return s;
}

/// Triangular prism: base (0,0,0), (3,0,0), (0,3,0), height 2; quads on the sides.
inline PolygonSoup prism() {
  return make_soup({v3(0, 0, 0), v3(3, 0, 0), v3(0, 3, 0), v3(0, 0, 2), v3(3, 0, 2), v3(0, 3, 2)},
                   {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}});
}

/// Each triangle split into 4 at its edge midpoints (shared between faces),
/// `levels` times. Non-triangles are fan-triangulated first.
inline PolygonSoup subdivided(const PolygonSoup& in, int levels) {
  PolygonSoup s = fan_triangulated(in);
  for (int l = 0; l < levels; ++l) {
    PolygonSoup t;
    t.points = s.points;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      auto i = static_cast<std::uint32_t>(t.points.size());
      t.points.push_back(Rational(1, 2) * (s.points[a] + s.points[b]));
      mid.emplace(key, i);
      return i;
    };
    for (std::size_t f = 0; f < s.num_faces(); ++f) {
      auto face = s.face(f);
      std::uint32_t a = face[0], b = face[1], c = face[2];
      std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      t.add_face({a, ab, ca});
      t.add_face({ab, b, bc});
      t.add_face({ca, bc, c});
      t.add_face({ab, bc, ca});
    }
    s = std::move(t);
  }
  return s;
}

/// Every face reversed (inward orientation for a closed outward surface).
inline PolygonSoup reversed(PolygonSoup s) {
  for (std::size_t f = 0; f < s.num_faces(); ++f)
    std::reverse(s.face_indices.begin() + s.face_offsets[f], s.face_indices.begin() + s.face_offsets[f + 1]);
  return s;
}

/// The same surface with vertices renumbered, faces reordered and each face
/// list rotated, all at random.
inline PolygonSoup shuffled(const PolygonSoup& in, std::mt19937& rng) {
  std::vector<std::uint32_t> perm(in.points.size());
  std::iota(perm.begin(), perm.end(), 0u);
  std::shuffle(perm.begin(), perm.end(), rng);
  PolygonSoup s;
  s.points.resize(in.points.size());
  for (std::size_t i = 0; i < perm.size(); ++i) s.points[perm[i]] = in.points[i];
  std::vector<std::size_t> order(in.num_faces());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::shuffle(order.begin(), order.end(), rng);
  for (std::size_t f : order) {
    auto face = in.face(f);
    std::vector<std::uint32_t> out;
    for (std::uint32_t v : face) out.push_back(perm[v]);
    std::rotate(out.begin(), out.begin() + static_cast<long>(rng() % out.size()), out.end());
    s.add_face(out);
  }
  return s;
}

/// x -> linear * x + offset applied to every point (faces unchanged).
inline PolygonSoup mapped(PolygonSoup s, const Mat3& linear, const Vec3& offset) {
  for (Vec3& p : s.points) p = linear * p + offset;
  return s;
}

/// The vertices of the rhombic dodecahedron: (+-1, +-1, +-1) and the
/// permutations of (+-2, 0, 0). Its 12 facet normals are (+-1, +-1, 0) and
/// permutations, so every Gaussian arc of the cube passes through one of them.
inline std::vector<Vec3> rhombic_dodecahedron_points() {
  std::vector<Vec3> pts;
  for (long x : {-1, 1})
    for (long y : {-1, 1})
      for (long z : {-1, 1}) pts.push_back(v3(x, y, z));
  for (long s : {-2, 2}) {
    pts.push_back(v3(s, 0, 0));
    pts.push_back(v3(0, s, 0));
    pts.push_back(v3(0, 0, s));
  }
  return pts;
}

/// The prism z in [z0, z1] over the counterclockwise polygon `base`: its caps
/// as single faces (bottom reversed, so both face outward), a quad per side.
inline PolygonSoup prism_over(const std::vector<Vec2>& base, const Rational& z0, const Rational& z1) {
  PolygonSoup soup;
  const auto m = static_cast<std::uint32_t>(base.size());
  for (const Vec2& q : base) soup.points.push_back({q.x, q.y, z0});
  for (const Vec2& q : base) soup.points.push_back({q.x, q.y, z1});
  std::vector<std::uint32_t> bottom, top;
  for (std::uint32_t i = 0; i < m; ++i) {
    bottom.push_back(m - 1 - i);
    top.push_back(m + i);
  }
  soup.add_face(bottom);
  soup.add_face(top);
  for (std::uint32_t i = 0; i < m; ++i) soup.add_face({i, (i + 1) % m, m + (i + 1) % m, m + i});
  return soup;
}

/// The comb of k >= 2 teeth, counterclockwise: a base [0, 3k - 2] x [0, 1]
/// and teeth [3i, 3i + 1] x [1, 4]; 4k corners. Triangulated, it holds long
/// thin triangles spanning the base.
inline std::vector<Vec2> comb_polygon(int k) {
  std::vector<std::pair<int, int>> cycle = {{0, 0}, {3 * k - 2, 0}, {3 * k - 2, 4}, {3 * k - 3, 4}, {3 * k - 3, 1}};
  for (int i = k - 2; i >= 1; --i)
    for (const auto& c : {std::pair{3 * i + 1, 1}, std::pair{3 * i + 1, 4}, std::pair{3 * i, 4}, std::pair{3 * i, 1}})
      cycle.push_back(c);
  for (const auto& c : {std::pair{1, 1}, std::pair{1, 4}, std::pair{0, 4}}) cycle.push_back(c);
  std::vector<Vec2> out;
  out.reserve(cycle.size());
  for (const auto& [x, y] : cycle) out.push_back({Rational(x), Rational(y)});
  return out;
}

}  // namespace cvms::test
