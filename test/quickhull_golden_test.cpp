// SPDX-License-Identifier: MIT
// The quickhull's output, down to the numbering of the points and the order
// of the faces, is fixed by its exact decisions alone: faster filters must
// not change it. The digests below were computed with an exact-only
// quickhull (no double filters), so a filter that answers
// a sign differently from the exact predicate, or a changed tie-break in the
// initial simplex, shows up here even where the hull stays correct.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/rational.hpp"
#include "cvms/shapes.hpp"
#include "hull_soup.hpp"

namespace cvms {
namespace {

// BEGIN shared with the program that computed the digests
std::uint64_t fnv(std::uint64_t h, const std::string& s) {
  for (char c : s) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return h;
}

std::uint64_t digest(const PolygonSoup& soup, const std::vector<std::uint32_t>& source) {
  std::uint64_t h = 1469598103934665603ull;
  for (const Vec3& p : soup.points)
    for (int k = 0; k < 3; ++k) h = fnv(h, to_string(p[k]) + ",");
  for (std::uint32_t i : soup.face_indices) h = fnv(h, std::to_string(i) + ",");
  for (std::uint32_t i : soup.face_offsets) h = fnv(h, std::to_string(i) + ";");
  for (std::uint32_t i : source) h = fnv(h, std::to_string(i) + ":");
  return h;
}

// Portable draws: a 64-bit LCG, doubles in [-1, 1) from its top 53 bits.
struct Draw {
  std::uint64_t state;
  std::uint64_t next() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return state >> 11;
  }
  double unit() { return static_cast<double>(next()) * 0x1p-52 - 1.0; }
};

std::vector<Vec3> ball(std::uint64_t seed, int n, const Rational& scale) {
  Draw d{seed};
  std::vector<Vec3> pts;
  while (static_cast<int>(pts.size()) < n) {
    const double x = d.unit(), y = d.unit(), z = d.unit();
    if (x * x + y * y + z * z <= 1.0)
      pts.push_back({Rational(x) * scale, Rational(y) * scale, Rational(z) * scale});
  }
  return pts;
}

// Small integers (duplicates, coplanar and collinear points everywhere),
// divided by 3 and 7 when `thirds` (approximations inexact).
std::vector<Vec3> lattice(std::uint64_t seed, int n, bool thirds) {
  Draw d{seed};
  std::vector<Vec3> pts;
  for (int i = 0; i < n; ++i) {
    Vec3 p;
    for (int k = 0; k < 3; ++k) p[k] = Rational(static_cast<long>(d.next() % 5) - 2);
    if (thirds) p = {p.x / 3, p.y / 7 + Rational(1, 3), p.z};
    pts.push_back(p);
  }
  return pts;
}

std::vector<Vec3> cube_plus_sphere(int k) {
  const ConvexPolyhedron a = shapes::cube(), b = shapes::geodesic_sphere(k);
  std::vector<Vec3> pts;
  for (VertexId i : a.mesh().vertices())
    for (VertexId j : b.mesh().vertices()) pts.push_back(a.vertex(i) + b.vertex(j));
  return pts;
}

struct Case {
  const char* name;
  std::vector<Vec3> (*points)();
};

const Case cases[] = {
    {"ball 2000", [] { return ball(1, 2000, Rational(1)); }},
    {"ball 2000 x 1e-300", [] { return ball(2, 2000, parse_rational("1e-300")); }},
    {"ball 2000 x 1e300", [] { return ball(3, 2000, parse_rational("1e300")); }},
    {"ball 500 / 3", [] { return ball(4, 500, Rational(1, 3)); }},
    {"lattice", [] { return lattice(5, 3000, false); }},
    {"lattice thirds", [] { return lattice(6, 3000, true); }},
    {"cube + sphere3", [] { return cube_plus_sphere(3); }},
    {"sphere4 points", [] { return shapes::geodesic_sphere_points(4, true); }},
};
// END shared

constexpr std::uint64_t expected[] = {
    0x796613f88347fabaull,  // ball 2000
    0xbd72848fdb2cd83full,  // ball 2000 x 1e-300
    0xf727b68f66ab5e28ull,  // ball 2000 x 1e300
    0x89b7c7bb45ea196dull,  // ball 500 / 3
    0xf1efe35a7708328cull,  // lattice
    0xcd58e9e718d4b568ull,  // lattice thirds
    0xa4d54e9353258472ull,  // cube + sphere3
    0xb35986a2e1c5a90full,  // sphere4 points
};

TEST(QuickhullGolden, SameSoupAsBeforeTheFilters) {
  ASSERT_EQ(std::size(expected), std::size(cases));
  for (std::size_t i = 0; i < std::size(cases); ++i) {
    SCOPED_TRACE(cases[i].name);
    const std::vector<Vec3> pts = cases[i].points();
    std::vector<std::uint32_t> source;
    const PolygonSoup soup = hull_soup(pts, &source);
    EXPECT_EQ(digest(soup, source), expected[i]) << std::hex << digest(soup, source);
  }
}

// Doubles taken as they are give the same soup as their rationals.
TEST(QuickhullGolden, SameSoupFromDoubles) {
  std::vector<std::array<double, 3>> pts;
  for (const Vec3& p : cases[0].points())
    pts.push_back({to_double_nearest(p.x), to_double_nearest(p.y), to_double_nearest(p.z)});
  std::vector<std::uint32_t> source;
  const PolygonSoup soup = hull_soup(std::span<const std::array<double, 3>>(pts), &source);
  EXPECT_EQ(digest(soup, source), expected[0]);
}

}  // namespace
}  // namespace cvms
