// SPDX-License-Identifier: MIT
// The assembly of a union's boundary (boundary_assembly.hpp) from fragments
// made by hand: the boundary faces of sets of unit cubes (voxels), each face
// cut into irregular pieces (seeded), and hand-written polygons. Oracles:
// vertex, facet, shell, cavity and genus counts and volumes counted by hand
// from the shapes; the mesh's combinatorics checked by brute force (every
// edge by index in exactly two triangles, opposite ways; no vertex inside an
// edge; no zero-area triangle); the result re-validated by Solid::from_soup
// where the set is a manifold.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "boundary_assembly.hpp"
#include "cvms/convex_polyhedron.hpp"
#include "cvms/error.hpp"
#include "cvms/predicates.hpp"
#include "cvms/solid.hpp"

namespace {

using cvms::Error;
using cvms::ErrorCategory;
using cvms::Rational;
using cvms::Solid;
using cvms::Vec3;
using cvms::detail::assemble_boundary;
using cvms::detail::BoundaryFragments;
using Voxel = std::array<int, 3>;

// Fragments on oriented planes, each plane given by its primitive normal and offset.
class FragmentBuilder {
 public:
  // Adds the polygon with outward normal `normal` (primitive), reordering
  // its corners counterclockwise seen from outside.
  void add(const Vec3& normal, std::vector<Vec3> corners) {
    Vec3 area{0, 0, 0};
    for (std::size_t i = 0; i < corners.size(); ++i)
      area += cross(corners[i], corners[(i + 1) % corners.size()]);
    if (sgn(dot(area, normal)) < 0) std::reverse(corners.begin(), corners.end());
    const Rational offset = dot(normal, corners[0]);
    const auto key = std::make_tuple(normal, offset);
    auto it = index_.find(key);
    if (it == index_.end()) {
      it = index_.emplace(key, static_cast<std::uint32_t>(out_.planes.size())).first;
      out_.planes.push_back({normal, offset});
    }
    out_.fragments.push_back({it->second, std::move(corners)});
  }
  [[nodiscard]] const BoundaryFragments& fragments() const { return out_; }

 private:
  struct KeyLess {
    bool operator()(const std::tuple<Vec3, Rational>& a, const std::tuple<Vec3, Rational>& b) const {
      if (std::get<0>(a) != std::get<0>(b)) return std::get<0>(a) < std::get<0>(b);
      return std::get<1>(a) < std::get<1>(b);
    }
  };
  BoundaryFragments out_;
  std::map<std::tuple<Vec3, Rational>, std::uint32_t, KeyLess> index_;
};

// The boundary faces of a set of voxels, each unit square cut into pieces
// of one of five kinds chosen by `rng` (whole, two triangles, two halves,
// a half and two quarters, four triangles about the centre).
BoundaryFragments voxel_fragments(const std::vector<Voxel>& voxels, std::mt19937& rng) {
  const std::set<Voxel> set(voxels.begin(), voxels.end());
  FragmentBuilder builder;
  const Rational h(1, 2);
  using P2 = std::array<Rational, 2>;
  const std::vector<std::vector<std::vector<P2>>> kinds = {
      {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}},
      {{{0, 0}, {1, 0}, {1, 1}}, {{0, 0}, {1, 1}, {0, 1}}},
      {{{0, 0}, {h, 0}, {h, 1}, {0, 1}}, {{h, 0}, {1, 0}, {1, 1}, {h, 1}}},
      {{{0, 0}, {h, 0}, {h, 1}, {0, 1}}, {{h, 0}, {1, 0}, {1, h}, {h, h}}, {{h, h}, {1, h}, {1, 1}, {h, 1}}},
      {{{0, 0}, {1, 0}, {h, h}}, {{1, 0}, {1, 1}, {h, h}}, {{1, 1}, {0, 1}, {h, h}}, {{0, 1}, {0, 0}, {h, h}}},
  };
  for (const Voxel& v : voxels)
    for (int a = 0; a < 3; ++a)
      for (int s : {-1, 1}) {
        Voxel n = v;
        n[a] += s;
        if (set.count(n) != 0) continue;
        Vec3 normal{0, 0, 0};
        normal[a] = s;
        const auto& kind = kinds[std::uniform_int_distribution<std::size_t>(0, kinds.size() - 1)(rng)];
        for (const auto& piece : kind) {
          std::vector<Vec3> corners;
          for (const P2& st : piece) {
            Vec3 p;
            p[a] = v[a] + (s > 0 ? 1 : 0);
            p[(a + 1) % 3] = v[(a + 1) % 3] + st[0];
            p[(a + 2) % 3] = v[(a + 2) % 3] + st[1];
            corners.push_back(p);
          }
          builder.add(normal, std::move(corners));
        }
      }
  return builder.fragments();
}

