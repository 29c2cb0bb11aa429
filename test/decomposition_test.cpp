// SPDX-License-Identifier: MIT
// Exact convex decomposition, certified against oracles written here and
// independent of the code under test:
//  - every piece is a convex polyhedron (is_convex());
//  - the pieces' volumes (signed tetrahedra over their facets) sum to the
//    solid's (signed tetrahedra over its triangles);
//  - no two pieces overlap in their interiors (a separating facet plane, or
//    else an exact penetration depth of zero);
//  - random exact points lie in the solid (a hand-written membership test:
//    closed voxels of a grid, or the fan triangles of a star polygon) iff
//    they lie in some piece. The seed is printed on failure.
// Each fixture also prints its piece count beside its reflex-edge count (the
// maximal reflex segments, counted by hand).
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/decomposition.hpp"
#include "cvms/error.hpp"
#include "cvms/predicates.hpp"
#include "cvms/progress.hpp"
#include "cvms/proximity.hpp"
#include "cvms/shapes.hpp"
#include "decomposition_fixtures.hpp"
#include "diamond_ring.hpp"
#include "solid_access.hpp"

namespace cvms {
namespace {

using test::DiamondRing;
using test::GridSolid;
using test::Triangles;
using test::unit_grid;

Rational dec(const char* text) { return parse_rational(text); }

// A five-pointed star prism 0 <= z <= 2: outer tips on radius 10, inner
// corners on radius 4 (integer approximations, exactly as listed), caps
// fanned from the centre.
struct StarPrism {
  std::vector<Vec2> ring{{10, 0}, {3, 2}, {3, 10}, {-1, 4}, {-8, 6}, {-4, 0}, {-8, -6}, {-1, -4}, {3, -10}, {3, -2}};
  Rational height = 2;

  Solid solid() const {
    std::vector<Vec3> vertices;
    Triangles triangles;
    const auto n = static_cast<std::uint32_t>(ring.size());
    for (const Vec2& p : ring) vertices.push_back(Vec3{p.x, p.y, 0});
    for (const Vec2& p : ring) vertices.push_back(Vec3{p.x, p.y, height});
    vertices.push_back(Vec3{0, 0, 0});
    vertices.push_back(Vec3{0, 0, height});
    for (std::uint32_t i = 0; i < n; ++i) {
      std::uint32_t j = (i + 1) % n;
      triangles.push_back({i, j, n + j});
      triangles.push_back({i, n + j, n + i});
      triangles.push_back({2 * n, j, i});
      triangles.push_back({2 * n + 1, n + i, n + j});
    }
    return SolidAccess::assume_valid(std::move(vertices), std::move(triangles));
  }

  bool contains(const Vec3& p) const {
    if (p.z < 0 || height < p.z) return false;
    Vec2 q{p.x, p.y}, o{0, 0};
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2& a = ring[i];
      const Vec2& b = ring[(i + 1) % ring.size()];
      if (orient2d(o, a, q) != Sign::negative && orient2d(a, b, q) != Sign::negative &&
          orient2d(b, o, q) != Sign::negative)
        return true;
    }
    return false;
  }
};

// Six times the volume: signed tetrahedra from the origin over a closed,
// outward surface.
Rational six_volume(std::span<const Vec3> points, const Triangles& triangles) {
  Rational sum;
  for (const auto& t : triangles) sum += dot(points[t[0]], cross(points[t[1]], points[t[2]]));
  return sum;
}

Rational six_volume(const ConvexPolyhedron& p) {
  PolygonSoup soup = p.to_soup();
  Triangles fan;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto face = soup.face(f);
    for (std::size_t k = 1; k + 1 < face.size(); ++k) fan.push_back({face[0], face[k], face[k + 1]});
  }
  return six_volume(soup.points, fan);
}

bool piece_contains(const ConvexPolyhedron& p, const Vec3& x) {
  for (FaceId f : p.mesh().faces())
    if (side_of_plane(x, p.normal(f), p.plane_offset(f)) == Sign::positive) return false;
  return true;
}

