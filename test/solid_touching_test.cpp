// SPDX-License-Identifier: MIT
// Solids whose parts touch along an edge or at a point (cvms/solid.hpp),
// against the voxel oracle (support/voxel_oracle.hpp), which never runs the
// library: polycubes whose cubes meet only along an edge or at a corner,
// given in the shared-index form (polycube_soup: an edge on four faces, a
// vertex with several fans) or as the sums write them (a point repeated per
// shell), are read with the volume, vertex points, facets, shells and
// containment of their cubes; summed with boxes and with each other they
// give the voxels of the sum; a written sum reads back, checks and sums
// again to the voxels of the twice-dilated cubes. Surfaces that cross,
// touch a face's interior or do not close are refused with located errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/io.hpp"
#include "solid_sum_fixtures.hpp"

namespace cvms::test {
namespace {

// The polycube through Solid::from_soup (the validation under test), mapped.
Solid touching_polycube(const Cubes& cubes, const Mapping& m = {}) {
  PolygonSoup soup = polycube_soup(cubes);
  for (Vec3& p : soup.points) p = m(p);
  return Solid::from_soup(std::move(soup));
}

Cubes edge_pair() { return {{0, 0, 0}, {1, 1, 0}}; }    // along x = y = 1
Cubes corner_pair() { return {{0, 0, 0}, {1, 1, 1}}; }  // at (1, 1, 1)
// The even cells of a 2 x 2 x 2 grid: four cubes, each pair along an edge
// through the centre, all four at the centre.
Cubes checker() {
  return cubes_where(2, 2, 2, [](int i, int j, int k) { return (i + j + k) % 2 == 0; });
}
// A 3 x 3 x 3 block with its centre cube empty (a cavity) and the cube at
// `notch` empty on its surface: the cavity touches the outside along an
// edge or at a corner.
Cubes cavity_touching_notch(const Cube& notch) {
  return cubes_where(3, 3, 3, [&](int i, int j, int k) {
    const Cube c{i, j, k};
    return c != Cube{1, 1, 1} && c != notch;
  });
}

struct Case {
  const char* name;
  Cubes cubes;
  std::uint32_t shells;
  std::uint32_t cavities;
};

std::vector<Case> touching_cases() {
  return {{"edge pair", edge_pair(), 2, 0},
          {"corner pair", corner_pair(), 2, 0},
          {"checker", checker(), 4, 0},
          {"cavity touching a notch along an edge", cavity_touching_notch({2, 2, 1}), 2, 1},
          {"cavity touching a notch at a corner", cavity_touching_notch({2, 2, 2}), 2, 1},
          {"L with a cube on its corner", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}}, 2, 0}};
}

// Containment of random grid-fraction points (many exactly on faces, edges
// and the touching points) against the closed cubes.
void expect_containment(const Solid& solid, const Cubes& cubes, const Mapping& m, std::uint64_t seed) {
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937_64 rng(seed);
  for (int k = 0; k < 400; ++k) {
    Vec3 g;
    for (int i = 0; i < 3; ++i) {
      g[i] = Rational(static_cast<long>(rng() % 17) - 2, 4);
      g[i].canonicalize();
    }
    EXPECT_EQ(solid.contains(m(g)), voxel_contains(cubes, g)) << text(g);
  }
}

Mapping turned() { return {rational_rotation(), Vec3{Rational(1, 3), Rational(-5, 7), Rational(2)}}; }

