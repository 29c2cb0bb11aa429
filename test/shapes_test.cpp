// SPDX-License-Identifier: MIT
// Tests of the shape generators: geodesic sphere points, rational rotations,
// circle polygons, random clouds, and the polyhedra built from them (checked
// against hand-counted V/E/F and the brute-force hull of test/support).
#include "cvms/shapes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>
#include <ostream>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "cvms/error.hpp"
#include "support/oracle.hpp"

namespace cvms {
namespace {

using shapes::geodesic_sphere_points;

struct P3 {
  double x, y, z;
};

P3 to_p3(const Vec3& v) { return {v.x.get_d(), v.y.get_d(), v.z.get_d()}; }

double distance(const P3& a, const P3& b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

template <class F>
void expect_error(F&& f, ErrorCategory category) {
  try {
    f();
    ADD_FAILURE() << "no error thrown";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), category) << e.what();
  }
}

// ---- geodesic sphere points -------------------------------------------------

TEST(GeodesicSpherePoints, CountIsTenTimesFourToTheLevelPlusTwo) {
  for (bool rotated : {false, true})
    for (int k = 1; k <= 6; ++k) {
      std::size_t expected = 10 * (std::size_t{1} << (2 * (k - 1))) + 2;
      EXPECT_EQ(geodesic_sphere_points(k, rotated).size(), expected) << "k " << k << " rotated " << rotated;
    }
}

TEST(GeodesicSpherePoints, RejectsLevelsOutsideOneToNine) {
  for (int k : {-1, 0, 10, 1000}) {
    expect_error([k] { (void)geodesic_sphere_points(k); }, ErrorCategory::invalid_argument);
    expect_error([k] { (void)shapes::geodesic_sphere(k); }, ErrorCategory::invalid_argument);
    expect_error([k] { (void)shapes::rotated_geodesic_sphere(k); }, ErrorCategory::invalid_argument);
  }
}

TEST(GeodesicSpherePoints, AreDistinctDoublesOnTheUnitSphere) {
  for (bool rotated : {false, true})
    for (int k = 1; k <= 5; ++k) {
      SCOPED_TRACE("k " + std::to_string(k) + " rotated " + std::to_string(rotated));
      std::vector<Vec3> points = geodesic_sphere_points(k, rotated);
      std::set<Vec3> distinct(points.begin(), points.end());
      EXPECT_EQ(distinct.size(), points.size());
      for (const Vec3& p : points) {
        ASSERT_TRUE(is_double_exact(p.x) && is_double_exact(p.y) && is_double_exact(p.z));
        // Exact |p|^2 - 1: each coordinate is within an ulp or so of the
        // true unit vector's.
        Rational norm2 = dot(p, p) - 1;
        ASSERT_LT(std::fabs(norm2.get_d()), 1e-15)
            << to_string(p.x) << " " << to_string(p.y) << " " << to_string(p.z);
      }
    }
}

// The 12 icosahedron vertices, from their definition, in long double.
std::vector<P3> reference_icosahedron() {
  const long double phi = (1.0L + std::sqrt(5.0L)) / 2.0L;
  const long double n = std::sqrt(1.0L + phi * phi);
  const double a = static_cast<double>(1.0L / n), b = static_cast<double>(phi / n);
  std::vector<P3> points;
  for (double s : {-1.0, 1.0})
    for (double t : {-1.0, 1.0}) {
      points.push_back({0, s * a, t * b});
      points.push_back({s * a, t * b, 0});
      points.push_back({t * b, 0, s * a});
    }
  return points;
}

TEST(GeodesicSpherePoints, LevelOneIsTheIcosahedron) {
  std::vector<Vec3> points = geodesic_sphere_points(1);
  std::vector<P3> reference = reference_icosahedron();
  for (const P3& r : reference) {
    int matches = 0;
    for (const Vec3& p : points)
      if (distance(to_p3(p), r) < 1e-15) ++matches;
    EXPECT_EQ(matches, 1) << r.x << " " << r.y << " " << r.z;
  }
}

TEST(GeodesicSpherePoints, LevelTwoAddsTheNormalisedEdgeMidpoints) {
  std::vector<P3> ico = reference_icosahedron();
  std::vector<P3> expected = ico;
  const double edge = 1.0514622242382672;  // 4 / sqrt(10 + 2 sqrt 5), circumradius 1
  for (std::size_t i = 0; i < ico.size(); ++i)
    for (std::size_t j = i + 1; j < ico.size(); ++j)
      if (std::fabs(distance(ico[i], ico[j]) - edge) < 1e-9) {
        P3 m{ico[i].x + ico[j].x, ico[i].y + ico[j].y, ico[i].z + ico[j].z};
        double n = std::sqrt(m.x * m.x + m.y * m.y + m.z * m.z);
        expected.push_back({m.x / n, m.y / n, m.z / n});
      }
  ASSERT_EQ(expected.size(), 42u);
  std::vector<Vec3> points = geodesic_sphere_points(2);
  ASSERT_EQ(points.size(), 42u);
  for (const P3& r : expected) {
    int matches = 0;
    for (const Vec3& p : points)
      if (distance(to_p3(p), r) < 1e-15) ++matches;
    EXPECT_EQ(matches, 1) << r.x << " " << r.y << " " << r.z;
  }
}

TEST(GeodesicSpherePoints, NearestNeighbourDistanceHalvesPerLevel) {
  // A subdivision that shares midpoints correctly has no near-duplicates:
  // every point's nearest neighbour is about an edge length away (a bit
  // more than half the previous level's: projection stretches the edges).
  double edge = 1.0514622242382672;
  for (int k = 1; k <= 4; ++k) {
    std::vector<Vec3> points = geodesic_sphere_points(k);
    double nearest = 10;
    for (std::size_t i = 0; i < points.size(); ++i)
      for (std::size_t j = i + 1; j < points.size(); ++j)
        nearest = std::min(nearest, distance(to_p3(points[i]), to_p3(points[j])));
    EXPECT_GT(nearest, 0.7 * edge) << "k " << k;
    EXPECT_LT(nearest, 1.1 * edge) << "k " << k;
    edge /= 2;
  }
}

TEST(GeodesicSpherePoints, RotatedIcosahedronIsARotationOfTheIcosahedron) {
  // Same Gram matrix (up to the rounding), but no point in common.
  std::vector<Vec3> plain = geodesic_sphere_points(1, false), rotated = geodesic_sphere_points(1, true);
  ASSERT_EQ(plain.size(), rotated.size());
  for (std::size_t i = 0; i < plain.size(); ++i) {
    for (std::size_t j = 0; j < plain.size(); ++j) {
      double a = dot(plain[i], plain[j]).get_d(), b = dot(rotated[i], rotated[j]).get_d();
      EXPECT_NEAR(a, b, 1e-14) << i << " " << j;
      EXPECT_GT(distance(to_p3(plain[i]), to_p3(rotated[j])), 1e-3) << i << " " << j;
    }
  }
}

TEST(GeodesicSpherePoints, AreDeterministic) {
  for (bool rotated : {false, true})
    EXPECT_EQ(geodesic_sphere_points(4, rotated), geodesic_sphere_points(4, rotated));
}

// FNV-1a over the bits of every coordinate. A change means the shapes differ
// from those on the machine that recorded the value (compiler contraction,
// excess precision or a changed subdivision order): the benchmark inputs
// would no longer be the same polyhedra everywhere.
std::uint64_t fingerprint(const std::vector<Vec3>& points) {
  std::uint64_t h = 1469598103934665603ULL;
  for (const Vec3& p : points)
    for (int i = 0; i < 3; ++i) {
      double d = p[i].get_d();
      std::uint64_t bits;
      std::memcpy(&bits, &d, sizeof bits);
      for (int b = 0; b < 8; ++b) {
        h ^= (bits >> (8 * b)) & 0xff;
        h *= 1099511628211ULL;
      }
    }
  return h;
}

TEST(GeodesicSpherePoints, AreTheSameOnEveryPlatform) {
  EXPECT_EQ(fingerprint(geodesic_sphere_points(1, false)), 1732009003384838995ULL);
  EXPECT_EQ(fingerprint(geodesic_sphere_points(5, false)), 3013464787883351211ULL);
  EXPECT_EQ(fingerprint(geodesic_sphere_points(1, true)), 4732606103794092535ULL);
  EXPECT_EQ(fingerprint(geodesic_sphere_points(5, true)), 4522494057988815283ULL);
}

// ---- rotations and scalings ---------------------------------------------------

Mat3 matrix(std::initializer_list<int> entries) {
  Mat3 m;
  int i = 0;
  for (int e : entries) {
    m.m[i / 3][i % 3] = e;
    ++i;
  }
  return m;
}

bool equal(const Mat3& a, const Mat3& b) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (a.m[i][j] != b.m[i][j]) return false;
  return true;
}

