// SPDX-License-Identifier: MIT
// Tests of the quickhull entry points that take doubles: the same soup
// (points, faces, order and source indices) as converting every point to
// rationals first, and the brute-force hull on small clouds; degenerate and
// extreme inputs (1e300, 1e-300, subnormals) where the filters must give up;
// NaN and infinity rejected with the point's index.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/convex_hull.hpp"
#include "hull_soup.hpp"
#include "support/oracle.hpp"

namespace cvms {
namespace {

using Point = std::array<double, 3>;

std::vector<Vec3> exact_points(const std::vector<Point>& pts) {
  std::vector<Vec3> out;
  for (const Point& p : pts) out.push_back({Rational(p[0]), Rational(p[1]), Rational(p[2])});
  return out;
}

// Both entry points give the same soup, down to the numbering.
void expect_same_as_exact_path(const std::vector<Point>& pts) {
  const std::vector<Vec3> exact = exact_points(pts);
  std::vector<std::uint32_t> source_d, source_e;
  PolygonSoup from_doubles, from_exact;
  bool threw_d = false, threw_e = false;
  std::string what_d, what_e;
  try {
    from_doubles = hull_soup(std::span<const Point>(pts), &source_d);
  } catch (const Error& e) {
    threw_d = true;
    what_d = e.what();
  }
  try {
    from_exact = hull_soup(exact, &source_e);
  } catch (const Error& e) {
    threw_e = true;
    what_e = e.what();
  }
  ASSERT_EQ(threw_d, threw_e) << what_d << " / " << what_e;
  if (threw_d) {
    EXPECT_EQ(what_d, what_e);
    return;
  }
  ASSERT_EQ(test::check_soup_invariants(from_doubles), "");
  EXPECT_EQ(from_doubles.points, from_exact.points);
  EXPECT_EQ(from_doubles.face_offsets, from_exact.face_offsets);
  EXPECT_EQ(from_doubles.face_indices, from_exact.face_indices);
  EXPECT_EQ(source_d, source_e);
}

std::vector<Point> cloud(std::uint64_t seed, int n, double scale, double offset, bool grid) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Point> pts;
  for (int i = 0; i < n; ++i) {
    Point p;
    for (double& x : p)
      x = offset + scale * (grid ? static_cast<double>(static_cast<long>(rng() % 5) - 2) : u(rng));
    pts.push_back(p);
  }
  return pts;
}

TEST(HullFromDoubles, SmallCloudsMatchBruteForce) {
  const double scales[] = {1.0, 1e300, 1e-300, 0x1p-1070, 1e150};
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const double scale = scales[seed % 5];
    auto pts =
        cloud(seed, 5 + static_cast<int>(seed % 30), scale, seed % 3 == 0 ? 3.0 * scale : 0.0, seed % 2 == 0);
    const std::vector<Vec3> exact = exact_points(pts);
    const test::Shape expected = test::brute_force_hull(exact);
    if (expected.planes.empty()) {
      EXPECT_THROW(hull_soup(std::span<const Point>(pts)), Error);
      continue;
    }
    const test::Shape actual = test::describe(hull_soup(std::span<const Point>(pts)));
    EXPECT_TRUE(expected == actual) << test::difference(expected, actual);
    expect_same_as_exact_path(pts);
  }
}

TEST(HullFromDoubles, SameSoupAsExactPath) {
  // Random balls and cubes, lattices full of duplicates and coplanar points,
  // and scales where the filters must fall back (beyond 2^300, below 2^-1000).
  const double scales[] = {1.0, 1e300, 1e-300, 0x1p-1060, 0x1p299};
  for (std::uint64_t seed = 100; seed < 120; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const double scale = scales[seed % 5];
    expect_same_as_exact_path(cloud(seed, 1500, scale, 0.0, false));
    expect_same_as_exact_path(cloud(seed, 1500, scale, 0.5 * scale, true));
    if (HasFatalFailure()) return;
  }
}

TEST(HullFromDoubles, NearlyFlatClouds) {
  // A plane through the origin, points rounded onto it and nudged by an ulp:
  // every orientation is close to zero.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Point> pts;
  for (int i = 0; i < 2000; ++i) {
    const double x = u(rng), y = u(rng);
    double z = 0.3 * x - 0.7 * y;
    if (i % 7 == 0) z = std::nextafter(z, rng() % 2 ? 1.0 : -1.0);
    pts.push_back({x, y, z});
  }
  expect_same_as_exact_path(pts);
}

TEST(HullFromDoubles, DegenerateInputs) {
  std::vector<Point> coplanar, collinear, equal(9, Point{0.1, 0.2, 0.3});
  for (int i = 0; i < 50; ++i) {
    coplanar.push_back({i * 0.25, (i % 7) * 0.5, 2.0});
    collinear.push_back({i * 0.5, i * 1.5, -i * 0.25});
  }
  for (const auto& [pts, word] :
       {std::pair{coplanar, "coplanar"}, {collinear, "collinear"}, {equal, "equal"}}) {
    try {
      convex_hull(std::span<const Point>(pts));
      ADD_FAILURE() << "no error for " << word;
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::degenerate);
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  }
}

TEST(HullFromDoubles, NanAndInfinityNameThePoint) {
  auto pts = cloud(3, 20, 1.0, 0.0, false);
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity()};
  for (double b : bad) {
    auto broken = pts;
    broken[13][1] = b;
    try {
      convex_hull(std::span<const Point>(broken));
      ADD_FAILURE() << "no error for " << b;
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
      EXPECT_NE(std::string(e.what()).find("point 13 "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(std::isnan(b) ? "NaN" : "infinite"), std::string::npos)
          << e.what();
    }
  }
}

TEST(HullFromDoubles, PolyhedronEqualsExactPath) {
  auto pts = cloud(11, 3000, 1.0, 0.0, false);
  const ConvexPolyhedron a = convex_hull(std::span<const Point>(pts));
  const ConvexPolyhedron b = convex_hull(exact_points(pts));
  EXPECT_EQ(test::check_invariants(a), "");
  EXPECT_TRUE(test::describe(a) == test::describe(b));
}

}  // namespace
}  // namespace cvms
