// SPDX-License-Identifier: MIT
// Solids made of the cells of a rectilinear grid, for the decomposition
// tests: built as triangles (SolidAccess::assume_valid) and with an exact
// membership test of their own (a point lies in a closed filled cell), so
// that the tests' oracle never runs the code under test.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "cvms/rational.hpp"
#include "cvms/solid.hpp"
#include "cvms/vec.hpp"
#include "solid_access.hpp"

namespace cvms::test {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;
using Cells = std::set<std::array<int, 3>>;

// A solid made of grid cells: the faces between a filled and an empty cell,
// two triangles per face, outward (from filled to empty). Faces of
// neighbouring cells on one plane make coplanar triangles and collinear
// vertices on the facets' edges; an empty cell enclosed by filled ones makes
// an inward-facing cavity shell.
struct GridSolid {
  std::array<std::vector<Rational>, 3> grid;
  Cells cells;

  bool filled(std::array<int, 3> c) const { return cells.count(c) != 0; }

  Solid solid() const {
    std::vector<Vec3> vertices;
    Triangles triangles;
    std::map<std::array<int, 3>, std::uint32_t> index;
    auto vertex = [&](std::array<int, 3> g) {
      auto [it, added] = index.emplace(g, static_cast<std::uint32_t>(vertices.size()));
      if (added) vertices.push_back(Vec3{grid[0][g[0]], grid[1][g[1]], grid[2][g[2]]});
      return it->second;
    };
    for (const auto& c : cells)
      for (int axis = 0; axis < 3; ++axis)
        for (int dir = 0; dir < 2; ++dir) {
          std::array<int, 3> n = c;
          n[axis] += dir == 0 ? -1 : 1;
          if (filled(n)) continue;
          int u = (axis + 1) % 3, v = (axis + 2) % 3;
          std::array<std::uint32_t, 4> q;
          const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
          for (int k = 0; k < 4; ++k) {
            std::array<int, 3> g = c;
            g[axis] += dir;
            g[u] += du[k];
            g[v] += dv[k];
            q[k] = vertex(g);
          }
          if (dir == 1) {
            triangles.push_back({q[0], q[1], q[2]});
            triangles.push_back({q[0], q[2], q[3]});
          } else {
            triangles.push_back({q[0], q[2], q[1]});
            triangles.push_back({q[0], q[3], q[2]});
          }
        }
    return SolidAccess::assume_valid(std::move(vertices), std::move(triangles));
  }

  // The filled cells as boxes (low corner, high corner).
  std::vector<std::pair<Vec3, Vec3>> boxes() const {
    std::vector<std::pair<Vec3, Vec3>> out;
    for (const auto& c : cells)
      out.emplace_back(Vec3{grid[0][c[0]], grid[1][c[1]], grid[2][c[2]]},
                       Vec3{grid[0][c[0] + 1], grid[1][c[1] + 1], grid[2][c[2] + 1]});
    return out;
  }

  // Closed membership: p lies in a closed filled cell.
  bool contains(const Vec3& p) const {
    std::array<std::vector<int>, 3> spans;
    for (int axis = 0; axis < 3; ++axis)
      for (std::size_t i = 0; i + 1 < grid[axis].size(); ++i)
        if (grid[axis][i] <= p[axis] && p[axis] <= grid[axis][i + 1]) spans[axis].push_back(static_cast<int>(i));
    for (int i : spans[0])
      for (int j : spans[1])
        for (int k : spans[2])
          if (filled({i, j, k})) return true;
    return false;
  }
};

inline std::vector<Rational> units(int n) {
  std::vector<Rational> g;
  for (int i = 0; i <= n; ++i) g.push_back(Rational(i));
  return g;
}

inline GridSolid unit_grid(int nx, int ny, int nz, const std::function<bool(int, int, int)>& fill) {
  GridSolid s{{units(nx), units(ny), units(nz)}, {}};
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        if (fill(i, j, k)) s.cells.insert({i, j, k});
  return s;
}

}  // namespace cvms::test