// A facet plane of a with all of b on or in front of it.
bool facet_separates(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  for (FaceId f : a.mesh().faces()) {
    bool all_front = true;
    for (const Vec3& v : b.mesh().positions())
      if (side_of_plane(v, a.normal(f), a.plane_offset(f)) == Sign::negative) {
        all_front = false;
        break;
      }
    if (all_front) return true;
  }
  return false;
}

struct Box {
  Vec3 lo, hi;
};

Box bounds(std::span<const Vec3> points) {
  Box b{points[0], points[0]};
  for (const Vec3& p : points)
    for (int a = 0; a < 3; ++a) {
      if (p[a] < b.lo[a]) b.lo[a] = p[a];
      if (b.hi[a] < p[a]) b.hi[a] = p[a];
    }
  return b;
}

// A random exact point near the box: often a grid value of the solid's own
// coordinates (to land on facets, edges and vertices), else a random
// rational.
Vec3 random_point(std::mt19937_64& rng, const Box& box, std::span<const Vec3> vertices) {
  Vec3 p;
  for (int a = 0; a < 3; ++a) {
    if (rng() % 3 == 0) {
      p[a] = vertices[rng() % vertices.size()][a];
    } else {
      Rational t(static_cast<long>(rng() % 1201) - 100, 1000);
      p[a] = box.lo[a] + t * (box.hi[a] - box.lo[a]);
    }
  }
  return p;
}

std::string point_text(const Vec3& p) {
  return "(" + to_string(p.x) + ", " + to_string(p.y) + ", " + to_string(p.z) + ")";
}

// Decomposes and checks every certificate; returns the piece count.
std::size_t certify(const std::string& name, const Solid& solid, const std::function<bool(const Vec3&)>& inside,
                    int reflex_segments) {
  auto start = std::chrono::steady_clock::now();
  ConvexUnion u = convex_decomposition(solid);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  auto pieces = u.pieces();
  std::cout << "[decomposition] " << name << ": " << pieces.size() << " pieces, " << reflex_segments
            << " reflex edges, " << solid.triangles().size() << " triangles, " << seconds << " s\n";
  SCOPED_TRACE(name);

  Triangles triangles(solid.triangles().begin(), solid.triangles().end());
  Rational total;
  for (const ConvexPolyhedron& p : pieces) {
    EXPECT_TRUE(p.is_convex());
    total += six_volume(p);
  }
  EXPECT_EQ(total, six_volume(solid.vertices(), triangles));

  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t j = i + 1; j < pieces.size(); ++j) {
      if (facet_separates(pieces[i], pieces[j]) || facet_separates(pieces[j], pieces[i])) continue;
      EXPECT_EQ(penetration(pieces[i], pieces[j]).squared_depth, 0) << "pieces " << i << " and " << j;
    }

  const std::uint64_t seed = 49001;
  std::mt19937_64 rng(seed);
  Box box = bounds(solid.vertices());
  for (int k = 0; k < 400; ++k) {
    Vec3 p = random_point(rng, box, solid.vertices());
    bool in_piece = false;
    for (const ConvexPolyhedron& piece : pieces) in_piece = in_piece || piece_contains(piece, p);
    if (inside(p) != in_piece) {
      ADD_FAILURE() << "seed " << seed << ", point " << k << " " << point_text(p) << ": in the solid "
                    << inside(p) << ", in a piece " << in_piece;
      break;
    }
  }
  return pieces.size();
}

std::size_t certify(const std::string& name, const GridSolid& g, int reflex_segments) {
  return certify(name, g.solid(), [&](const Vec3& p) { return g.contains(p); }, reflex_segments);
}

TEST(ConvexDecomposition, LBlock) {
  auto g = unit_grid(2, 2, 1, [](int i, int j, int) { return i == 0 || j == 0; });
  EXPECT_EQ(certify("L-block", g, 1), 2u);
}

