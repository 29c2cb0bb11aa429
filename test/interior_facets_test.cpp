// SPDX-License-Identifier: MIT
// The facets of the pieces f + B that interior_facets.hpp proves inside
// A + B, against brute force: points of each such facet's relative interior
// (its centroid and random exact interior points), and those points moved
// by 2^-30 along each of the 26 axis and diagonal directions, all lie in a
// piece or in A + b, by exact containment in each convex piece and one
// locate in A. The inner translates (each face polygon's facet of its piece
// facing into A) are found by the polygons' area vectors and all checked,
// and so are the facets certified at A's edges (those skipped only when the
// polygons are known to be made of A's triangles).
// Operands: the test solids, polycubes (random ones with fixed seeds,
// mapped by a rational rotation for decimal coordinates), a star prism, a
// comb prism, parts touching along an edge or at a point, and face
// polygons that do not meet edge to edge, each summed with a cube,
// an octahedron, a random convex polyhedron and a box 2^-20 thin; and, with
// neither operand convex, the pairwise sums of their decompositions.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "boundary_fragments.hpp"
#include "cvms/convex_hull.hpp"
#include "cvms/decomposition.hpp"
#include "cvms/error.hpp"
#include "face_sums.hpp"
#include "facet_polygons.hpp"
#include "interior_facets.hpp"
#include "solid_sum_fixtures.hpp"
#include "support/hand_solids.hpp"

namespace cvms::test {
namespace {

struct Box {
  Vec3 lo, hi;
  [[nodiscard]] bool holds(const Vec3& p) const {
    for (int i = 0; i < 3; ++i)
      if (p[i] < lo[i] || p[i] > hi[i]) return false;
    return true;
  }
};

Box box_of(const ConvexPolyhedron& piece) {
  Box box{piece.vertex(VertexId(0)), piece.vertex(VertexId(0))};
  for (VertexId v : piece.mesh().vertices())
    for (int i = 0; i < 3; ++i) {
      box.lo[i] = std::min(box.lo[i], piece.vertex(v)[i]);
      box.hi[i] = std::max(box.hi[i], piece.vertex(v)[i]);
    }
  return box;
}

bool piece_contains(const ConvexPolyhedron& piece, const Vec3& p) {
  for (FaceId f : piece.mesh().faces())
    if (dot(piece.normal(f), p) > piece.plane_offset(f)) return false;
  return true;
}

// The sum's pieces, their facets' mask, and what the brute force needs.
struct SumParts {
  std::vector<ConvexPolyhedron> pieces;
  detail::FacetMask mask;
  std::vector<Box> boxes;
  const Solid* a = nullptr;  // with B convex, A + b_point is part of the sum
  Vec3 b_point;

  // The pieces polygon + B of the sum of a with a convex b.
  SumParts(const Solid& solid, const ConvexPolyhedron& b, const std::vector<std::vector<Vec3>>& polygons,
           detail::PolygonTiling tiling)
      : pieces(detail::face_sums(polygons, b, {})), a(&solid) {
    mask = detail::interior_facets(polygons, pieces, {}, tiling);
    for (VertexId v : b.mesh().vertices()) b_point = b_point + b.vertex(v);
    b_point = Rational(Rational(1) / b.num_vertices()) * b_point;
    boxes_of_pieces();
  }

  // The pairwise sums of the two decompositions.
  SumParts(const ConvexUnion& a_parts, const ConvexUnion& b_parts) {
    const ConvexUnion sums = minkowski_sum(a_parts, b_parts);
    pieces.assign(sums.pieces().begin(), sums.pieces().end());
    mask = detail::interior_facets_of_pairs(vertices_of(a_parts), vertices_of(b_parts), pieces, {});
    boxes_of_pieces();
  }

  [[nodiscard]] bool contains(const Vec3& p) const {
    if (a != nullptr && a->contains(p - b_point)) return true;
    for (std::size_t k = 0; k < pieces.size(); ++k)
      if (boxes[k].holds(p) && piece_contains(pieces[k], p)) return true;
    return false;
  }