Mat3 transpose(const Mat3& a) {
  Mat3 t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t.m[i][j] = a.m[j][i];
  return t;
}

TEST(RationalRotation, HandCheckedQuarterAndHalfTurns) {
  using shapes::rational_rotation;
  EXPECT_TRUE(equal(rational_rotation(1, 0, 0, 0), Mat3::identity()));
  EXPECT_TRUE(equal(rational_rotation(-7, 0, 0, 0), Mat3::identity()));
  EXPECT_TRUE(equal(rational_rotation(0, 1, 0, 0), matrix({1, 0, 0, 0, -1, 0, 0, 0, -1})));
  EXPECT_TRUE(equal(rational_rotation(0, 0, 3, 0), matrix({-1, 0, 0, 0, 1, 0, 0, 0, -1})));
  // Quarter turns about x, y, z (counterclockwise seen from the +axis).
  EXPECT_TRUE(equal(rational_rotation(1, 1, 0, 0), matrix({1, 0, 0, 0, 0, -1, 0, 1, 0})));
  EXPECT_TRUE(equal(rational_rotation(2, 0, 2, 0), matrix({0, 0, 1, 0, 1, 0, -1, 0, 0})));
  EXPECT_TRUE(equal(rational_rotation(1, 0, 0, 1), matrix({0, -1, 0, 1, 0, 0, 0, 0, 1})));
  // (1, 1, 1, 1): the third of a turn about (1,1,1) that maps x -> y -> z.
  EXPECT_TRUE(equal(rational_rotation(1, 1, 1, 1), matrix({0, 0, 1, 1, 0, 0, 0, 1, 0})));
  // A Pythagorean one: (2, 0, 0, 1) turns about z by 2 atan(1/2): cos 3/5, sin 4/5.
  Mat3 r = rational_rotation(2, 0, 0, 1);
  Mat3 expected;
  expected.m[0][0] = Rational(3, 5);
  expected.m[0][1] = Rational(-4, 5);
  expected.m[1][0] = Rational(4, 5);
  expected.m[1][1] = Rational(3, 5);
  expected.m[2][2] = 1;
  EXPECT_TRUE(equal(r, expected));
}

