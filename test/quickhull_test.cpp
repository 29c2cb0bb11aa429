// SPDX-License-Identifier: MIT
// Tests of the exact quickhull: the soup core (lib/hull/hull_soup.hpp) against the
// brute-force oracle, known solids, degenerate clouds; and convex_hull.
#include "hull_soup.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/predicates.hpp"
#include "filtered_predicates.hpp"
#include "cvms/convex_hull.hpp"
#include "support/oracle.hpp"

namespace cvms {
namespace {

using test::brute_force_hull;
using test::check_soup_invariants;
using test::describe;
using test::difference;
using test::Plane;
using test::Shape;

std::size_t num_edges(const PolygonSoup& soup) { return soup.face_indices.size() / 2; }

Vec3 v(long x, long y, long z) { return {Rational(x), Rational(y), Rational(z)}; }

enum class Kind { small_integers, integers, decimals, doubles };

// n seeded random points. Small integers give many duplicates, collinear and
// coplanar points; decimals are exact tenths; doubles are exact binary values.
std::vector<Vec3> random_cloud(std::uint64_t seed, int n, Kind kind) {
  std::mt19937_64 rng(seed);
  std::vector<Vec3> pts;
  for (int i = 0; i < n; ++i) {
    Vec3 p;
    for (int k = 0; k < 3; ++k) {
      switch (kind) {
        case Kind::small_integers:
          p[k] = Rational(static_cast<long>(rng() % 5) - 2);
          break;
        case Kind::integers:
          p[k] = Rational(static_cast<long>(rng() % 2001) - 1000);
          break;
        case Kind::decimals:
          p[k] = Rational(static_cast<long>(rng() % 20001) - 10000, 10);
          p[k].canonicalize();  // gmpxx does not reduce p/q on construction
          break;
        case Kind::doubles:
          p[k] = Rational(std::uniform_real_distribution<double>(-1.0, 1.0)(rng));
          break;
      }
    }
    pts.push_back(p);
  }
  return pts;
}

// convex_hull (the trusted construction) gives a polyhedron that passes every
// independent invariant check and describes the same solid as the soup, and
// the checked construction from the soup accepts it unchanged.
void expect_full_path(std::span<const Vec3> pts, const PolygonSoup& soup) {
  ConvexPolyhedron p = convex_hull(pts);
  ASSERT_EQ(test::check_invariants(p), "");
  EXPECT_TRUE(p.is_convex());
  EXPECT_TRUE(describe(p) == describe(soup)) << difference(describe(soup), describe(p));
  ConvexPolyhedron checked = ConvexPolyhedron::from_soup(soup);
  EXPECT_EQ(checked.num_vertices(), soup.points.size());
  EXPECT_EQ(checked.num_facets(), soup.num_faces());
}

// The soup is a valid convex polyhedron, its points are input points (as the
// source indices say), and it equals the brute-force hull.
void expect_matches_brute_force(std::span<const Vec3> pts) {
  std::vector<std::uint32_t> source;
  PolygonSoup soup = hull_soup(pts, &source);
  ASSERT_EQ(check_soup_invariants(soup), "");
  ASSERT_EQ(source.size(), soup.points.size());
  for (std::size_t i = 0; i < source.size(); ++i) ASSERT_EQ(pts[source[i]], soup.points[i]);
  Shape expected = brute_force_hull(pts);
  Shape actual = describe(soup);
  EXPECT_TRUE(expected == actual) << difference(expected, actual);
  expect_full_path(pts, soup);
}

// Checks for clouds too big for brute force: a valid convex polyhedron
// (strictly convex, maximal facets, closed) whose vertices are input points
// and whose facet planes have every input point on or below them.
void expect_valid_hull_of(std::span<const Vec3> pts, const PolygonSoup& soup) {
  ASSERT_EQ(check_soup_invariants(soup), "");
  std::set<Vec3> input(pts.begin(), pts.end());
  for (const Vec3& p : soup.points) ASSERT_TRUE(input.count(p)) << "output vertex is not an input point";
  Shape s = describe(soup);
  ASSERT_EQ(s.planes.size(), soup.num_faces());
  for (const Plane& pl : s.planes)
    for (const Vec3& p : input) ASSERT_LE(dot(pl.normal, p), pl.offset) << "an input point is above a facet";
  expect_full_path(pts, soup);
}

TEST(HullSoup, RandomCloudsMatchBruteForce) {
  const Kind kinds[] = {Kind::small_integers, Kind::integers, Kind::decimals, Kind::doubles};
  for (std::uint64_t seed = 1; seed <= 80; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    Kind kind = kinds[seed % 4];
    int n = seed % 20 == 0 ? 60 : 4 + static_cast<int>(seed * 7919 % 37);  // 4..40, sometimes 60
    auto pts = random_cloud(seed, n, kind);
    if (brute_force_hull(pts).planes.empty()) {
      EXPECT_THROW(hull_soup(pts), Error);  // a rare flat draw
      continue;
    }
    expect_matches_brute_force(pts);
  }
}

TEST(HullSoup, OrderDoesNotMatter) {
  for (std::uint64_t seed = 200; seed < 210; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    auto pts = random_cloud(seed, 300, Kind::small_integers);
    Shape first = describe(hull_soup(pts));
    std::mt19937_64 rng(seed);
    for (int round = 0; round < 3; ++round) {
      std::shuffle(pts.begin(), pts.end(), rng);
      Shape again = describe(hull_soup(pts));
      EXPECT_TRUE(first == again) << difference(first, again);
    }
  }
}

TEST(HullSoup, BigRandomClouds) {
  for (std::uint64_t seed = 300; seed < 306; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    Kind kind = seed % 3 == 0 ? Kind::doubles : (seed % 3 == 1 ? Kind::small_integers : Kind::integers);
    auto pts = random_cloud(seed, 2000, kind);
    expect_valid_hull_of(pts, hull_soup(pts));
  }
}

TEST(HullSoup, BallOfDoubles) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> pts;
  while (pts.size() < 3000) {
    double x = u(rng), y = u(rng), z = u(rng);
    if (x * x + y * y + z * z <= 1.0) pts.push_back({Rational(x), Rational(y), Rational(z)});
  }
  expect_valid_hull_of(pts, hull_soup(pts));
}

// Known solids: V/E/F by hand, and the same solid with extra points inside,
// on facets and on edges (which must not show up as vertices).
struct Solid {
  const char* name;
  std::vector<Vec3> vertices;
  std::size_t v, e, f;
};

std::vector<Vec3> signed_permutations(long a, long b, long c) {
  std::set<Vec3> out;
  long base[3] = {a, b, c};
  std::sort(base, base + 3);
  do {
    for (int s = 0; s < 8; ++s)
      out.insert(v(s & 1 ? -base[0] : base[0], s & 2 ? -base[1] : base[1], s & 4 ? -base[2] : base[2]));
  } while (std::next_permutation(base, base + 3));
  return {out.begin(), out.end()};
}

std::vector<Solid> solids() {
  return {
      {"tetrahedron", {v(1, 1, 1), v(1, -1, -1), v(-1, 1, -1), v(-1, -1, 1)}, 4, 6, 4},
      {"cube", signed_permutations(1, 1, 1), 8, 12, 6},
      {"octahedron", signed_permutations(0, 0, 1), 6, 12, 8},
      {"cuboctahedron", signed_permutations(0, 1, 1), 12, 24, 14},
      {"truncated octahedron", signed_permutations(0, 1, 2), 24, 36, 14},
  };
}

TEST(HullSoup, PlatonicAndArchimedeanSolids) {
  for (const Solid& s : solids()) {
    SCOPED_TRACE(s.name);
    ASSERT_EQ(s.vertices.size(), s.v);
    PolygonSoup soup = hull_soup(s.vertices);
    ASSERT_EQ(check_soup_invariants(soup), "");
    EXPECT_EQ(soup.points.size(), s.v);
    EXPECT_EQ(num_edges(soup), s.e);
    EXPECT_EQ(soup.num_faces(), s.f);
    expect_matches_brute_force(s.vertices);

    // Add the centre, edge midpoints, facet centroids-ish (midpoints of all
    // vertex pairs lie inside, on edges or on facets) and duplicates.
    std::vector<Vec3> more = s.vertices;
    for (std::size_t i = 0; i < s.vertices.size(); ++i)
      for (std::size_t j = i; j < s.vertices.size(); ++j)
        more.push_back(Rational(1, 2) * (s.vertices[i] + s.vertices[j]));
    more.push_back(v(0, 0, 0));
    std::mt19937_64 rng(7);
    std::shuffle(more.begin(), more.end(), rng);
    PolygonSoup soup2 = hull_soup(more);
    ASSERT_EQ(check_soup_invariants(soup2), "");
    EXPECT_TRUE(describe(soup2) == describe(soup)) << difference(describe(soup), describe(soup2));
    EXPECT_EQ(num_edges(soup2), s.e);
  }
}

TEST(HullSoup, GridIsACube) {
  for (int n : {2, 3, 6}) {
    SCOPED_TRACE("grid " + std::to_string(n));
    std::vector<Vec3> pts;
    for (int x = 0; x < n; ++x)
      for (int y = 0; y < n; ++y)
        for (int z = 0; z < n; ++z) pts.push_back(v(x, y, z));
    PolygonSoup soup = hull_soup(pts);
    ASSERT_EQ(check_soup_invariants(soup), "");
    Shape s = describe(soup);
    std::set<Vec3> corners;
    for (int c = 0; c < 8; ++c) corners.insert(v(c & 1 ? n - 1 : 0, c & 2 ? n - 1 : 0, c & 4 ? n - 1 : 0));
    EXPECT_EQ(s.vertices, corners);
    EXPECT_EQ(s.planes.size(), 6u);
    EXPECT_EQ(num_edges(soup), 12u);
    expect_full_path(pts, soup);
  }
}

TEST(HullSoup, ManyCoplanarPointsOnEachFace) {
  // Random integer points on the six faces of [-10, 10]^3: with the corners
  // the hull is the cube; without them, compare with brute force.
  for (std::uint64_t seed = 400; seed < 410; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    std::vector<Vec3> pts;
    for (int i = 0; i < 50; ++i) {
      Vec3 p = v(static_cast<long>(rng() % 21) - 10, static_cast<long>(rng() % 21) - 10,
                 static_cast<long>(rng() % 21) - 10);
      p[static_cast<int>(rng() % 3)] = rng() % 2 ? 10 : -10;
      pts.push_back(p);
    }
    expect_matches_brute_force(pts);
    for (const Vec3& c : signed_permutations(10, 10, 10)) pts.push_back(c);
    PolygonSoup soup = hull_soup(pts);
    ASSERT_EQ(check_soup_invariants(soup), "");
    Shape s = describe(soup);
    EXPECT_EQ(s.vertices.size(), 8u);
    EXPECT_EQ(s.planes.size(), 6u);
    expect_full_path(pts, soup);
  }
}

TEST(HullSoup, PyramidWithManyPointsOnTheBase) {
  // The base is a regular-ish polygon of lattice points on a circle (all
  // extreme in the base plane) plus points inside the base and on its sides.
  std::vector<Vec3> pts;
  const long r2 = 325;  // 5^2 * 13: many lattice points on x^2 + y^2 = 325
  for (long x = -18; x <= 18; ++x)
    for (long y = -18; y <= 18; ++y)
      if (x * x + y * y == r2) pts.push_back(v(x, y, 0));
  const std::size_t circle = pts.size();
  ASSERT_GE(circle, 20u);
  for (long x = -5; x <= 5; ++x) pts.push_back(v(x, 2 * x % 7, 0));
  pts.push_back(v(1, 2, 30));
  PolygonSoup soup = hull_soup(pts);
  ASSERT_EQ(check_soup_invariants(soup), "");
  EXPECT_EQ(soup.points.size(), circle + 1);
  EXPECT_EQ(soup.num_faces(), circle + 1);
  std::size_t biggest = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) biggest = std::max(biggest, soup.face(f).size());
  EXPECT_EQ(biggest, circle);
  expect_full_path(pts, soup);
}