TEST(TouchingSolid, SharedIndexPolycubesReadAsTheirCubes) {
  for (const Case& c : touching_cases())
    for (const Mapping& m : {Mapping{}, turned()}) {
      SCOPED_TRACE(c.name);
      const Solid solid = touching_polycube(c.cubes, m);
      // The read solid keeps every corner of the unit squares (vertices are
      // never dropped); its facets are the voxels'.
      EXPECT_EQ(solid.volume(), Rational(static_cast<long>(c.cubes.size())) * m.linear.determinant());
      std::set<Vec3> corners;
      for (const Vec3& p : polycube_soup(c.cubes).points) corners.insert(m(p));
      EXPECT_EQ(vertex_coordinates(solid), corners);
      EXPECT_EQ(solid.num_facets(), voxel_facets(c.cubes));
      EXPECT_EQ(solid.num_shells(), c.shells);
      EXPECT_EQ(solid.num_cavities(), c.cavities);
      EXPECT_EQ(solid.genus(), 0u);
      expect_containment(solid, c.cubes, m, c.cubes.size());
      Rational pieces_volume = 0;
      const ConvexUnion pieces = convex_decomposition(solid);
      for (const ConvexPolyhedron& piece : pieces.pieces())
        pieces_volume += volume_by_tetrahedra(piece);
      EXPECT_EQ(pieces_volume, solid.volume());
    }
}

TEST(TouchingSolid, EveryShellIsAClosedTwoManifoldByIndex) {
  // Each edge of the triangles (by vertex index) on exactly two, opposite.
  for (const Case& c : touching_cases()) {
    SCOPED_TRACE(c.name);
    const Solid solid = touching_polycube(c.cubes);
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (const auto& t : solid.triangles())
      for (int i = 0; i < 3; ++i) ++uses[{t[i], t[(i + 1) % 3]}];
    for (const auto& [edge, count] : uses) {
      EXPECT_EQ(count, 1);
      EXPECT_EQ(uses.count({edge.second, edge.first}), 1u);
    }
  }
}

TEST(TouchingSolid, SumsWithBoxesAndWithEachOtherAreTheVoxelSums) {
  const std::vector<std::pair<Cubes, Cubes>> pairs = {
      {edge_pair(), box_cubes(1, 1, 1)},  {corner_pair(), box_cubes(2, 1, 1)},
      {checker(), box_cubes(1, 1, 1)},    {cavity_touching_notch({2, 2, 2}), box_cubes(1, 1, 1)},
      {edge_pair(), corner_pair()},       {checker(), edge_pair()}};
  std::uint64_t seed = 100;
  for (const auto& [a, b] : pairs)
    for (const Mapping& m : {Mapping{}, turned()}) {
      SCOPED_TRACE("pair " + std::to_string(seed));
      const Solid sum = minkowski_sum(touching_polycube(a, m), touching_polycube(b, m));
      const Mapping twice{m.linear, m.offset + m.offset};
      const Cubes expected = polycube_sum(a, b);
      expect_voxels(sum, expected, twice);
      expect_containment(sum, expected, twice, ++seed);
    }
}

// Random subsets of a 3 x 3 x 2 grid (fixed seeds): cubes touching in every
// way, rings whose ends meet along an edge among them. Each is a solid with
// the cubes' volume, facets and containment; some are summed with a box.
TEST(TouchingSolid, RandomPolycubesAreSolidsAndSumToTheirVoxels) {
  for (std::uint64_t seed = 1; seed <= 120; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    const Cubes cubes = cubes_where(3, 3, 2, [&](int, int, int) { return rng() % 2 == 0; });
    if (cubes.empty()) continue;
    const Solid solid = touching_polycube(cubes);
    EXPECT_EQ(solid.volume(), Rational(static_cast<long>(cubes.size())));
    EXPECT_EQ(solid.num_facets(), voxel_facets(cubes));
    expect_containment(solid, cubes, {}, seed);
    if (seed % 4 != 0) continue;
    // Voxels, brute force over the pieces and their planes, as the soak run.
    expect_polycube_sum(cubes, box_cubes(1, 1 + static_cast<int>(seed % 3), 1), {}, seed);
  }
}

// The soup written as OFF and read back.
Solid written_and_read(const PolygonSoup& soup) {
  std::ostringstream out;
  write_off(out, soup);
  std::istringstream in(out.str());
  return Solid::from_soup(read_off(in, "<written>"));
}