// The fragments under the shear x -> M x, M = [[1, 1/2, 0], [0, 1, 1/3],
// [1/5, 0, 1]] (det 31/30 > 0: orientation kept, volumes times 31/30), so
// that every plane is slanted and the charts of all three axes are used.
BoundaryFragments sheared(const BoundaryFragments& in) {
  const auto map = [](const Vec3& p) {
    return Vec3{p.x + Rational(1, 2) * p.y, p.y + Rational(1, 3) * p.z, Rational(1, 5) * p.x + p.z};
  };
  FragmentBuilder builder;
  for (const auto& f : in.fragments) {
    std::vector<Vec3> corners;
    for (const Vec3& c : f.corners) corners.push_back(map(c));
    Vec3 area{0, 0, 0};
    for (std::size_t i = 0; i < corners.size(); ++i) area += cross(corners[i], corners[(i + 1) % corners.size()]);
    builder.add(cvms::primitive_direction(area), std::move(corners));
  }
  return builder.fragments();
}

cvms::Options with_threads(unsigned threads) {
  cvms::Options options;
  options.threads = threads;
  return options;
}

bool strictly_inside_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  if (p == a || p == b || !cvms::is_parallel(b - a, p - a)) return false;
  for (int k = 0; k < 3; ++k)
    if (p[k] < std::min(a[k], b[k]) || p[k] > std::max(a[k], b[k])) return false;
  return true;
}

// The brute-force checks every assembled boundary must pass.
void check_mesh(const Solid& s) {
  const auto vertices = s.vertices();
  const auto triangles = s.triangles();
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : triangles) {
    EXPECT_FALSE(cvms::is_zero(cross(vertices[t[1]] - vertices[t[0]], vertices[t[2]] - vertices[t[0]])));
    for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
    const auto back = directed.find({edge.second, edge.first});
    EXPECT_TRUE(back != directed.end() && back->second == 1) << "edge " << edge.first << "-" << edge.second;
    for (const Vec3& p : vertices)
      EXPECT_FALSE(strictly_inside_segment(p, vertices[edge.first], vertices[edge.second]))
          << "a vertex inside edge " << edge.first << "-" << edge.second;
  }
  // Every vertex is used.
  std::vector<bool> used(vertices.size(), false);
  for (const auto& t : triangles)
    for (auto c : t) used[c] = true;
  EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool b) { return b; }));
}

// For a manifold set: the soup passes the full validation, with the same properties.
void check_revalidates(const Solid& s) {
  const Solid again = Solid::from_soup(s.to_soup());
  EXPECT_EQ(again.volume(), s.volume());
  EXPECT_EQ(again.num_shells(), s.num_shells());
  EXPECT_EQ(again.num_cavities(), s.num_cavities());
  EXPECT_EQ(again.genus(), s.genus());
  EXPECT_EQ(again.num_facets(), s.num_facets());
}

struct Counts {
  std::size_t vertices;
  std::uint32_t facets, shells, cavities, genus;
  Rational volume;
};

void expect_counts(const Solid& s, const Counts& c) {
  EXPECT_EQ(s.vertices().size(), c.vertices);
  EXPECT_EQ(s.num_facets(), c.facets);
  EXPECT_EQ(s.num_shells(), c.shells);
  EXPECT_EQ(s.num_cavities(), c.cavities);
  EXPECT_EQ(s.genus(), c.genus);
  EXPECT_EQ(s.volume(), c.volume);
}