std::vector<Vec3> sphere_points(long r2) {
  std::vector<Vec3> pts;
  long r = 0;
  while ((r + 1) * (r + 1) <= r2) ++r;
  for (long x = -r; x <= r; ++x)
    for (long y = -r; y <= r; ++y)
      for (long z = -r; z <= r; ++z)
        if (x * x + y * y + z * z == r2) pts.push_back(v(x, y, z));
  return pts;
}

// The plane triples hull_soup reports (hull_soup.hpp), checked against the
// exact predicates: for every face, three input points on which every
// corner of the face lies, with every input point on or below them and some
// strictly below (so the triple spans the face's plane, counterclockwise
// from outside); and no two faces with the same triple, compared as whole
// triples. Approximations with no error bound decide everything exactly, as
// the dual hull's fallbacks do; exact doubles let the filters decide.
void expect_plane_triples(std::span<const Vec3> pts) {
  std::vector<std::array<double, 3>> doubles;
  for (const Vec3& p : pts) doubles.push_back({p.x.get_d(), p.y.get_d(), p.z.get_d()});
  for (const double error : {0.0, std::numeric_limits<double>::infinity()}) {
    SCOPED_TRACE("error bound " + std::to_string(error));
    const ApproximatePoints approx{doubles, error, [&](std::uint32_t i) { return pts[i]; }};
    const ExactOrient orient = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
      return orient3d(pts[a], pts[b], pts[c], pts[d]);
    };
    std::vector<std::uint32_t> source;
    std::vector<std::array<std::uint32_t, 3>> planes;
    const PolygonSoup soup = hull_soup(approx, orient, {}, source, &planes);
    ASSERT_EQ(planes.size(), soup.num_faces());
    std::set<std::array<std::uint32_t, 3>> distinct;
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      const auto [i, j, k] = planes[f];
      for (const std::uint32_t c : soup.face(f))
        ASSERT_EQ(orient3d(pts[i], pts[j], pts[k], pts[source[c]]), Sign::zero) << "face " << f << " corner " << c;
      bool below = false;
      for (const Vec3& p : pts) {
        const Sign s = orient3d(pts[i], pts[j], pts[k], p);
        ASSERT_NE(s, Sign::positive) << "face " << f << ": a point above its triple";
        below = below || s == Sign::negative;
      }
      ASSERT_TRUE(below) << "face " << f << ": a collinear triple";
      std::array<std::uint32_t, 3> sorted = planes[f];
      std::sort(sorted.begin(), sorted.end());
      ASSERT_TRUE(distinct.insert(sorted).second) << "face " << f << " repeats another face's triple";
    }
  }
}