TEST(TouchingSolid, WrittenSumsReadBackAndSumAgain) {
  // Cubes apart grown by a unit cube until they touch along an edge, at a
  // corner; the written sum (a point once per shell) read back and summed
  // with a unit cube again.
  for (const Cubes& apart : {Cubes{{0, 0, 0}, {2, 2, 0}}, Cubes{{0, 0, 0}, {2, 2, 2}}}) {
    const Cubes unit = box_cubes(1, 1, 1);
    const Solid sum = minkowski_sum(touching_polycube(apart), touching_polycube(unit));
    const Solid back = written_and_read(sum.to_soup());
    const Cubes once = polycube_sum(apart, unit);
    expect_voxels(back, once);
    EXPECT_EQ(back.num_shells(), 2u);
    std::vector<Vec3> written(sum.vertices().begin(), sum.vertices().end());
    std::vector<Vec3> read(back.vertices().begin(), back.vertices().end());
    std::sort(written.begin(), written.end());
    std::sort(read.begin(), read.end());
    EXPECT_EQ(read, written);  // the touching points once per shell, as written
    const Solid again = minkowski_sum(back, touching_polycube(unit));
    expect_voxels(again, polycube_sum(once, unit));
    const Solid with_touching = minkowski_sum(back, touching_polycube(corner_pair()));
    expect_voxels(with_touching, polycube_sum(once, corner_pair()));
  }
}

// The located error of Solid::from_soup on a soup, or a failure.
void expect_refused(const PolygonSoup& soup, const std::vector<std::string>& parts) {
  try {
    (void)Solid::from_soup(soup);
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::topology) << e.what();
    for (const std::string& part : parts) EXPECT_NE(std::string(e.message()).find(part), std::string::npos) << e.message();
  }
}

// The soups of two solids side by side (b's indices after a's).
PolygonSoup joined(const PolygonSoup& a, const PolygonSoup& b) {
  PolygonSoup soup = a;
  const auto shift = static_cast<std::uint32_t>(a.points.size());
  soup.points.insert(soup.points.end(), b.points.begin(), b.points.end());
  for (std::size_t f = 0; f < b.num_faces(); ++f) {
    std::vector<std::uint32_t> face;
    for (std::uint32_t v : b.face(f)) face.push_back(v + shift);
    soup.add_face(face);
  }
  return soup;
}

PolygonSoup moved(PolygonSoup soup, const Vec3& t) {
  for (Vec3& p : soup.points) p += t;
  return soup;
}

PolygonSoup reversed(PolygonSoup soup) {
  PolygonSoup out;
  out.points = soup.points;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    std::vector<std::uint32_t> face(soup.face(f).begin(), soup.face(f).end());
    std::reverse(face.begin(), face.end());
    out.add_face(face);
  }
  return out;
}

TEST(TouchingSolid, CrossingOrOpenSurfacesAreRefusedWithLocatedErrors) {
  const PolygonSoup cube = polycube_soup(box_cubes(1, 1, 1));
  SCOPED_TRACE("shells that cross");
  expect_refused(joined(cube, moved(cube, Vec3{Rational(1, 2), Rational(1, 2), Rational(1, 2)})),
                 {"faces ", "intersect (self-intersecting surface)"});
  SCOPED_TRACE("a corner on the interior of another's face");
  expect_refused(joined(cube, moved(cube, Vec3{Rational(1, 2), 1, Rational(1, 3)})),
                 {"faces ", "intersect (self-intersecting surface)"});
  SCOPED_TRACE("cubes sharing a face (overlap in an area)");
  expect_refused(joined(cube, moved(cube, Vec3{1, 0, 0})), {"intersect (self-intersecting surface)"});
  SCOPED_TRACE("an inward cube along an outward cube's edge: the wedges overlap");
  expect_refused(joined(cube, reversed(moved(cube, Vec3{1, 1, 0}))), {"edge (", "do not alternate"});
  SCOPED_TRACE("a face missing next to the touching edge");
  PolygonSoup open = polycube_soup(edge_pair());
  PolygonSoup without;
  without.points = open.points;
  for (std::size_t f = 1; f < open.num_faces(); ++f)
    without.add_face(std::vector<std::uint32_t>(open.face(f).begin(), open.face(f).end()));
  expect_refused(without, {"open surface"});
}

}  // namespace
}  // namespace cvms::test