// Assembles the voxels' fragments under several seeds, on one thread and
// on two (same bytes), and checks the hand counts and the mesh.
void check_voxels(const std::vector<Voxel>& voxels, const Counts& counts, bool manifold) {
  for (unsigned seed : {1U, 2U, 3U, 4U}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    const BoundaryFragments fragments = voxel_fragments(voxels, rng);
    const Solid s = assemble_boundary(fragments, with_threads(1));
    expect_counts(s, counts);
    check_mesh(s);
    if (manifold) check_revalidates(s);
    const Solid t = assemble_boundary(fragments, with_threads(2));
    EXPECT_TRUE(std::equal(s.vertices().begin(), s.vertices().end(), t.vertices().begin(), t.vertices().end()));
    EXPECT_TRUE(std::equal(s.triangles().begin(), s.triangles().end(), t.triangles().begin(), t.triangles().end()));
    Counts slanted = counts;
    slanted.volume *= Rational(31, 30);
    const Solid u = assemble_boundary(sheared(fragments), with_threads(1));
    expect_counts(u, slanted);
    check_mesh(u);
  }
}

std::vector<Voxel> box(int nx, int ny, int nz) {
  std::vector<Voxel> out;
  for (int x = 0; x < nx; ++x)
    for (int y = 0; y < ny; ++y)
      for (int z = 0; z < nz; ++z) out.push_back({x, y, z});
  return out;
}

TEST(BoundaryAssembly, CubeFromManyIrregularPieces) {
  // 3 x 3 x 3 voxels: 54 unit squares cut further, T-junctions everywhere.
  check_voxels(box(3, 3, 3), {8, 6, 1, 0, 0, 27}, true);
}

TEST(BoundaryAssembly, LShapeAndStaircase) {
  // The L prism: an L of 6 corners extruded, 12 vertices, 2 + 6 facets.
  check_voxels({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {12, 8, 1, 0, 0, 3}, true);
  // A staircase of 3, 2 and 1 voxels: a profile of 8 corners, extruded.
  check_voxels({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 0, 1}, {2, 0, 1}, {2, 0, 2}}, {16, 10, 1, 0, 0, 6}, true);
}

TEST(BoundaryAssembly, FrameHasGenusOneAndCubeWithCavityTwoShells) {
  std::vector<Voxel> frame;
  for (const Voxel& v : box(3, 3, 1))
    if (v != Voxel{1, 1, 0}) frame.push_back(v);
  // Top and bottom (each a square with a square hole), 4 outer and 4 inner sides.
  check_voxels(frame, {16, 10, 1, 0, 1, 8}, true);
  std::vector<Voxel> hollow;
  for (const Voxel& v : box(3, 3, 3))
    if (v != Voxel{1, 1, 1}) hollow.push_back(v);
  check_voxels(hollow, {16, 12, 2, 1, 0, 26}, true);
}

TEST(BoundaryAssembly, FacetWithHoleUsesOnlyFragmentCorners) {
  std::vector<Voxel> frame;
  for (const Voxel& v : box(3, 3, 1))
    if (v != Voxel{1, 1, 0}) frame.push_back(v);
  std::mt19937 rng(7);
  const BoundaryFragments fragments = voxel_fragments(frame, rng);
  std::set<Vec3> corners;
  for (const auto& f : fragments.fragments) corners.insert(f.corners.begin(), f.corners.end());
  const Solid s = assemble_boundary(fragments, with_threads(1));
  for (const Vec3& v : s.vertices()) EXPECT_EQ(corners.count(v), 1U);
  // The top facet (z = 1, facing +z): 3 x 3 minus the 1 x 1 hole.
  Rational top_area;
  std::set<std::uint32_t> top_facets;
  for (std::size_t t = 0; t < s.triangles().size(); ++t) {
    const auto& tri = s.triangles()[t];
    const auto& p = s.vertices();
    if (p[tri[0]].z != 1 || p[tri[1]].z != 1 || p[tri[2]].z != 1) continue;
    const Vec3 area = cross(p[tri[1]] - p[tri[0]], p[tri[2]] - p[tri[0]]);
    top_area += area.z / 2;
    top_facets.insert(s.triangle_facets()[t]);
  }
  EXPECT_EQ(top_area, 8);
  EXPECT_EQ(top_facets.size(), 1U);
}

