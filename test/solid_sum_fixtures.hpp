// SPDX-License-Identifier: MIT
// Fixtures and checks of the sums of solids (solid_sum_test.cpp and its
// soak run): polycubes as solids (GridSolid's triangles, placed by a map
// x -> M x + t), and the checks of a result against oracles that never run
// the boundary code: the voxel oracle (support/voxel_oracle.hpp), brute
// force over the pairwise sums of the decompositions' pieces
// (support/union_oracle.hpp), and the pieces' facet planes.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "cvms/decomposition.hpp"
#include "cvms/solid_sum.hpp"
#include "decomposition_fixtures.hpp"
#include "support/union_oracle.hpp"
#include "support/voxel_oracle.hpp"

namespace cvms::test {

// A polycube as a solid (GridSolid's triangles), mapped by m (det > 0).
// Cubes that meet only along an edge or at a corner need their shells
// split there, which assume_valid does not do: such a polycube is validated
// from its squares (Solid::from_soup), which gives each shell its vertices.
inline Solid polycube(const Cubes& cubes, const Mapping& m = {}) {
  {
    PolygonSoup soup = polycube_soup(cubes);
    const std::size_t corners = soup.points.size();
    for (Vec3& p : soup.points) p = m(p);
    Solid split = Solid::from_soup(std::move(soup));
    if (split.vertices().size() != corners) return split;
  }
  int n = 1;
  for (const Cube& c : cubes) n = std::max({n, c[0] + 1, c[1] + 1, c[2] + 1});
  GridSolid grid{{units(n), units(n), units(n)}, Cells(cubes.begin(), cubes.end())};
  const Solid s = grid.solid();
  std::vector<Vec3> vertices;
  for (const Vec3& p : s.vertices()) vertices.push_back(m(p));
  Triangles triangles(s.triangles().begin(), s.triangles().end());
  return SolidAccess::assume_valid(std::move(vertices), std::move(triangles));
}

inline Cubes cubes_where(int nx, int ny, int nz, const std::function<bool(int, int, int)>& fill) {
  Cubes out;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        if (fill(i, j, k)) out.insert({i, j, k});
  return out;
}

inline Cubes l_shape() { return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}; }

// A square frame of side n around a hole of side n - 2, one cube high.
inline Cubes frame(int n) {
  return cubes_where(n, n, 1,
                     [n](int i, int j, int) { return i == 0 || j == 0 || i == n - 1 || j == n - 1; });
}

// A cube of side n with a cubic cavity of side n - 2.
inline Cubes hollow_cube(int n) {
  return cubes_where(n, n, n, [n](int i, int j, int k) {
    return i == 0 || j == 0 || k == 0 || i == n - 1 || j == n - 1 || k == n - 1;
  });
}

inline std::string text(const Vec3& p) {
  return "(" + to_string(p.x) + ", " + to_string(p.y) + ", " + to_string(p.z) + ")";
}

inline std::set<Vec3> vertex_coordinates(const Solid& s) {
  return {s.vertices().begin(), s.vertices().end()};
}

// x with M x + t == y, by Cramer's rule.
inline Vec3 unmapped(const Vec3& y, const Mapping& m) {
  const Vec3 b = y - m.offset;
  const Rational det = m.linear.determinant();
  Vec3 x;
  for (int column = 0; column < 3; ++column) {
    Mat3 replaced = m.linear;
    for (int row = 0; row < 3; ++row) replaced.m[row][column] = b[row];
    x[column] = replaced.determinant() / det;
  }
  return x;
}

// Volume, vertices and facets against the voxels of the expected sum.
inline void expect_voxels(const Solid& result, const Cubes& sum, const Mapping& m = {}) {
  EXPECT_EQ(result.volume(), Rational(static_cast<long>(sum.size())) * m.linear.determinant());
  std::set<Vec3> expected;
  for (const Cube& g : voxel_vertices(sum))
    expected.insert(m(Vec3{Rational(g[0]), Rational(g[1]), Rational(g[2])}));
  EXPECT_EQ(vertex_coordinates(result), expected);
  EXPECT_EQ(result.num_facets(), voxel_facets(sum));
}

inline Rational small_step(const Vec3& n) {
  Rational largest = 1;
  for (int i = 0; i < 3; ++i) largest = std::max(largest, Rational(abs(n[i])));
  return Rational(1, 1024) / largest;
}

