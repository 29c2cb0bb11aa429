// SPDX-License-Identifier: MIT
// Long randomised runs of the exact quickhull against the brute-force hull
// (label "soak": not part of the default test run).
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "cvms/error.hpp"
#include "hull_soup.hpp"
#include "support/oracle.hpp"

namespace cvms {
namespace {

// Points from a small lattice, from a few random planes, or from a lattice
// sphere: inputs full of duplicates, coplanar and cospherical subsets.
std::vector<Vec3> structured_cloud(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto r = [&](long range) { return static_cast<long>(rng() % (2 * range + 1)) - range; };
  const int n = 4 + static_cast<int>(rng() % 45);
  std::vector<Vec3> pts;
  switch (seed % 3) {
    case 0:
      for (int i = 0; i < n; ++i) pts.push_back({Rational(r(2)), Rational(r(2)), Rational(r(2))});
      break;
    case 1: {
      // Points on three random planes a0 z = b - a1 x - a2 y (a0 is 1 or 2).
      long plane[3][4];
      for (auto& pl : plane) {
        pl[0] = 1 + static_cast<long>(rng() % 2);
        pl[1] = r(2);
        pl[2] = r(2);
        pl[3] = r(5);
      }
      for (int i = 0; i < n; ++i) {
        const long* pl = plane[rng() % 3];
        long x = r(6), y = r(6);
        Rational z(pl[3] - pl[1] * x - pl[2] * y, pl[0]);
        z.canonicalize();
        pts.push_back({Rational(x), Rational(y), z});
      }
      break;
    }
    default: {
      const long r2 = 9 + static_cast<long>(rng() % 3) * 8;  // 9, 17, 25
      std::vector<Vec3> sphere;
      for (long x = -5; x <= 5; ++x)
        for (long y = -5; y <= 5; ++y)
          for (long z = -5; z <= 5; ++z)
            if (x * x + y * y + z * z == r2) sphere.push_back({Rational(x), Rational(y), Rational(z)});
      for (int i = 0; i < n; ++i) pts.push_back(sphere[rng() % sphere.size()]);
      break;
    }
  }
  return pts;
}

TEST(QuickhullSoak, StructuredCloudsMatchBruteForce) {
  for (std::uint64_t seed = 1; seed <= 3000; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    auto pts = structured_cloud(seed);
    test::Shape expected = test::brute_force_hull(pts);
    if (expected.planes.empty()) {
      EXPECT_THROW(hull_soup(pts), Error);
      continue;
    }
    PolygonSoup soup = hull_soup(pts);
    ASSERT_EQ(test::check_soup_invariants(soup), "");
    test::Shape actual = test::describe(soup);
    ASSERT_TRUE(expected == actual) << test::difference(expected, actual);
  }
}

}  // namespace
}  // namespace cvms