TEST(HullSoup, PlaneTriplesSpanTheFaces) {
  for (int n : {2, 3, 5}) {
    std::vector<Vec3> grid;
    for (int x = 0; x < n; ++x)
      for (int y = 0; y < n; ++y)
        for (int z = 0; z < n; ++z) grid.push_back(v(x, y, z));
    expect_plane_triples(grid);
  }
  expect_plane_triples(sphere_points(9));
  for (std::uint64_t seed = 500; seed < 520; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_plane_triples(random_cloud(seed, 60, Kind::small_integers));
    std::mt19937_64 rng(seed);
    std::vector<Vec3> faces;  // many coplanar points on the faces of a cube
    for (int i = 0; i < 80; ++i) {
      Vec3 p = v(static_cast<long>(rng() % 7) - 3, static_cast<long>(rng() % 7) - 3, static_cast<long>(rng() % 7) - 3);
      p[static_cast<int>(rng() % 3)] = rng() % 2 ? 3 : -3;
      faces.push_back(p);
    }
    expect_plane_triples(faces);
  }
}

TEST(HullSoup, CosphericalPoints) {
  // r^2 = 9: 30 lattice points, many of them on common circles (facets with
  // more than three vertices).
  auto small = sphere_points(9);
  ASSERT_EQ(small.size(), 30u);
  expect_matches_brute_force(small);
  // r^2 = 2 * 3^2 * 5^2 = 450: every lattice point on the sphere is extreme.
  auto big = sphere_points(450);
  ASSERT_GE(big.size(), 200u);
  PolygonSoup soup = hull_soup(big);
  expect_valid_hull_of(big, soup);
  EXPECT_EQ(soup.points.size(), big.size());
}