TEST(RationalRotation, IsOrthogonalWithDeterminantOneAndFixesItsAxis) {
  std::mt19937_64 engine(7);
  std::vector<std::array<std::int64_t, 4>> quaternions{
      {1, 3, 5, 7},
      {std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::min(), 1, -1},
      {std::numeric_limits<std::int64_t>::min(), 0, 0, 0}};
  for (int i = 0; i < 50; ++i) {
    std::array<std::int64_t, 4> q;
    for (auto& c : q) c = static_cast<std::int64_t>(engine() >> (i % 2 == 0 ? 60 : 2)) - (i % 2 == 0 ? 8 : 0);
    if (q == std::array<std::int64_t, 4>{0, 0, 0, 0}) continue;
    quaternions.push_back(q);
  }
  for (const auto& [a, b, c, d] : quaternions) {
    SCOPED_TRACE(std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + " " +
                 std::to_string(d));
    Mat3 r = shapes::rational_rotation(a, b, c, d);
    EXPECT_TRUE(equal(transpose(r) * r, Mat3::identity()));
    EXPECT_EQ(r.determinant(), 1);
    Vec3 axis{Rational(mpz_class(std::to_string(b))), Rational(mpz_class(std::to_string(c))),
              Rational(mpz_class(std::to_string(d)))};
    EXPECT_EQ(r * axis, axis);
  }
}

TEST(RationalRotation, RejectsTheZeroQuaternion) {
  expect_error([] { (void)shapes::rational_rotation(0, 0, 0, 0); }, ErrorCategory::invalid_argument);
}

TEST(Scaling, IsDiagonalAndRejectsZero) {
  Mat3 s = shapes::scaling(2, Rational(-1, 3), 5);
  EXPECT_EQ((s * Vec3{1, 1, 1}), (Vec3{2, Rational(-1, 3), 5}));
  EXPECT_EQ(s.determinant(), Rational(-10, 3));
  expect_error([] { (void)shapes::scaling(1, 0, 1); }, ErrorCategory::invalid_argument);
}