TEST(BoundaryAssembly, TJunctionVertexIsInsertedIntoTheStraightEdge) {
  // A unit cube and, beside it on x in [1, 2], a wedge whose cross-section in
  // (y, z) is (0, 0), (1, 0), (1, 1): its slanted facet (y = z) meets the
  // cube's front facet (y = 0) at (1, 0, 0), a true vertex inside the
  // bottom's straight edge from (0, 0, 0) to (2, 0, 0); likewise (1, 1, 1)
  // inside the back's top edge. Hand count: 10 vertices, 8 facets (left,
  // bottom, back, front, top, the cube's uncovered triangle at x = 1, the
  // slanted one, the wedge's end), volume 1 + 1/2.
  FragmentBuilder b;
  b.add({-1, 0, 0}, {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}});
  b.add({0, 0, -1}, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  b.add({0, 0, -1}, {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}});
  b.add({0, 1, 0}, {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}});
  b.add({0, 1, 0}, {{1, 1, 0}, {2, 1, 0}, {2, 1, 1}, {1, 1, 1}});
  b.add({0, -1, 0}, {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}});
  b.add({0, 0, 1}, {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}});
  b.add({1, 0, 0}, {{1, 0, 0}, {1, 1, 1}, {1, 0, 1}});
  b.add({0, -1, 1}, {{1, 0, 0}, {2, 0, 0}, {2, 1, 1}, {1, 1, 1}});
  b.add({1, 0, 0}, {{2, 0, 0}, {2, 1, 0}, {2, 1, 1}});
  const Solid s = assemble_boundary(b.fragments(), with_threads(1));
  expect_counts(s, {10, 8, 1, 0, 0, Rational(3, 2)});
  check_mesh(s);
  check_revalidates(s);
  const auto v = s.vertices();
  EXPECT_NE(std::find(v.begin(), v.end(), Vec3{1, 0, 0}), v.end());
  EXPECT_NE(std::find(v.begin(), v.end(), Vec3{1, 1, 1}), v.end());
  EXPECT_EQ(std::find(v.begin(), v.end(), Vec3{1, 1, 0}), v.end());  // not a true vertex
}

std::size_t distinct_points(const Solid& s) {
  return std::set<Vec3>(s.vertices().begin(), s.vertices().end()).size();
}

// The triangles of each shell (connected through shared vertex indices) as a soup of its own.
std::vector<cvms::PolygonSoup> shell_soups(const Solid& s) {
  const auto triangles = s.triangles();
  std::vector<std::uint32_t> parent(s.vertices().size());
  for (std::uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
  const auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x];
    return x;
  };
  for (const auto& t : triangles)
    for (int i = 1; i < 3; ++i) parent[find(t[i])] = find(t[0]);
  std::map<std::uint32_t, cvms::PolygonSoup> by_root;
  for (const auto& t : triangles) {
    cvms::PolygonSoup& soup = by_root[find(t[0])];
    std::array<std::uint32_t, 3> face{};
    for (int i = 0; i < 3; ++i) {
      face[i] = static_cast<std::uint32_t>(soup.points.size());
      soup.points.push_back(s.vertices()[t[i]]);
    }
    soup.add_face(face);
  }
  std::vector<cvms::PolygonSoup> out;
  for (auto& [root, soup] : by_root) out.push_back(std::move(soup));
  return out;
}

TEST(BoundaryAssembly, CubesTouchingAlongAnEdgeOrAtAPointMakeTwoShells) {
  // Along the edge x = y = 1: 14 points, the edge's two ends duplicated.
  check_voxels({{0, 0, 0}, {1, 1, 0}}, {16, 12, 2, 0, 0, 2}, false);
  std::mt19937 rng(5);
  const Solid edge = assemble_boundary(voxel_fragments({{0, 0, 0}, {1, 1, 0}}, rng), with_threads(1));
  EXPECT_EQ(distinct_points(edge), 14U);
  // At the point (1, 1, 1) only: 15 points, that one duplicated.
  check_voxels({{0, 0, 0}, {1, 1, 1}}, {16, 12, 2, 0, 0, 2}, false);
  const Solid point = assemble_boundary(voxel_fragments({{0, 0, 0}, {1, 1, 1}}, rng), with_threads(1));
  EXPECT_EQ(distinct_points(point), 15U);
  // Each shell alone passes the full validation as a unit cube.
  for (const Solid* s : {&edge, &point}) {
    const auto shells = shell_soups(*s);
    ASSERT_EQ(shells.size(), 2U);
    for (const auto& soup : shells) EXPECT_EQ(Solid::from_soup(soup).volume(), 1);
  }
}