TEST(HullSoup, DuplicatedPoints) {
  for (std::uint64_t seed = 500; seed < 510; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    auto pts = random_cloud(seed, 20, Kind::integers);
    auto twice = pts;
    twice.insert(twice.end(), pts.begin(), pts.end());
    twice.insert(twice.end(), pts.begin(), pts.begin() + 5);
    std::mt19937_64 rng(seed);
    std::shuffle(twice.begin(), twice.end(), rng);
    expect_matches_brute_force(twice);
  }
}

void expect_degenerate(std::span<const Vec3> pts, const std::string& word) {
  try {
    hull_soup(pts);
    ADD_FAILURE() << "no error; expected one saying " << word;
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::degenerate);
    EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
  }
}

TEST(HullSoup, TooFewPoints) {
  expect_degenerate({}, "no points");
  std::vector<Vec3> one{v(1, 2, 3)};
  expect_degenerate(one, "equal");
  std::vector<Vec3> two{v(1, 2, 3), v(4, 5, 6)};
  expect_degenerate(two, "collinear");
  std::vector<Vec3> three{v(1, 2, 3), v(4, 5, 6), v(0, 0, 1)};
  expect_degenerate(three, "coplanar");
  std::vector<Vec3> four{v(1, 2, 3), v(4, 5, 6), v(0, 0, 1), v(0, 1, 0)};
  PolygonSoup soup = hull_soup(four);
  EXPECT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.num_faces(), 4u);
  // The fourth point is an affine combination of the first three.
  std::vector<Vec3> four_flat{v(1, 2, 3), v(4, 5, 6), v(0, 0, 1), v(0, 0, 0)};
  four_flat[3] = four_flat[0] + Rational(2) * (four_flat[1] - four_flat[0]) - (four_flat[2] - four_flat[0]);
  expect_degenerate(four_flat, "coplanar");
}

