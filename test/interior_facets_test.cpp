// SPDX-License-Identifier: MIT
// The facets of the pieces f + B that interior_facets.hpp proves inside
// A + B, against brute force: points of each such facet's relative interior
// (its centroid and random exact interior points), and those points moved
// by 2^-30 along each of the 26 axis and diagonal directions, all lie in a
// piece or in A + b, by exact containment in each convex piece and one
// locate in A. Operands: the test solids, polycubes (random ones with fixed
// seeds, mapped by a rational rotation for decimal coordinates), a star
// prism, and face polygons that do not meet edge to edge; and, with neither
// operand convex, the pairwise sums of their decompositions.
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
  SumParts(const Solid& solid, const ConvexPolyhedron& b, const std::vector<std::vector<Vec3>>& polygons)
      : pieces(detail::face_sums(polygons, b, {})), a(&solid) {
    mask = detail::interior_facets(polygons, pieces, {});
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
  const Rational step(1, std::int64_t{1} << 30);
  const std::size_t stride = std::max<std::size_t>(1, skipped.size() / budget);
  for (std::size_t i = rng() % stride; i < skipped.size(); i += stride) {
    const auto [k, f] = skipped[i];
    for (const Vec3& x : relative_interior_points(facet_corners(parts.pieces[k], f), rng))
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) {
            const Vec3 p = x + step * Vec3{Rational(dx), Rational(dy), Rational(dz)};
            EXPECT_TRUE(parts.contains(p)) << "piece " << k << " facet " << f.index() << " point " << text(p);
          }
  }
  return skipped.size();
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

// Some facets are skipped with one operand or another: a box's facets
// summed with a cube's are all boxes, none of whose facets is certified
// (each meets the sum's boundary), but the octahedron's slanted facets are.
void expect_for(const Solid& a, std::uint64_t seed) {
  std::size_t skipped = 0;
  for (const ConvexPolyhedron& b : convex_operands(seed))
    skipped += expect_skipped_inside(SumParts(a, b, detail::facet_polygons(a)), seed);
  EXPECT_GT(skipped, 0U);
}

TEST(InteriorFacets, TestSolids) {
  std::uint64_t seed = 50;
  for (const char* name : {"l_block.off", "box_with_hole.off", "cavity_cube.off", "star_prism.off",
                           "nested_shells.off", "split_top_cube.off", "collinear_cube.off"}) {
    SCOPED_TRACE(name);
    expect_for(data_solid(name), ++seed);
  }
}

TEST(InteriorFacets, Polycubes) {
  expect_for(polycube(l_shape()), 1);
  expect_for(polycube(frame(4)), 2);
  expect_for(polycube(hollow_cube(3)), 3);
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
  std::size_t skipped = 0;
  for (const ConvexPolyhedron& b : convex_operands(7)) skipped += expect_skipped_inside(SumParts(cube, b, polygons), 7);
  EXPECT_GT(skipped, 0U);
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
  const SumParts parts(a, random_convex(11), polygons);
  Options two;
  two.threads = 2;
  EXPECT_EQ(parts.mask, detail::interior_facets(polygons, parts.pieces, two));
}

TEST(InteriorFacets, MaskOfTheWrongShapeIsRejected) {
  const Solid a = data_solid("l_block.off");
  const SumParts parts(a, cube_of_side(Rational(1, 2)), detail::facet_polygons(a));
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