// ---- circle polygons ------------------------------------------------------------

void check_circle_polygon(int n, bool all_pairs) {
  SCOPED_TRACE("n " + std::to_string(n));
  std::vector<Vec2> points = shapes::circle_polygon(n);
  ASSERT_EQ(points.size(), static_cast<std::size_t>(n));
  int upward_crossings = 0;
  for (int i = 0; i < n; ++i) {
    const Vec2& p = points[i];
    const Vec2& q = points[(i + 1) % n];
    ASSERT_EQ(p.x * p.x + p.y * p.y, 1) << i;
    // Strictly convex, counterclockwise: every other point strictly left of
    // the edge p -> q (plain rational arithmetic, not the predicates).
    if (all_pairs) {
      for (int j = 0; j < n; ++j) {
        if (j != i && j != (i + 1) % n) {
          ASSERT_GT(sgn(cross(q - p, points[j] - p)), 0) << i << " " << j;
        }
      }
    } else {
      ASSERT_GT(sgn(cross(q - p, points[(i + 2) % n] - p)), 0) << i;
    }
    ASSERT_GT(sgn(cross(p, q)), 0) << i;  // a counterclockwise step around the centre
    if (sgn(p.y) < 0 && sgn(q.y) >= 0) ++upward_crossings;
    // Nearly regular: within a quarter of the step of the aimed-at angle.
    double angle = std::atan2(p.y.get_d(), p.x.get_d());
    double target = -std::numbers::pi + 2 * std::numbers::pi * (i + 0.5) / n;
    ASSERT_LT(std::fabs(angle - target), std::numbers::pi / (2 * n)) << i;
  }
  EXPECT_EQ(upward_crossings, 1);  // winds around once
}

TEST(CirclePolygon, IsExactlyOnTheCircleStrictlyConvexAndNearlyRegular) {
  for (int n = 3; n <= 40; ++n) check_circle_polygon(n, true);
  for (int n : {97, 128, 1000, 12345}) check_circle_polygon(n, false);
}

TEST(CirclePolygon, HasSmallDenominators) {
  // t = p / (4n): the denominators are 16 n^2 + p^2 (or divisors).
  for (const Vec2& p : shapes::circle_polygon(6)) {
    EXPECT_LE(p.x.get_den(), 16 * 36 + 16 * 36 * 4);
    EXPECT_LE(p.y.get_den(), 16 * 36 + 16 * 36 * 4);
  }
  // n = 4: t = tan(-3pi/8), tan(-pi/8), ... = -2.414.., -0.414.. -> -39/16, -7/16, 7/16, 39/16.
  std::vector<Vec2> square = shapes::circle_polygon(4);
  ASSERT_EQ(square.size(), 4u);
  auto point = [](int p, int d) {
    return Vec2{Rational(d * d - p * p, d * d + p * p), Rational(2 * p * d, d * d + p * p)};
  };
  EXPECT_EQ(square[0], point(-39, 16));
  EXPECT_EQ(square[1], point(-7, 16));
  EXPECT_EQ(square[2], point(7, 16));
  EXPECT_EQ(square[3], point(39, 16));
}

TEST(CirclePolygon, RejectsBadCounts) {
  for (int n : {-5, 0, 2, 1000001}) {
    expect_error([n] { (void)shapes::circle_polygon(n); }, ErrorCategory::invalid_argument);
    expect_error([n] { (void)shapes::prism(n, 1); }, ErrorCategory::invalid_argument);
  }
  expect_error([] { (void)shapes::prism(5, 0); }, ErrorCategory::invalid_argument);
  expect_error([] { (void)shapes::prism(5, Rational(-1, 2)); }, ErrorCategory::invalid_argument);
}

// ---- random clouds ----------------------------------------------------------------

bool spans_3d(const std::vector<Vec3>& points) {
  // Plain rational arithmetic: some four points with nonzero volume.
  for (std::size_t i = 1; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      Vec3 n = cross(points[i] - points[0], points[j] - points[0]);
      if (is_zero(n)) continue;
      for (std::size_t l = j + 1; l < points.size(); ++l)
        if (sgn(dot(n, points[l] - points[0])) != 0) return true;
    }
  return false;
}