TEST(HullSoup, AllEqual) {
  std::vector<Vec3> pts(17, Vec3{Rational(1, 3), Rational(-2), Rational(5, 7)});
  expect_degenerate(pts, "equal");
}

TEST(HullSoup, Collinear) {
  std::vector<Vec3> pts;
  for (long k = -20; k <= 20; k += 3) pts.push_back(v(4 + k, 5 + 2 * k, 6 - 3 * k));
  pts.push_back(pts[3]);
  expect_degenerate(pts, "collinear");
  std::vector<Vec3> axis;
  for (long k = 0; k < 10; ++k) axis.push_back(v(0, 0, k * k));
  expect_degenerate(axis, "collinear");
}

TEST(HullSoup, CoplanarInAxisAndSkewPlanes) {
  std::mt19937_64 rng(600);
  auto r = [&] { return static_cast<long>(rng() % 41) - 20; };
  for (int plane = 0; plane < 4; ++plane) {
    SCOPED_TRACE("plane " + std::to_string(plane));
    std::vector<Vec3> pts;
    for (int i = 0; i < 100; ++i) {
      long a = r(), b = r();
      switch (plane) {
        case 0:
          pts.push_back(v(a, b, 0));
          break;  // xy
        case 1:
          pts.push_back(v(a, 7, b));
          break;  // xz (at y = 7)
        case 2:
          pts.push_back(v(-3, a, b));
          break;   // yz (at x = -3)
        case 3: {  // x + 2y + 3z = 5
          Rational z(5 - a - 2 * b, 3);
          z.canonicalize();
          pts.push_back({Rational(a), Rational(b), z});
          break;
        }
      }
    }
    expect_degenerate(pts, "coplanar");
    // One point off the plane makes it a pyramid.
    pts.push_back(v(1, 1, 1) + pts[0]);
    if (plane == 0) pts.back() = v(0, 0, 1);
    expect_valid_hull_of(pts, hull_soup(pts));
  }
}

TEST(HullSoup, TinyAndHugeCoordinates) {
  // Exactness does not depend on scale: a cube of side 1e-300 around 1e300.
  Rational tiny = parse_rational("1e-300"), huge = parse_rational("1e300");
  std::vector<Vec3> pts;
  for (const Vec3& c : signed_permutations(1, 1, 1)) pts.push_back(Vec3{huge, huge, huge} + tiny * c);
  pts.push_back({huge, huge, huge});
  predicate_counters() = {};
  PolygonSoup soup = hull_soup(pts);
  EXPECT_GT(predicate_counters().exact, 0u);  // the double filter cannot decide here
  ASSERT_EQ(check_soup_invariants(soup), "");
  EXPECT_EQ(soup.points.size(), 8u);
  EXPECT_EQ(soup.num_faces(), 6u);
  expect_full_path(pts, soup);
}

}  // namespace
}  // namespace cvms