TEST(ConvexDecomposition, UBlock) {
  auto g = unit_grid(3, 1, 2, [](int i, int, int k) { return k == 0 || i != 1; });
  EXPECT_EQ(certify("U-block", g, 2), 3u);
}

TEST(ConvexDecomposition, CubeWithNotch) {
  auto g = unit_grid(3, 3, 3, [](int i, int, int k) { return !(i == 1 && k == 2); });
  EXPECT_EQ(certify("cube with a notch", g, 2), 3u);
}

TEST(ConvexDecomposition, Staircase) {
  auto g = unit_grid(4, 2, 4, [](int i, int, int k) { return k <= i; });
  EXPECT_EQ(certify("staircase", g, 3), 4u);
}

TEST(ConvexDecomposition, BoxWithThroughHole) {
  auto g = unit_grid(3, 3, 1, [](int i, int j, int) { return !(i == 1 && j == 1); });
  EXPECT_EQ(certify("box with a square through-hole (genus 1)", g, 4), 4u);
}

TEST(ConvexDecomposition, TwoDisjointBoxes) {
  auto g = unit_grid(3, 1, 1, [](int i, int, int) { return i != 1; });
  EXPECT_EQ(certify("two disjoint boxes", g, 0), 2u);
}

TEST(ConvexDecomposition, BoxWithCavity) {
  auto g = unit_grid(3, 3, 3, [](int i, int j, int k) { return !(i == 1 && j == 1 && k == 1); });
  EXPECT_LE(certify("box with a cubic cavity", g, 12), 6u);
}

// A geodesic sphere with one vertex moved onto the vertex farthest from it:
// its fan becomes a thin cone reaching across the inside to touch the far
// side at one point. Convex but for the cone (whose edges are the solid's
// only reflex edges) and that touching point.
Solid pinched_sphere(int k) {
  const ConvexPolyhedron sphere = shapes::geodesic_sphere(k);
  PolygonSoup soup;
  soup.points = sphere.mesh().positions();
  for (FaceId f : sphere.mesh().faces()) {
    std::vector<std::uint32_t> cycle;
    for (HalfedgeId h : sphere.mesh().face_halfedges(f)) cycle.push_back(sphere.mesh().from(h).index());
    for (std::size_t i = 1; i + 1 < cycle.size(); ++i) {  // fan: the solid's triangles
      soup.face_indices.insert(soup.face_indices.end(), {cycle[0], cycle[i], cycle[i + 1]});
      soup.face_offsets.push_back(static_cast<std::uint32_t>(soup.face_indices.size()));
    }
  }
  std::size_t far = 0;
  Rational best = -1;
  for (std::size_t v = 1; v < soup.points.size(); ++v) {
    const Vec3 d = soup.points[v] - soup.points[0];
    if (best < dot(d, d)) {
      best = dot(d, d);
      far = v;
    }
  }
  soup.points[0] = soup.points[far];
  return Solid::from_soup(std::move(soup));
}

// Brute-force point location in a solid: on a triangle, or an odd number of
// crossings of a ray with the triangles (a ray through an edge or a vertex is
// replaced by another direction). Exact; independent of the decomposition.
bool on_triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x) {
  if (orient3d(a, b, c, x) != Sign::zero) return false;
  const Vec3 e = a + cross(b - a, c - a);
  const Sign s1 = orient3d(a, b, e, x), s2 = orient3d(b, c, e, x), s3 = orient3d(c, a, e, x);
  const bool has_pos = s1 == Sign::positive || s2 == Sign::positive || s3 == Sign::positive;
  const bool has_neg = s1 == Sign::negative || s2 == Sign::negative || s3 == Sign::negative;
  return !(has_pos && has_neg);
}