TEST(RandomPoints, AreSeededIntegersInRange) {
  for (std::uint64_t seed : {0ULL, 1ULL, 12345ULL}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::vector<Vec3> points = shapes::random_points(seed, 200, 50);
    EXPECT_EQ(points, shapes::random_points(seed, 200, 50));
    EXPECT_NE(points, shapes::random_points(seed + 1, 200, 50));
    ASSERT_EQ(points.size(), 200u);
    std::set<long> seen;
    for (const Vec3& p : points)
      for (int i = 0; i < 3; ++i) {
        ASSERT_EQ(p[i].get_den(), 1);
        ASSERT_TRUE(p[i] >= -50 && p[i] <= 50);
        seen.insert(p[i].get_num().get_si());
      }
    EXPECT_GT(seen.size(), 90u);  // 600 draws from 101 values
    EXPECT_TRUE(seen.count(-50) + seen.count(50) > 0 || seen.size() > 95);
  }
}

TEST(RandomPoints, HugeRangeDoesNotOverflow) {
  const std::int64_t range = std::int64_t{1} << 62;
  std::vector<Vec3> points = shapes::random_points(3, 100, range);
  bool big = false;
  for (const Vec3& p : points)
    for (int i = 0; i < 3; ++i) {
      ASSERT_TRUE(abs(p[i]) <= Rational(mpz_class("4611686018427387904")));
      if (abs(p[i]) > Rational(mpz_class("1000000000000000000"))) big = true;
    }
  EXPECT_TRUE(big);
}

TEST(RandomPoints, DrawMorePointsUntilTheCloudSpans3d) {
  // With range 1, four points of the 27 grid points are often coplanar.
  int extended = 0;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::vector<Vec3> points = shapes::random_points(seed, 4, 1);
    ASSERT_GE(points.size(), 4u);
    ASSERT_TRUE(spans_3d(points));
    if (points.size() > 4) {
      ++extended;
      // Only as many as needed: without the last point it is flat.
      std::vector<Vec3> fewer(points.begin(), points.end() - 1);
      EXPECT_FALSE(spans_3d(fewer));
    }
    // The first four are the same draws as without extension.
    std::vector<Vec3> more = shapes::random_points(seed, 5, 1);
    EXPECT_TRUE(std::equal(points.begin(), points.begin() + 4, more.begin()));
  }
  EXPECT_GT(extended, 0);
}

TEST(RandomPoints, RejectsBadArguments) {
  expect_error([] { (void)shapes::random_points(1, 3); }, ErrorCategory::invalid_argument);
  expect_error([] { (void)shapes::random_points(1, 10, 0); }, ErrorCategory::invalid_argument);
  expect_error([] { (void)shapes::random_points(1, 10, -5); }, ErrorCategory::invalid_argument);
  expect_error([] { (void)shapes::random_points(1, 10, (std::int64_t{1} << 62) + 1); },
               ErrorCategory::invalid_argument);
  expect_error([] { (void)shapes::random_hull(1, 2); }, ErrorCategory::invalid_argument);
}

TEST(RandomPoints, AreTheSameOnEveryPlatform) {
  // mt19937_64 and the rejection sampling are fully specified.
  EXPECT_EQ(fingerprint(shapes::random_points(42, 1000, 1000)), 9956623497615799792ULL);
}

// ---- boxes ------------------------------------------------------------------------

TEST(Box, RejectsEmptyOrFlatBoxes) {
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 lo{0, 0, 0}, hi{1, 1, 1};
    hi[axis] = 0;
    expect_error([&] { (void)shapes::box(lo, hi); }, ErrorCategory::degenerate);
    hi[axis] = -1;
    expect_error([&] { (void)shapes::box(lo, hi); }, ErrorCategory::degenerate);
  }
}

// ---- polyhedra ------------------------------------------------------------------------

using test::brute_force_hull;
using test::check_invariants;
using test::describe;
using test::difference;

struct Counts {
  std::uint32_t v, e, f;
  friend bool operator==(const Counts&, const Counts&) = default;
};
Counts counts(const ConvexPolyhedron& p) { return {p.num_vertices(), p.num_edges(), p.num_facets()}; }
std::ostream& operator<<(std::ostream& out, const Counts& c) {
  return out << c.v << "/" << c.e << "/" << c.f;
}