// Adds the convex polygon `corners` with its normal pointing away from `inside`.
void add_facing_away(FragmentBuilder& b, const Vec3& inside, std::vector<Vec3> corners) {
  Vec3 area{0, 0, 0};
  for (std::size_t i = 0; i < corners.size(); ++i) area += cross(corners[i], corners[(i + 1) % corners.size()]);
  Vec3 normal = cvms::primitive_direction(area);
  if (sgn(dot(normal, corners[0] - inside)) < 0) normal = -normal;
  b.add(normal, std::move(corners));
}

// The six faces of the unit cube [0, 1]^3, each as (0, 0), (1, 0), (1, 1),
// (0, 1) in the coordinates after its normal's axis.
std::vector<std::vector<Vec3>> unit_cube_faces() {
  std::vector<std::vector<Vec3>> faces;
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      std::vector<Vec3> corners;
      for (const auto& [u, v] : std::vector<std::pair<int, int>>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
        Vec3 p;
        p[a] = side;
        p[(a + 1) % 3] = u;
        p[(a + 2) % 3] = v;
        corners.push_back(p);
      }
      faces.push_back(std::move(corners));
    }
  return faces;
}

TEST(BoundaryAssembly, VertexTouchingTheMiddleOfAnEdgeSplitsIt) {
  // The unit cube and a tetrahedron whose apex (1/2, 0, 1) touches the
  // middle of the cube's edge from (0, 0, 1) to (1, 0, 1) from outside
  // (its base is the triangle (0, -1, 2), (1, -1, 2), (1/2, -2, 2)). The
  // edge is split there and the point is duplicated: the cube keeps 9
  // vertices (8 + the split point), the tetrahedron 4; volumes 1 and 1/6.
  FragmentBuilder b;
  const Vec3 centre{Rational(1, 2), Rational(1, 2), Rational(1, 2)};
  for (const auto& face : unit_cube_faces()) add_facing_away(b, centre, face);
  const Vec3 apex{Rational(1, 2), 0, 1};
  const std::vector<Vec3> base = {{0, -1, 2}, {1, -1, 2}, {Rational(1, 2), -2, 2}};
  const Vec3 inside{Rational(1, 2), Rational(-5, 4), Rational(7, 4)};
  add_facing_away(b, inside, base);
  for (int i = 0; i < 3; ++i) add_facing_away(b, inside, {apex, base[i], base[(i + 1) % 3]});
  const Solid s = assemble_boundary(b.fragments(), with_threads(1));
  expect_counts(s, {13, 10, 2, 0, 0, Rational(7, 6)});
  EXPECT_EQ(distinct_points(s), 12U);
  check_mesh(s);
  std::vector<Rational> volumes;
  for (const auto& soup : shell_soups(s)) volumes.push_back(Solid::from_soup(soup).volume());
  std::sort(volumes.begin(), volumes.end());
  EXPECT_EQ(volumes, (std::vector<Rational>{Rational(1, 6), 1}));
}

TEST(BoundaryAssembly, CornerWhereALoneFragmentDoesNotTurnIsNoVertex) {
  // The unit cube, its bottom given as one fragment with a fifth corner
  // (1/2, 0, 0) on a straight side: still 8 vertices and 6 facets.
  FragmentBuilder b;
  const Vec3 centre{Rational(1, 2), Rational(1, 2), Rational(1, 2)};
  for (auto face : unit_cube_faces()) {
    if (face[0].z == 0 && face[1].z == 0 && face[2].z == 0) face.insert(face.begin() + 1, Vec3{Rational(1, 2), 0, 0});
    add_facing_away(b, centre, face);
  }
  const Solid s = assemble_boundary(b.fragments(), with_threads(1));
  expect_counts(s, {8, 6, 1, 0, 0, 1});
  check_mesh(s);
}