bool solid_contains(const Solid& solid, const Vec3& x) {
  auto v = solid.vertices();
  for (const auto& t : solid.triangles())
    if (on_triangle(v[t[0]], v[t[1]], v[t[2]], x)) return true;
  for (long attempt = 1;; ++attempt) {
    const Vec3 d{Rational(1), Rational(attempt, 7919), Rational(attempt * attempt + 3, 104729)};
    const Vec3 y = x + d;
    bool degenerate = false;
    int crossings = 0;
    for (const auto& t : solid.triangles()) {
      const Vec3 &a = v[t[0]], &b = v[t[1]], &c = v[t[2]];
      const Vec3 n = cross(b - a, c - a);
      const int toward = sgn(dot(n, a - x)), along = sgn(dot(n, d));
      if (toward == 0 || along == 0 || toward != along) continue;  // no crossing ahead
      const Sign o1 = orient3d(x, y, a, b), o2 = orient3d(x, y, b, c), o3 = orient3d(x, y, c, a);
      if (o1 == Sign::zero || o2 == Sign::zero || o3 == Sign::zero) {
        const bool mixed = (o1 == Sign::positive || o2 == Sign::positive || o3 == Sign::positive) &&
                           (o1 == Sign::negative || o2 == Sign::negative || o3 == Sign::negative);
        if (!mixed) degenerate = true;
        continue;
      }
      if (o1 == o2 && o2 == o3) ++crossings;
    }
    if (!degenerate) return crossings % 2 == 1;
  }
}

TEST(ConvexDecomposition, StarPrism) {
  StarPrism star;
  EXPECT_LE(certify("star prism", star.solid(), [&](const Vec3& p) { return star.contains(p); }, 5), 5u);
}

TEST(ConvexDecomposition, RingOfSegmentsCutAtItsJoints) {
  DiamondRing ring{{{2, 1}, {1, 2}, {-1, 2}, {-2, 1}, {-2, -1}, {-1, -2}, {1, -2}, {2, -1}}};
  EXPECT_EQ(certify("diamond ring of 8 segments (genus 1)", ring.solid(),
                    [&](const Vec3& p) { return ring.contains(p); }, 16),
            8u);
  DiamondRing bar{{{3, 0}, {2, 2}, {0, 3}, {-2, 2}}, false};
  EXPECT_EQ(certify("bent diamond bar of 3 segments", bar.solid(), [&](const Vec3& p) { return bar.contains(p); }, 4),
            3u);
}

TEST(ConvexDecomposition, CoplanarAndCollinearFacets) {
  // Convex, but every facet is split into coplanar triangles with collinear
  // vertices on its edges: one piece.
  auto block = unit_grid(2, 3, 2, [](int, int, int) { return true; });
  EXPECT_EQ(certify("block of coplanar triangles", block, 0), 1u);
  // An L whose reflex edge is two collinear segments.
  auto l = unit_grid(4, 4, 2, [](int i, int j, int) { return i < 2 || j < 2; });
  EXPECT_EQ(certify("subdivided L-block", l, 1), 2u);
}

TEST(ConvexDecomposition, DecimalCoordinates) {
  GridSolid g{{std::vector<Rational>{dec("0"), dec("0.1"), dec("0.35"), dec("1.2")},
               std::vector<Rational>{dec("-0.5"), dec("0.25")},
               std::vector<Rational>{dec("0"), dec("0.3"), dec("0.75")}},
              {}};
  for (int i = 0; i < 3; ++i) g.cells.insert({i, 0, 0});
  g.cells.insert({0, 0, 1});
  g.cells.insert({2, 0, 1});
  EXPECT_EQ(certify("U-block, decimal coordinates", g, 2), 3u);
}

TEST(ConvexDecomposition, ConvexSolidIsItsOwnPiece) {
  auto g = unit_grid(1, 1, 1, [](int, int, int) { return true; });
  ConvexUnion u = convex_decomposition(g.solid());
  ASSERT_EQ(u.size(), 1u);
  EXPECT_EQ(u.pieces()[0].num_vertices(), 8u);
  EXPECT_EQ(u.pieces()[0].num_facets(), 6u);
}