 private:
  void boxes_of_pieces() {
    for (const ConvexPolyhedron& piece : pieces) boxes.push_back(box_of(piece));
  }
  static std::vector<std::vector<Vec3>> vertices_of(const ConvexUnion& parts) {
    std::vector<std::vector<Vec3>> out;
    for (const ConvexPolyhedron& part : parts.pieces()) {
      std::vector<Vec3>& vertices = out.emplace_back();
      for (VertexId v : part.mesh().vertices()) vertices.push_back(part.vertex(v));
    }
    return out;
  }
};

std::vector<Vec3> facet_corners(const ConvexPolyhedron& piece, FaceId f) {
  std::vector<Vec3> corners;
  for (HalfedgeId h : piece.mesh().face_halfedges(f)) corners.push_back(piece.vertex(piece.mesh().to(h)));
  return corners;
}

// The centroid and random points with weights in [1, 16] on the corners.
std::vector<Vec3> relative_interior_points(const std::vector<Vec3>& corners, std::mt19937_64& rng) {
  std::vector<Vec3> points;
  Vec3 sum;
  for (const Vec3& c : corners) sum = sum + c;
  points.push_back(Rational(Rational(1) / static_cast<long>(corners.size())) * sum);
  for (int k = 0; k < 2; ++k) {
    Vec3 weighted;
    long total = 0;
    for (const Vec3& c : corners) {
      const auto w = static_cast<long>(1 + rng() % 16);
      weighted = weighted + Rational(w) * c;
      total += w;
    }
    points.push_back(Rational(Rational(1) / total) * weighted);
  }
  return points;
}

// Facet f of piece k lies inside the sum: its centroid and random points
// of its relative interior, each moved by 2^-30 along the 26 axis and
// diagonal directions (and not moved), lie in the sum.
void expect_facet_inside(const SumParts& parts, std::size_t k, FaceId f, std::mt19937_64& rng) {
  const Rational step(1, std::int64_t{1} << 30);
  for (const Vec3& x : relative_interior_points(facet_corners(parts.pieces[k], f), rng))
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const Vec3 p = x + step * Vec3{Rational(dx), Rational(dy), Rational(dz)};
          EXPECT_TRUE(parts.contains(p)) << "piece " << k << " facet " << f.index() << " point " << text(p);
        }
}

// Every skipped facet checked (at most `budget` of them, spread over all);
// returns how many were skipped.
std::size_t expect_skipped_inside(const SumParts& parts, std::uint64_t seed, std::size_t budget = 60) {
  SCOPED_TRACE("seed " + std::to_string(seed));
  const detail::FacetMask& mask = parts.mask;
  EXPECT_EQ(mask.size(), parts.pieces.size());
  std::vector<std::pair<std::size_t, FaceId>> skipped;
  for (std::size_t k = 0; k < parts.pieces.size(); ++k) {
    EXPECT_EQ(mask[k].size(), parts.pieces[k].num_facets());
    for (FaceId f : parts.pieces[k].mesh().faces())
      if (mask[k][f.index()] != 0) skipped.emplace_back(k, f);
  }
  std::mt19937_64 rng(seed);
  const std::size_t stride = std::max<std::size_t>(1, skipped.size() / budget);
  for (std::size_t i = rng() % stride; i < skipped.size(); i += stride)
    expect_facet_inside(parts, skipped[i].first, skipped[i].second, rng);
  return skipped.size();
}

// A polygon's normal by Newell's sum of cross products: its area vector,
// pointing to where its corners turn counterclockwise.
Vec3 area_vector(const std::vector<Vec3>& polygon) {
  Vec3 sum;
  for (std::size_t i = 0; i < polygon.size(); ++i) sum = sum + cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return sum;
}

// The inner translates, found by their normals against the polygons' area
// vectors (outward from A): each piece has one, it is skipped, and all of
// them lie inside the sum by brute force. The outer translates (normal
// along the area vector, facing out of A, where the sum often ends) are
// never skipped.
void expect_inner_translates(const SumParts& parts, const std::vector<std::vector<Vec3>>& polygons,
                             std::uint64_t seed) {
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937_64 rng(seed);
  ASSERT_EQ(parts.pieces.size(), polygons.size());
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    const Vec3 outward = area_vector(polygons[k]);
    std::size_t inner = 0;
    for (FaceId f : parts.pieces[k].mesh().faces()) {
      const Vec3& n = parts.pieces[k].normal(f);
      if (cross(n, outward) != Vec3{}) continue;
      if (dot(n, outward) > 0) {
        EXPECT_EQ(parts.mask[k][f.index()], 0) << "outer translate of polygon " << k;
        continue;
      }
      ++inner;
      EXPECT_NE(parts.mask[k][f.index()], 0) << "inner translate of polygon " << k;
      expect_facet_inside(parts, k, f, rng);
    }
    EXPECT_EQ(inner, 1U) << "polygon " << k;
  }
}