// Checks p against the brute-force hull of the points it is meant to be the
// hull of, and its invariants.
void expect_hull_of(const ConvexPolyhedron& p, const std::vector<Vec3>& points) {
  EXPECT_EQ(check_invariants(p), "");
  EXPECT_TRUE(p.is_convex());
  test::Shape expected = brute_force_hull(points);
  ASSERT_FALSE(expected.planes.empty());
  test::Shape actual = describe(p);
  EXPECT_TRUE(expected == actual) << difference(expected, actual);
}

std::vector<Vec3> sign_combinations(const Vec3& v) {
  std::vector<Vec3> out;
  for (int s = 0; s < 8; ++s)
    out.push_back({(s & 1) ? -v.x : v.x, (s & 2) ? -v.y : v.y, (s & 4) ? -v.z : v.z});
  return out;
}

TEST(Platonic, TetrahedronIsTheHullOfItsFourAlternateCubeCorners) {
  ConvexPolyhedron t = shapes::tetrahedron();
  EXPECT_EQ(counts(t), (Counts{4, 6, 4}));
  std::vector<Vec3> corners{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  expect_hull_of(t, corners);
  // Planes by hand: x + y + z = -1 opposite (1,1,1), and its reflections.
  std::set<test::Plane> planes{{{-1, -1, -1}, 1}, {{-1, 1, 1}, 1}, {{1, -1, 1}, 1}, {{1, 1, -1}, 1}};
  EXPECT_TRUE(describe(t).planes == planes);
}

TEST(Platonic, CubeIsMinusOneOneCubed) {
  ConvexPolyhedron c = shapes::cube();
  EXPECT_EQ(counts(c), (Counts{8, 12, 6}));
  expect_hull_of(c, sign_combinations({1, 1, 1}));
}

TEST(Platonic, OctahedronIsTheUnitCrossPolytope) {
  ConvexPolyhedron o = shapes::octahedron();
  EXPECT_EQ(counts(o), (Counts{6, 12, 8}));
  std::vector<Vec3> points{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  expect_hull_of(o, points);
  std::set<test::Plane> planes;
  for (const Vec3& n : sign_combinations({1, 1, 1})) planes.insert({n, 1});
  EXPECT_TRUE(describe(o).planes == planes);
}

TEST(Platonic, TruncatedCubeHasSixOctagonsAndEightTriangles) {
  ConvexPolyhedron t = shapes::truncated_cube();
  EXPECT_EQ(counts(t), (Counts{24, 36, 14}));
  std::vector<Vec3> points;
  for (const Vec3& v : {Vec3{Rational(1, 3), 1, 1}, Vec3{1, Rational(1, 3), 1}, Vec3{1, 1, Rational(1, 3)}})
    for (const Vec3& w : sign_combinations(v)) points.push_back(w);
  expect_hull_of(t, points);
  std::set<test::Plane> planes;
  for (const Vec3& n : sign_combinations({1, 1, 1})) planes.insert({n, Rational(7, 3)});
  for (int a = 0; a < 3; ++a)
    for (int s : {-1, 1}) {
      Vec3 n{0, 0, 0};
      n[a] = s;
      planes.insert({n, 1});
    }
  EXPECT_TRUE(describe(t).planes == planes);
  int octagons = 0, triangles = 0;
  for (FaceId f : t.mesh().faces()) {
    std::uint32_t d = t.mesh().degree(f);
    octagons += d == 8;
    triangles += d == 3;
  }
  EXPECT_EQ(octagons, 6);
  EXPECT_EQ(triangles, 8);
}

TEST(Box, IsTheHullOfItsCorners) {
  Vec3 lo{Rational(-1, 2), 3, -7}, hi{Rational(1, 3), 4, 100};
  ConvexPolyhedron b = shapes::box(lo, hi);
  EXPECT_EQ(counts(b), (Counts{8, 12, 6}));
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  expect_hull_of(b, corners);
}

TEST(Prism, IsTheHullOfTwoCirclePolygons) {
  for (int n = 3; n <= 12; ++n) {
    SCOPED_TRACE("n " + std::to_string(n));
    ConvexPolyhedron p = shapes::prism(n, Rational(5, 2));
    EXPECT_EQ(counts(p), (Counts{static_cast<std::uint32_t>(2 * n), static_cast<std::uint32_t>(3 * n),
                                 static_cast<std::uint32_t>(n + 2)}));
    std::vector<Vec3> points;
    for (const Vec2& q : shapes::circle_polygon(n))
      for (const Rational& z : {Rational(-5, 4), Rational(5, 4)}) points.push_back({q.x, q.y, z});
    expect_hull_of(p, points);
  }
  ConvexPolyhedron big = shapes::prism(500, 1);
  EXPECT_EQ(counts(big), (Counts{1000, 1500, 502}));
  EXPECT_EQ(check_invariants(big), "");
}

TEST(RandomHull, IsTheBruteForceHullOfItsPoints) {
  for (std::uint64_t seed : {1ULL, 2ULL, 3ULL, 99ULL}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_hull_of(shapes::random_hull(seed, 25, 100), shapes::random_points(seed, 25, 100));
  }
  // Tiny range: many coplanar and duplicate points.
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_hull_of(shapes::random_hull(seed, 12, 1), shapes::random_points(seed, 12, 1));
  }
}

// ---- geodesic spheres ------------------------------------------------------------

TEST(GeodesicSphere, LevelsOneAndTwoAreTheBruteForceHullOfTheirPoints) {
  for (bool rotated : {false, true})
    for (int k = 1; k <= 2; ++k) {
      SCOPED_TRACE("k " + std::to_string(k) + " rotated " + std::to_string(rotated));
      ConvexPolyhedron s = rotated ? shapes::rotated_geodesic_sphere(k) : shapes::geodesic_sphere(k);
      expect_hull_of(s, geodesic_sphere_points(k, rotated));
    }
}

TEST(GeodesicSphere, IsTheSubdivisionTriangulation) {
  // All points are extreme (they are on the sphere up to 1e-16, and the
  // subdivision's dihedral sag is far larger). Rounding could merge nearly
  // coplanar triangles or flip diagonals of nearly planar quads, but the
  // subdivision has none close enough: every hull facet is a subdivision
  // triangle, so the counts are those of the subdivision, and no hull edge
  // is a (much longer) quad diagonal.
  for (bool rotated : {false, true})
    for (int k = 1; k <= 4; ++k) {
      SCOPED_TRACE("k " + std::to_string(k) + " rotated " + std::to_string(rotated));
      ConvexPolyhedron s = rotated ? shapes::rotated_geodesic_sphere(k) : shapes::geodesic_sphere(k);
      std::vector<Vec3> points = geodesic_sphere_points(k, rotated);
      std::set<Vec3> vertices;
      for (VertexId v : s.mesh().vertices()) vertices.insert(s.vertex(v));
      EXPECT_TRUE(vertices == std::set<Vec3>(points.begin(), points.end()));
      const std::uint32_t power = 1u << (2 * (k - 1));
      EXPECT_EQ(counts(s), (Counts{10 * power + 2, 30 * power, 20 * power}));
      double shortest = 10, longest = 0;
      for (EdgeId e : s.mesh().edges()) {
        Vec3 d = s.edge_vector(Mesh::halfedge(e));
        double length = std::sqrt(dot(d, d).get_d());
        shortest = std::min(shortest, length);
        longest = std::max(longest, length);
      }
      EXPECT_LT(longest, 1.25 * shortest);
      if (k <= 3) {
        EXPECT_EQ(check_invariants(s), "");
      }
    }
}

// No facet normal of one sphere is parallel to one of the other, or on a
// great circle through an edge's two facet normals (plain rational
// arithmetic): the two Gaussian maps are in general position.
TEST(GeodesicSphere, RotatedGaussianMapIsInGeneralPosition) {
  for (int k = 1; k <= 2; ++k) {
    SCOPED_TRACE("k " + std::to_string(k));
    ConvexPolyhedron a = shapes::geodesic_sphere(k), b = shapes::rotated_geodesic_sphere(k);
    for (auto [p, q] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
      for (FaceId f : p->mesh().faces()) {
        const Vec3& n = p->normal(f);
        for (FaceId g : q->mesh().faces()) ASSERT_FALSE(is_zero(cross(n, q->normal(g))));
        for (EdgeId e : q->mesh().edges()) ASSERT_NE(sgn(dot(n, q->edge_vector(Mesh::halfedge(e)))), 0);
      }
    }
  }
}

}  // namespace
}  // namespace cvms