TEST(BoundaryAssembly, RegionTouchingItselfAndSeveralHoles) {
  // 3 x 3 minus the centre and a corner: a C whose tips touch along the edge
  // x = y = 2. The top and bottom regions pass through (2, 2) twice; the
  // C's outline has 10 corners, (2, 2) twice, so 20 vertices, 2 + 10 facets.
  std::vector<Voxel> c_shape;
  for (const Voxel& v : box(3, 3, 1))
    if (v != Voxel{1, 1, 0} && v != Voxel{2, 2, 0}) c_shape.push_back(v);
  check_voxels(c_shape, {20, 12, 1, 0, 0, 7}, false);
  // 4 x 4 minus two holes touching along the edge x = y = 2: traced as one
  // hole through (2, 2) twice; after the split, one tunnel (genus 1), 12
  // corners per face, 2 + 4 + 8 facets.
  std::vector<Voxel> touching_holes;
  for (const Voxel& v : box(4, 4, 1))
    if (v != Voxel{1, 1, 0} && v != Voxel{2, 2, 0}) touching_holes.push_back(v);
  check_voxels(touching_holes, {24, 14, 1, 0, 1, 14}, false);
  // 5 x 5 with four holes: the bridges of later holes must avoid the others.
  std::vector<Voxel> four_holes;
  for (const Voxel& v : box(5, 5, 1))
    if (v[0] % 2 == 0 || v[1] % 2 == 0) four_holes.push_back(v);
  check_voxels(four_holes, {40, 22, 1, 0, 4, 21}, true);
}

// Random sets of voxels in a 4 x 4 x 4 grid, half full: touching edges and
// points, pinched regions, holes and cavities in every combination. Oracles:
// the voxel count (volume) and membership of every voxel's centre.
TEST(BoundaryAssembly, RandomVoxelSets) {
  for (unsigned seed = 1; seed <= 8; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    std::vector<Voxel> voxels;
    std::set<Voxel> set;
    for (const Voxel& v : box(4, 4, 4))
      if (std::bernoulli_distribution(0.5)(rng)) {
        voxels.push_back(v);
        set.insert(v);
      }
    const BoundaryFragments fragments = voxel_fragments(voxels, rng);
    const Solid s = assemble_boundary(fragments, with_threads(1));
    EXPECT_EQ(s.volume(), static_cast<int>(voxels.size()));
    check_mesh(s);
    for (const Voxel& v : box(4, 4, 4)) {
      const Vec3 centre{Rational(2 * v[0] + 1, 2), Rational(2 * v[1] + 1, 2), Rational(2 * v[2] + 1, 2)};
      EXPECT_EQ(s.locate(centre), set.count(v) != 0 ? cvms::Location::inside : cvms::Location::outside);
    }
    const Solid t = assemble_boundary(fragments, with_threads(2));
    EXPECT_TRUE(std::equal(s.triangles().begin(), s.triangles().end(), t.triangles().begin(), t.triangles().end()));
  }
}

TEST(BoundaryAssembly, ReportsItsStageAndStopsWhenAsked) {
  std::mt19937 rng(1);
  const BoundaryFragments fragments = voxel_fragments(box(2, 2, 2), rng);
  cvms::Options options;
  std::set<std::string> stages;
  options.progress = [&](const cvms::Progress& p) {
    stages.insert(p.stage);
    return true;
  };
  (void)assemble_boundary(fragments, options);
  EXPECT_EQ(stages, std::set<std::string>{"union: assembly"});
  options.progress = [](const cvms::Progress&) { return false; };
  for (unsigned threads : {1U, 2U}) {
    options.threads = threads;
    try {
      (void)assemble_boundary(fragments, options);
      FAIL() << "not cancelled";
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::cancelled);
    }
  }
}

TEST(BoundaryAssembly, RejectsFragmentsThatDoNotBoundASolid) {
  FragmentBuilder b;
  b.add({0, 0, 1}, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
  BoundaryFragments open = b.fragments();
  try {
    (void)assemble_boundary(open, with_threads(1));
    FAIL() << "an open surface was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
  }
  open.fragments[0].plane = 5;
  try {
    (void)assemble_boundary(open, with_threads(1));
    FAIL() << "a fragment on no plane was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
    EXPECT_NE(std::string(e.what()).find("fragment 0"), std::string::npos);
  }
  open.fragments[0].plane = 0;
  open.planes[0].normal = Vec3{0, 0, 0};
  try {
    (void)assemble_boundary(open, with_threads(1));
    FAIL() << "a zero normal was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
    EXPECT_NE(std::string(e.what()).find("plane 0"), std::string::npos);
  }
  EXPECT_EQ(assemble_boundary(BoundaryFragments{}, with_threads(1)).num_shells(), 0U);
}

}  // namespace