ConvexPolyhedron cube_of_side(const Rational& side) {
  std::vector<Vec3> points;
  for (int i = 0; i < 8; ++i)
    points.push_back({(i & 1) != 0 ? side : Rational(0), (i & 2) != 0 ? side : Rational(0),
                      (i & 4) != 0 ? side : Rational(0)});
  return convex_hull(points);
}

ConvexPolyhedron octahedron(const Rational& r) {
  return convex_hull(std::vector<Vec3>{{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}});
}

// The hull of random points with coordinates k / 8 in [-1/2, 1/2].
ConvexPolyhedron random_convex(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> points;
  for (int k = 0; k < 14; ++k)
    points.push_back({Rational(static_cast<long>(rng() % 9) - 4, 8), Rational(static_cast<long>(rng() % 9) - 4, 8),
                      Rational(static_cast<long>(rng() % 9) - 4, 8)});
  return convex_hull(points);
}

std::vector<ConvexPolyhedron> convex_operands(std::uint64_t seed) {
  return {cube_of_side(Rational(1, 2)), octahedron(Rational(1, 3)), random_convex(seed)};
}

Solid data_solid(const std::string& name) {
  return read_solid(std::string(CVMS_TEST_DATA_DIR) + "/solids/" + name);
}

// The box [0, 1] x [0, 1] x [0, 2^-20]: B barely rises above its bottom,
// the face of the inner translates of A's upward polygons.
ConvexPolyhedron thin_box() {
  const Rational height(1, std::int64_t{1} << 20);
  std::vector<Vec3> points;
  for (int i = 0; i < 8; ++i)
    points.push_back({Rational((i & 1) != 0 ? 1 : 0), Rational((i & 2) != 0 ? 1 : 0),
                      (i & 4) != 0 ? height : Rational(0)});
  return convex_hull(points);
}

// The facets certified at A's edges: skipped for polygons made of A's
// triangles but not for any convex tiling. All of them are checked; returns
// how many there are.
std::size_t expect_edge_facets_inside(const SumParts& parts, const std::vector<std::vector<Vec3>>& polygons,
                                      std::uint64_t seed) {
  SCOPED_TRACE("seed " + std::to_string(seed));
  const detail::FacetMask convex = detail::interior_facets(polygons, parts.pieces, {});
  std::mt19937_64 rng(seed);
  std::size_t count = 0;
  for (std::size_t k = 0; k < parts.pieces.size(); ++k)
    for (FaceId f : parts.pieces[k].mesh().faces()) {
      EXPECT_FALSE(convex[k][f.index()] != 0 && parts.mask[k][f.index()] == 0) << "piece " << k;
      if (parts.mask[k][f.index()] == 0 || convex[k][f.index()] != 0) continue;
      ++count;
      expect_facet_inside(parts, k, f, rng);
    }
  return count;
}

// Some facets are skipped with every operand: at least the inner
// translates, checked one by one, the facets certified at A's edges, all
// checked, and a sample of all skipped facets. Returns how many facets were
// certified at edges.
std::size_t expect_for(const Solid& a, std::uint64_t seed) {
  const std::vector<std::vector<Vec3>> polygons = detail::facet_polygons(a);
  std::vector<ConvexPolyhedron> operands = convex_operands(seed);
  operands.push_back(thin_box());
  std::size_t at_edges = 0;
  for (const ConvexPolyhedron& b : operands) {
    const SumParts parts(a, b, polygons, detail::PolygonTiling::of_triangles);
    EXPECT_GT(expect_skipped_inside(parts, seed), 0U);
    expect_inner_translates(parts, polygons, seed);
    at_edges += expect_edge_facets_inside(parts, polygons, seed);
  }
  return at_edges;
}