// Points on the output (its triangles' corners, edge midpoints and
// centroids, which locate must call boundary), next to it (centroids moved
// along the facet normal, corners along a diagonal) and random ones in its
// box; each checked against the brute force over the pieces, and against
// `other` when given (closed containment).
inline void expect_points(const Solid& result, const ConvexUnion& pieces, std::uint64_t seed,
                          const std::function<bool(const Vec3&)>& other = {}) {
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::vector<Vec3> on, near;
  const auto vertices = result.vertices();
  const auto triangles = result.triangles();
  const std::size_t stride = std::max<std::size_t>(1, triangles.size() / 150);
  for (std::size_t t = 0; t < triangles.size(); t += stride) {
    const Vec3 &a = vertices[triangles[t][0]], &b = vertices[triangles[t][1]], &c = vertices[triangles[t][2]];
    const Vec3 centroid = Rational(1, 3) * (a + b + c);
    on.insert(on.end(), {a, Rational(1, 2) * (a + b), Rational(1, 2) * (b + c), centroid});
    const Vec3& n = result.facet_normal(result.triangle_facets()[t]);
    const Rational step = small_step(n);
    near.insert(near.end(), {centroid + step * n, centroid - step * n});
    const Vec3 diagonal{Rational(1, 1024), Rational(1, 2048), Rational(-1, 4096)};
    near.insert(near.end(), {a + diagonal, a - diagonal});
  }
  std::mt19937_64 rng(seed);
  std::vector<Vec3> random;
  Vec3 low = vertices[0], high = vertices[0];
  for (const Vec3& p : vertices)
    for (int i = 0; i < 3; ++i) {
      low[i] = std::min(low[i], p[i]);
      high[i] = std::max(high[i], p[i]);
    }
  for (int k = 0; k < 300; ++k) {
    Vec3 p;
    for (int i = 0; i < 3; ++i) {
      // low - 1 + r / q for r in [0, (high - low + 2) q].
      const auto q = static_cast<long>(1 + rng() % 16);
      const Rational span = (high[i] - low[i] + 2) * q;
      const auto steps = static_cast<std::uint64_t>(span.get_d()) + 1;
      Rational r(static_cast<long>(rng() % steps), q);
      r.canonicalize();
      p[i] = low[i] - 1 + r;
    }
    random.push_back(p);
  }
  for (const Vec3& p : on) {
    EXPECT_EQ(result.locate(p), Location::boundary) << text(p);
    EXPECT_TRUE(union_contains_brute_force(pieces, p)) << text(p);
  }
  for (const auto* points : {&near, &random})
    for (const Vec3& p : *points) {
      const bool brute = union_contains_brute_force(pieces, p);
      EXPECT_EQ(result.contains(p), brute) << text(p);
      if (other) {
        EXPECT_EQ(other(p), brute) << text(p);
      }
    }
}

// Every vertex on three facet planes of the pieces with independent normals.
inline void expect_vertices_on_piece_planes(const Solid& result, const ConvexUnion& pieces) {
  for (const Vec3& v : vertex_coordinates(result)) {
    std::vector<Vec3> normals;
    for (const ConvexPolyhedron& piece : pieces.pieces())
      for (FaceId f : piece.mesh().faces())
        if (dot(piece.normal(f), v) == piece.plane_offset(f)) normals.push_back(piece.normal(f));
    bool independent = false;
    for (std::size_t i = 0; i < normals.size() && !independent; ++i)
      for (std::size_t j = i + 1; j < normals.size() && !independent; ++j) {
        const Vec3 c = cross(normals[i], normals[j]);
        if (c == Vec3{}) continue;
        for (std::size_t k = j + 1; k < normals.size() && !independent; ++k)
          independent = dot(c, normals[k]) != 0;
      }
    EXPECT_TRUE(independent) << text(v) << " lies on " << normals.size()
                             << " piece planes, not three independent";
  }
}

// Everything above for a sum of two polycubes placed by m (the second one's
// offset is m's too, so the sum's offset is 2 t).
inline void expect_polycube_sum(const Cubes& a, const Cubes& b, const Mapping& m, std::uint64_t seed) {
  const Solid sa = polycube(a, m), sb = polycube(b, m);
  const Solid result = minkowski_sum(sa, sb);
  const Cubes sum = polycube_sum(a, b);
  const Mapping twice{m.linear, m.offset + m.offset};
  expect_voxels(result, sum, twice);
  const ConvexUnion pieces = minkowski_sum_pieces(sa, sb);
  expect_points(result, pieces, seed, [&](const Vec3& p) { return voxel_contains(sum, unmapped(p, twice)); });
  expect_vertices_on_piece_planes(result, pieces);
}

// The matrix with these 9 entries, row-major.
inline Mat3 matrix(const std::vector<Rational>& entries) {
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m.m[i][j] = entries[static_cast<std::size_t>(3 * i + j)];
  return m;
}

// A rotation with rational entries (two 3-4-5 turns about different axes).
inline Mat3 rational_rotation() {
  const Mat3 z = matrix({Rational(3, 5), Rational(-4, 5), 0, Rational(4, 5), Rational(3, 5), 0, 0, 0, 1});
  const Mat3 x =
      matrix({1, 0, 0, 0, Rational(5, 13), Rational(-12, 13), 0, Rational(12, 13), Rational(5, 13)});
  return z * x;
}

// A random height field on a 4 x 3 grid, h(i, j) = max(f(i), g(j)) with
// f, g in 1..3 drawn from `seed`: no two of its cubes meet only along an
// edge or at a point, so it is a solid.
inline Cubes random_height_field(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<int> f(4), g(3);
  for (int& h : f) h = 1 + static_cast<int>(rng() % 3);
  for (int& h : g) h = 1 + static_cast<int>(rng() % 3);
  return cubes_where(4, 3, 3, [&](int i, int j, int k) {
    return k < std::max(f[static_cast<std::size_t>(i)], g[static_cast<std::size_t>(j)]);
  });
}

// The map of the decimal-coordinate tests: rational_rotation() and a
// decimal offset.
inline Mapping decimal_rotation() {
  return {rational_rotation(), Vec3{Rational(1, 10), Rational(-3, 10), Rational(7, 100)}};
}

}  // namespace cvms::test
