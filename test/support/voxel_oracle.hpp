// SPDX-License-Identifier: MIT
// An exact oracle for sums of polycubes (unions of closed unit cubes on the
// integer grid), independent of the library: the sum of the cubes at p and
// q is the 2 x 2 x 2 block of cubes at p + q + {0, 1}^3, so the sum of two
// polycubes is a polycube computed by integer dilation, and an a x b x c
// box with integer sides is the polycube of its a b c cubes. From the cubes:
//  - the volume is their count;
//  - a grid point is a vertex of the boundary exactly when the occupancy of
//    its 8 surrounding cubes depends on all three axes (depending on one
//    axis only it is a flat point of a facet, on two only a point inside a
//    straight edge, on none it is inside or outside);
//  - the facets are the classes of unit squares between a filled and an
//    empty cube, on one plane and facing one way, joined across shared
//    edges (two such squares meeting only at a corner are different facets);
//  - a point is in the set when it lies in a closed filled cube.
// A Mapping x -> M x + t (det M > 0) carries all of it to a polycube placed
// anywhere (scaled to decimals, rotated): the sum of the mapped operands is
// the mapped sum when both use the same M, with offsets t_A + t_B.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "cvms/polygon_soup.hpp"
#include "cvms/rational.hpp"
#include "cvms/vec.hpp"