TEST(InteriorFacets, TestSolids) {
  std::uint64_t seed = 50;
  std::size_t at_edges = 0;
  for (const char* name : {"l_block.off", "box_with_hole.off", "cavity_cube.off", "star_prism.off",
                           "nested_shells.off", "split_top_cube.off", "collinear_cube.off"}) {
    SCOPED_TRACE(name);
    at_edges += expect_for(data_solid(name), ++seed);
  }
  EXPECT_GT(at_edges, 0U);
}

TEST(InteriorFacets, Polycubes) {
  EXPECT_GT(expect_for(polycube(l_shape()), 1), 0U);
  EXPECT_GT(expect_for(polycube(frame(4)), 2), 0U);
  EXPECT_GT(expect_for(polycube(hollow_cube(3)), 3), 0U);
}

// A comb prism: its reflex edges at the roots of the teeth give most of
// the facets certified at edges.
TEST(InteriorFacets, CombPrism) {
  EXPECT_GT(expect_for(Solid::from_soup(prism_over(comb_polygon(4), Rational(0), Rational(1))), 9), 0U);
}

// Two wedges (triangular prisms, z in [0, 1]) touching along their apex
// edge, the z axis, both below the plane y = 0: four polygons meet at that
// edge, and none has a corner above it. Two of them (listed first) face
// away from +y, yet the points just above the edge lie outside A: a facet
// e + B_n with n = +y is not inside the sum, and only the edge certificate's
// "exactly two polygons" keeps it a candidate.
Solid wedges_touching_along_an_edge() {
  const auto p = [](int x, int y, int z) { return Vec3{Rational(x), Rational(y), Rational(z)}; };
  PolygonSoup soup;
  // Each wedge's apex edge, then its two other edges (bottom, top).
  soup.points = {p(0, 0, 0), p(0, 0, 1), p(-4, -1, 0), p(-4, -1, 1), p(-2, -4, 0), p(-2, -4, 1),
                 p(0, 0, 0), p(0, 0, 1), p(2, -4, 0),  p(2, -4, 1),  p(4, -1, 0),  p(4, -1, 1)};
  soup.add_face({4, 0, 1, 5});   // the first wedge's side facing down and right
  soup.add_face({6, 8, 9, 7});   // the second's facing down and left
  soup.add_face({0, 2, 3, 1});   // the first's facing up and left
  soup.add_face({2, 4, 5, 3});   // the first's far side
  soup.add_face({0, 4, 2});      // the first's bottom
  soup.add_face({1, 3, 5});      // the first's top
  soup.add_face({8, 10, 11, 9}); // the second's far side
  soup.add_face({10, 6, 7, 11}); // the second's facing up and right
  soup.add_face({6, 10, 8});     // the second's bottom
  soup.add_face({7, 9, 11});     // the second's top
  return Solid::from_soup(std::move(soup));
}

TEST(InteriorFacets, WedgesTouchingAlongAnEdge) { (void)expect_for(wedges_touching_along_an_edge(), 12); }

// Parts touching along an edge or at a point (two cubes, the even cells of
// a 2 x 2 x 2 grid, a cavity touching a notch of the outside along an
// edge): four polygons meet at such an edge, and every facet certified
// there is still inside the sum.
TEST(InteriorFacets, PartsTouchingAlongAnEdgeOrAtAPoint) {
  const Cubes checker = cubes_where(2, 2, 2, [](int i, int j, int k) { return (i + j + k) % 2 == 0; });
  const Cubes notched = cubes_where(3, 3, 3, [](int i, int j, int k) {
    const Cube c{i, j, k};
    return c != Cube{1, 1, 1} && c != Cube{2, 2, 1};
  });
  std::uint64_t seed = 10;
  for (const Cubes& cubes : {Cubes{{0, 0, 0}, {1, 1, 0}}, Cubes{{0, 0, 0}, {1, 1, 1}}, checker, notched})
    (void)expect_for(polycube(cubes), ++seed);
}