TEST(ConvexDecomposition, Deterministic) {
  auto g = unit_grid(3, 3, 3, [](int i, int j, int k) { return (i + j + k) % 2 == 0 || k == 0; });
  ConvexUnion a = convex_decomposition(g.solid());
  ConvexUnion b = convex_decomposition(g.solid());
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_EQ(a.pieces()[i].mesh().positions(), b.pieces()[i].mesh().positions()) << "piece " << i;
}

void expect_limit(const Solid& solid, const DecompositionOptions& options, const std::string& named) {
  try {
    (void)convex_decomposition(solid, options);
    ADD_FAILURE() << "no limit error";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::limit);
    EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
  }
}

TEST(ConvexDecomposition, Limits) {
  auto g = unit_grid(3, 1, 2, [](int i, int, int k) { return k == 0 || i != 1; });
  DecompositionOptions few;
  few.limits.max_pieces = 2;
  expect_limit(g.solid(), few, "max_pieces");
  DecompositionOptions small;
  small.limits.max_memory_bytes = 1000;
  expect_limit(g.solid(), small, "max_memory_bytes");
}

TEST(ConvexDecomposition, PinchedSphereEndsAtConvexCells) {
  // Away from the cone the cells hold convex parts of the solid and end
  // there, so the pieces number about the cone's facets, not the sphere's.
  const Solid pinched = pinched_sphere(3);
  EXPECT_LE(certify("pinched geodesic sphere", pinched, [&](const Vec3& p) { return solid_contains(pinched, p); },
                    6),
            12u);
  ConvexUnion big = convex_decomposition(pinched_sphere(5));
  EXPECT_LE(big.size(), 12u);
}

TEST(ConvexDecomposition, PinchedSphereLimits) {
  const Solid pinched = pinched_sphere(5);
  DecompositionOptions few;
  few.limits.max_pieces = 2;
  expect_limit(pinched, few, "max_pieces");
  DecompositionOptions small;
  small.limits.max_memory_bytes = 100000;
  expect_limit(pinched, small, "max_memory_bytes");
}

TEST(ConvexDecomposition, PinchedSphereCancelled) {
  // The callback sees each stage start at done 0, done never decreasing
  // within a run and at most total; a false return in any stage stops the
  // call.
  const Solid pinched = pinched_sphere(5);
  for (const char* stop_in : {"decomposition: partition", "hull", "decomposition: merge"}) {
    SCOPED_TRACE(stop_in);
    DecompositionOptions options;
    std::string stage;
    std::uint64_t last = 0;
    int in_stage = 0;  // reports of stop_in so far
    options.progress = [&](const Progress& p) {
      if (stage != p.stage) {
        EXPECT_EQ(p.done, 0u) << p.stage;
        stage = p.stage;
        last = 0;
      }
      EXPECT_GE(p.done, last);
      EXPECT_LE(p.done, p.total);
      last = p.done;
      return stage != stop_in || ++in_stage < 2;  // stop at its second report
    };
    try {
      (void)convex_decomposition(pinched, options);
      ADD_FAILURE() << "not cancelled";
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::cancelled) << e.what();
    }
  }
  DecompositionOptions listening;
  std::vector<std::string> stages;
  listening.progress = [&](const Progress& p) {
    if (stages.empty() || stages.back() != p.stage) stages.push_back(p.stage);
    return true;
  };
  EXPECT_LE(convex_decomposition(pinched, listening).size(), 12u);
  ASSERT_FALSE(stages.empty());
  EXPECT_EQ(stages.front(), "decomposition: partition");
  EXPECT_EQ(stages.back(), "decomposition: merge");
}

TEST(ConvexDecomposition, EmptySolid) {
  try {
    (void)convex_decomposition(Solid{});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
  }
}

}  // namespace
}  // namespace cvms