namespace cvms::test {

using Cube = std::array<int, 3>;
using Cubes = std::set<Cube>;

/// x -> linear * x + offset.
struct Mapping {
  Mat3 linear = Mat3::identity();
  Vec3 offset;
  [[nodiscard]] Vec3 operator()(const Vec3& x) const { return linear * x + offset; }
};

/// The cubes at p + q + {0, 1}^3 for p in a, q in b.
inline Cubes polycube_sum(const Cubes& a, const Cubes& b) {
  Cubes out;
  for (const Cube& p : a)
    for (const Cube& q : b)
      for (int d = 0; d < 8; ++d)
        out.insert({p[0] + q[0] + (d & 1), p[1] + q[1] + ((d >> 1) & 1), p[2] + q[2] + (d >> 2)});
  return out;
}

/// The a x b x c box [0, a] x [0, b] x [0, c] as cubes.
inline Cubes box_cubes(int a, int b, int c) {
  Cubes out;
  for (int i = 0; i < a; ++i)
    for (int j = 0; j < b; ++j)
      for (int k = 0; k < c; ++k) out.insert({i, j, k});
  return out;
}

/// The sum of a polycube with the box [0, a] x [0, b] x [0, c]: each cube
/// dilated (the same as polycube_sum with box_cubes, without the pairs).
inline Cubes dilated(const Cubes& cubes, int a, int b, int c) {
  Cubes out;
  for (const Cube& p : cubes)
    for (int i = 0; i <= a; ++i)
      for (int j = 0; j <= b; ++j)
        for (int k = 0; k <= c; ++k) out.insert({p[0] + i, p[1] + j, p[2] + k});
  return out;
}

/// The grid points that are vertices of the boundary (see the file comment).
inline std::vector<Cube> voxel_vertices(const Cubes& cubes) {
  std::set<Cube> candidates;
  for (const Cube& c : cubes)
    for (int d = 0; d < 8; ++d) candidates.insert({c[0] + (d & 1), c[1] + ((d >> 1) & 1), c[2] + (d >> 2)});
  std::vector<Cube> out;
  for (const Cube& g : candidates) {
    // occupancy[d]: the cube whose corner g is corner 7 - d.
    std::array<bool, 8> occupancy{};
    for (int d = 0; d < 8; ++d)
      occupancy[d] = cubes.count({g[0] - 1 + (d & 1), g[1] - 1 + ((d >> 1) & 1), g[2] - 1 + (d >> 2)}) != 0;
    bool all_axes = true;
    for (int axis = 0; axis < 3; ++axis) {
      bool depends = false;
      for (int d = 0; d < 8; ++d)
        if (((d >> axis) & 1) == 0 && occupancy[d] != occupancy[d | (1 << axis)]) depends = true;
      all_axes = all_axes && depends;
    }
    if (all_axes) out.push_back(g);
  }
  return out;
}

/// The number of facets (see the file comment).
inline std::size_t voxel_facets(const Cubes& cubes) {
  // A square: the axis of its normal, the direction (0 toward -axis, 1 toward
  // +axis) and the cube it bounds.
  using Square = std::array<int, 5>;  // axis, direction, cube x, y, z
  std::set<Square> squares;
  for (const Cube& c : cubes)
    for (int axis = 0; axis < 3; ++axis)
      for (int dir = 0; dir < 2; ++dir) {
        Cube n = c;
        n[axis] += dir == 0 ? -1 : 1;
        if (cubes.count(n) == 0) squares.insert({axis, dir, c[0], c[1], c[2]});
      }
  std::size_t facets = 0;
  std::set<Square> seen;
  for (const Square& start : squares) {
    if (!seen.insert(start).second) continue;
    ++facets;
    std::vector<Square> stack{start};
    while (!stack.empty()) {
      const Square s = stack.back();
      stack.pop_back();
      // Squares on the same plane facing the same way share an edge when
      // their cubes are neighbours across one of the other two axes.
      for (int axis = 0; axis < 3; ++axis) {
        if (axis == s[0]) continue;
        for (int step : {-1, 1}) {
          Square t = s;
          t[2 + axis] += step;
          if (squares.count(t) != 0 && seen.insert(t).second) stack.push_back(t);
        }
      }
    }
  }
  return facets;
}

/// Whether the point x (in grid units) lies in a closed filled cube.
inline bool voxel_contains(const Cubes& cubes, const Vec3& x) {
  std::array<std::vector<int>, 3> spans;
  for (int axis = 0; axis < 3; ++axis) {
    const mpz_class low = x[axis].get_num() / x[axis].get_den();  // truncates toward zero
    mpz_class floor = low;
    if (Rational(low) > x[axis]) floor -= 1;
    const int f = static_cast<int>(floor.get_si());
    spans[axis].push_back(f);
    if (Rational(floor) == x[axis]) spans[axis].push_back(f - 1);
  }
  for (int i : spans[0])
    for (int j : spans[1])
      for (int k : spans[2])
        if (cubes.count({i, j, k}) != 0) return true;
  return false;
}

/// The polycube's boundary as a soup of unit squares, outward (each square
/// between a filled and an empty cube, counterclockwise seen from the empty
/// one). Cubes that meet only along an edge or at a corner share that
/// edge's or corner's index (an edge on four squares, a corner with several
/// fans), which Solid::from_soup splits into touching shells.
inline PolygonSoup polycube_soup(const Cubes& cubes) {
  PolygonSoup soup;
  std::map<Cube, std::uint32_t> index;
  auto vertex = [&](const Cube& g) {
    const auto [it, added] = index.emplace(g, static_cast<std::uint32_t>(soup.points.size()));
    if (added) soup.points.push_back(Vec3{Rational(g[0]), Rational(g[1]), Rational(g[2])});
    return it->second;
  };
  for (const Cube& c : cubes)
    for (int axis = 0; axis < 3; ++axis)
      for (int dir = 0; dir < 2; ++dir) {
        Cube n = c;
        n[axis] += dir == 0 ? -1 : 1;
        if (cubes.count(n) != 0) continue;
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        std::vector<std::uint32_t> square;
        for (const auto& [du, dv] : {std::pair{0, 0}, std::pair{1, 0}, std::pair{1, 1}, std::pair{0, 1}}) {
          Cube g = c;
          g[axis] += dir;
          g[u] += du;
          g[v] += dv;
          square.push_back(vertex(g));
        }
        // (u, v, axis) is a right-handed frame: counterclockwise seen from
        // +axis; reversed when the square faces -axis.
        if (dir == 0) std::swap(square[1], square[3]);
        soup.add_face(square);
      }
  return soup;
}

/// The grid point g as a point, mapped.
inline Vec3 mapped_point(const Cube& g, const Mapping& m) {
  return m(Vec3{Rational(g[0]), Rational(g[1]), Rational(g[2])});
}

}  // namespace cvms::test