TEST(InteriorFacets, RandomPolycubesWithDecimalCoordinates) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) expect_for(polycube(random_height_field(seed), decimal_rotation()), seed);
}

// A cube [0, 2]^3 whose top is two rectangles: their shared corners lie
// in the middle of the front and back squares' edges, not at their corners.
TEST(InteriorFacets, PolygonsNotEdgeToEdge) {
  const auto p = [](int x, int y, int z) { return Vec3{Rational(x), Rational(y), Rational(z)}; };
  std::vector<std::vector<Vec3>> polygons = {
      {p(0, 0, 0), p(0, 2, 0), p(2, 2, 0), p(2, 0, 0)}, {p(0, 0, 2), p(1, 0, 2), p(1, 2, 2), p(0, 2, 2)},
      {p(1, 0, 2), p(2, 0, 2), p(2, 2, 2), p(1, 2, 2)}, {p(0, 0, 0), p(2, 0, 0), p(2, 0, 2), p(0, 0, 2)},
      {p(0, 2, 0), p(0, 2, 2), p(2, 2, 2), p(2, 2, 0)}, {p(0, 0, 0), p(0, 0, 2), p(0, 2, 2), p(0, 2, 0)},
      {p(2, 0, 0), p(2, 2, 0), p(2, 2, 2), p(2, 0, 2)}};
  const Solid cube = polycube(cubes_where(2, 2, 2, [](int, int, int) { return true; }));
  std::vector<ConvexPolyhedron> operands = convex_operands(7);
  operands.push_back(thin_box());
  for (const ConvexPolyhedron& b : operands) {
    const SumParts parts(cube, b, polygons, detail::PolygonTiling::convex);
    EXPECT_GT(expect_skipped_inside(parts, 7), 0U);
    expect_inner_translates(parts, polygons, 7);
  }
}

// Both operands not convex: the pieces of their decompositions.
TEST(InteriorFacets, PairsOfDecompositions) {
  const Solid l_block = data_solid("l_block.off"), star = data_solid("star_prism.off");
  const Solid hole = data_solid("box_with_hole.off"), cavity = data_solid("cavity_cube.off");
  const Mapping rotated{rational_rotation(), Vec3{Rational(1, 10), Rational(-3, 10), Rational(7, 100)}};
  const Solid turned_l = polycube(l_shape(), rotated);
  const std::vector<std::pair<const Solid*, const Solid*>> pairs = {
      {&l_block, &star}, {&hole, &l_block}, {&star, &turned_l}, {&cavity, &l_block}, {&turned_l, &hole}};
  std::size_t skipped = 0;
  std::uint64_t seed = 70;
  for (const auto& [a, b] : pairs) {
    const SumParts parts(convex_decomposition(*a), convex_decomposition(*b));
    skipped += expect_skipped_inside(parts, ++seed, 40);
  }
  EXPECT_GT(skipped, 0U);
}

TEST(InteriorFacets, SameMaskOnAnyThreadCount) {
  const Solid a = data_solid("star_prism.off");
  const std::vector<std::vector<Vec3>> polygons = detail::facet_polygons(a);
  const SumParts parts(a, random_convex(11), polygons, detail::PolygonTiling::of_triangles);
  Options two;
  two.threads = 2;
  EXPECT_EQ(parts.mask, detail::interior_facets(polygons, parts.pieces, two, detail::PolygonTiling::of_triangles));
}

TEST(InteriorFacets, MaskOfTheWrongShapeIsRejected) {
  const Solid a = data_solid("l_block.off");
  const SumParts parts(a, cube_of_side(Rational(1, 2)), detail::facet_polygons(a),
                       detail::PolygonTiling::of_triangles);
  detail::FacetMask mask = parts.mask;
  mask.back().pop_back();
  EXPECT_THROW(
      {
        try {
          (void)detail::union_boundary_fragments(parts.pieces, {}, mask);
        } catch (const Error& e) {
          EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
          EXPECT_NE(std::string(e.message()).find("facet mask"), std::string::npos) << e.message();
          throw;
        }
      },
      Error);
  mask.pop_back();
  EXPECT_THROW((void)detail::union_boundary_fragments(parts.pieces, {}, mask), Error);
}

}  // namespace
}  // namespace cvms::test
