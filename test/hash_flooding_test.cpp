// SPDX-License-Identifier: MIT
// Hash flooding: hash_value(Vec3) is made of invertible splitmix steps, so
// anyone can make points that all share one 64-bit hash. A duplicate-point
// check or an STL vertex merge by hashing goes quadratic on them (tens of
// seconds for a few MB of OFF or a valid 100,000-vertex paraboloid). The
// attack points are made here, at test time, by
// inverting the hash; each test first proves that they really collide, then
// that the work they cause is bounded (O(n log n): the merges do not hash).
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/convex_polyhedron.hpp"
#include "cvms/io.hpp"
#include "cvms/mesh.hpp"
#include "support/cpu_time.hpp"
#include "support/io_expect.hpp"

namespace cvms {
namespace {

using test::throws_error;

using test::slow_factor;

// ---- the hash of lib/numeric/vec.cpp, and its inverse ----------------------
// Replicated on purpose: an attacker reads the source too. Every test asserts
// through the public hash_value that the points collide, so a change of the
// hash shows up here as a failed precondition, never as a silently weak test.

constexpr std::uint64_t golden = 0x9e3779b97f4a7c15ULL;

std::uint64_t avalanche(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return x;
}

// x with x ^ (x >> s) == y.
std::uint64_t unxorshift(std::uint64_t y, int s) {
  std::uint64_t x = y;
  for (int i = 0; i < 64 / s + 1; ++i) x = y ^ (x >> s);
  return x;
}

// The inverse of an odd number modulo 2^64 (Newton's iteration).
std::uint64_t inverse_odd(std::uint64_t a) {
  std::uint64_t x = a;  // correct to 3 bits
  for (int i = 0; i < 6; ++i) x *= 2 - a * x;
  return x;
}

std::uint64_t unavalanche(std::uint64_t x) {
  x = unxorshift(x, 31);
  x *= inverse_odd(0x94d049bb133111ebULL);
  x = unxorshift(x, 27);
  x *= inverse_odd(0xbf58476d1ce4e5b9ULL);
  return unxorshift(x, 30);
}

std::uint64_t mix(std::uint64_t seed, std::uint64_t value) { return avalanche(seed * golden + avalanche(value)); }

// `value` with mix(seed, value) == target.
std::uint64_t unmix_value(std::uint64_t seed, std::uint64_t target) {
  return unavalanche(unavalanche(target) - seed * golden);
}
// `seed` with mix(seed, value) == target.
std::uint64_t unmix_seed(std::uint64_t value, std::uint64_t target) {
  return (unavalanche(target) - avalanche(value)) * inverse_odd(golden);
}

// The hash of a non-negative integer given by its limbs (low first).
std::uint64_t hash_limbs(const std::vector<std::uint64_t>& limbs) {
  std::uint64_t h = limbs.size();
  for (std::uint64_t limb : limbs) h = mix(h, limb);
  return h;
}

Rational from_limbs(const std::vector<std::uint64_t>& limbs) {
  mpz_class z;
  for (auto it = limbs.rbegin(); it != limbs.rend(); ++it) {
    z <<= 64;
    z += mpz_class(static_cast<unsigned long>(*it));
  }
  return Rational(z);
}

// Limbs of an integer of `size` limbs whose hash_mpz is `target`, with every
// limb above the lowest given by `high` (the lowest is solved for).
std::vector<std::uint64_t> limbs_with_hash(std::vector<std::uint64_t> high, std::uint64_t target) {
  std::uint64_t h = target;
  for (auto it = high.rbegin(); it != high.rend(); ++it) h = unmix_seed(*it, h);
  std::vector<std::uint64_t> limbs{unmix_value(high.size() + 1, h)};
  limbs.insert(limbs.end(), high.begin(), high.end());
  return limbs;
}

// The hash_mpz a rational's numerator needs for hash_value(Rational) == target
// with the given denominator hash.
std::uint64_t numerator_hash_for(std::uint64_t denominator_hash, std::uint64_t target) {
  return unmix_seed(denominator_hash, target);
}

// The hash z must have for hash_value(Vec3{x, y, z}) == target.
std::uint64_t z_hash_for(const Rational& x, const Rational& y, std::uint64_t target) {
  return unmix_value(mix(hash_value(x), hash_value(y)), target);
}

constexpr std::uint64_t target_hash = 0x5eed5eed5eed5eedULL;

// Point (x, y, z) with an integer z of two limbs (below 2^128) and the target hash.
Vec3 colliding_point(const Rational& x, const Rational& y) {
  const std::uint64_t one_hash = hash_limbs({1});
  const std::uint64_t numerator = numerator_hash_for(one_hash, z_hash_for(x, y, target_hash));
  for (std::uint64_t high = 1;; ++high) {
    std::vector<std::uint64_t> limbs = limbs_with_hash({high}, numerator);
    if (limbs.back() != 0) return Vec3{x, y, from_limbs(limbs)};
  }
}

double seconds_since(double start) {
  return test::cpu_seconds() - start;
}

TEST(HashFlooding, TheAttackPointsShareOneHash) {
  for (int i = 0; i < 100; ++i) {
    Rational y(-i, 3);
    y.canonicalize();
    Vec3 p = colliding_point(Rational(i), y);
    EXPECT_EQ(hash_value(p), target_hash) << i;
  }
}

// 200,000 distinct points with one hash, then a duplicate of the first: the
// old hash set compared each point with all before it (2*10^10 comparisons).
TEST(HashFlooding, DuplicatePointCheckOf200000PointsWithOneHashIsFast) {
  constexpr std::uint32_t n = 200000;
  PolygonSoup soup;
  for (std::uint32_t i = 0; i < n; ++i) soup.points.push_back(colliding_point(Rational(i), Rational(0)));
  for (std::uint32_t i = 0; i + 2 < n; i += 3) soup.add_face({i, i + 1, i + 2});
  soup.add_face({n - 2, n - 1, 0});  // the leftover points, referenced
  soup.points.push_back(soup.points[0]);
  soup.add_face({n, 1, 2});
  for (std::uint32_t i = 0; i < n; i += 997) ASSERT_EQ(hash_value(soup.points[i]), target_hash) << i;
  const auto start = test::cpu_seconds();
  EXPECT_TRUE(throws_error([&] { (void)Mesh::from_soup(soup); }, ErrorCategory::topology,
                           {"vertices 0 and 200000 are at the same point"}));
  EXPECT_LT(seconds_since(start), 2.0 * slow_factor);
}

// The pair reported is still the earliest second occurrence in index order,
// with the first occurrence of its position (the old hash set's answer).
TEST(HashFlooding, DuplicatePointReportIsTheFirstInIndexOrder) {
  PolygonSoup soup;
  auto p = [](int x) { return Vec3{Rational(x), Rational(0), Rational(0)}; };
  // 0:a 1:b 2:c 3:b 4:a 5:c -> "vertices 1 and 3".
  soup.points = {p(5), p(1), p(7), p(1), p(5), p(7)};
  soup.add_face({0, 1, 2});
  soup.add_face({3, 4, 5});
  EXPECT_TRUE(
      throws_error([&] { (void)Mesh::from_soup(soup); }, ErrorCategory::topology, {"vertices 1 and 3 are"}));
}

// An ASCII STL of 30,000 triangles whose 90,000 distinct vertices share one
// hash (about 7 MB): the old unordered_map merge was quadratic.
TEST(HashFlooding, AsciiStlWith90000CollidingVerticesIsMergedFast) {
  constexpr int triangles = 30000;
  std::string text = "solid flood\n";
  std::vector<Vec3> expected;
  for (int t = 0; t < triangles; ++t) {
    text += "facet normal 0 0 0\nouter loop\n";
    for (int k = 0; k < 3; ++k) {
      Vec3 v = colliding_point(Rational(t), Rational(k));
      text += "vertex " + to_string(v.x) + " " + to_string(v.y) + " " + to_string(v.z) + "\n";
      expected.push_back(std::move(v));
    }
    text += "endloop\nendfacet\n";
  }
  text += "endsolid flood\n";
  ASSERT_EQ(hash_value(expected[12345]), target_hash);
  std::istringstream in(text);
  const auto start = test::cpu_seconds();
  PolygonSoup soup = read_stl(in, "flood.stl");
  EXPECT_LT(seconds_since(start), 3.0 * slow_factor);
  ASSERT_EQ(soup.points.size(), expected.size());
  EXPECT_EQ(soup.points, expected);  // first-occurrence numbering
}

// The binary merge sorts the float bit patterns: 79,202 triangles (4 MB),
// each vertex shared by 6, numbered in order of first appearance.
TEST(HashFlooding, BinaryStlMergeIsSortedAndKeepsFirstOccurrenceOrder) {
  constexpr std::uint32_t side = 200;  // a side x side grid of vertices, 2 triangles per cell
  std::string data(80, ' ');
  std::uint32_t count = 2 * (side - 1) * (side - 1);
  auto put_u32 = [&data](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) data += static_cast<char>((v >> (8 * i)) & 0xff);
  };
  auto put_float = [&](float f) { put_u32(std::bit_cast<std::uint32_t>(f)); };
  put_u32(count);
  // Cells in a scrambled order, so first appearances are not sorted.
  std::vector<std::uint32_t> cells((side - 1) * (side - 1));
  for (std::uint32_t i = 0; i < cells.size(); ++i) cells[i] = static_cast<std::uint32_t>((i * 7919ull) % cells.size());
  std::vector<Vec3> positions;  // of each corner, in file order
  auto corner = [&](std::uint32_t i, std::uint32_t j) {
    put_float(static_cast<float>(i) * 0.5f);
    put_float(-static_cast<float>(j) * 0.25f);
    put_float(i == 0 && j == 0 ? -0.0f : 0.0f);
    positions.push_back(Vec3{Rational(i) / 2, -Rational(j) / 4, Rational(0)});
  };
  for (std::uint32_t cell : cells) {
    const std::uint32_t i = cell % (side - 1), j = cell / (side - 1);
    for (int half = 0; half < 2; ++half) {
      for (int c = 0; c < 3; ++c) put_float(0.0f);
      corner(i, j);
      corner(i + 1, j + half);
      corner(i + 1 - half, j + 1);
      data += std::string(2, '\0');
    }
  }
  ASSERT_EQ(data.size(), 84 + 50 * std::size_t{count});
  std::istringstream in(data);
  const auto start = test::cpu_seconds();
  PolygonSoup soup = read_stl(in, "grid.stl");
  EXPECT_LT(seconds_since(start), 3.0 * slow_factor);
  ASSERT_EQ(soup.points.size(), std::size_t{side} * side);
  ASSERT_EQ(soup.face_indices.size(), 3 * std::size_t{count});
  // Each corner's index holds its exact position, so (as the grid has
  // side^2 distinct positions) equal indices are exactly equal positions;
  // and a new index appears exactly in file order.
  std::uint32_t next = 0;
  for (std::size_t c = 0; c < soup.face_indices.size(); ++c) {
    const std::uint32_t index = soup.face_indices[c];
    ASSERT_EQ(soup.points[index], positions[c]) << c;
    ASSERT_LE(index, next);
    if (index == next) ++next;
  }
  EXPECT_EQ(next, soup.points.size());
}

// A valid convex polyhedron can collide too: integer (x, y) on a grid and
// z = x^2 + y^2 + d / 2^128 with a tiny d chosen for the collision (every
// point stays a vertex: the tangent plane at a grid point clears the others
// by at least 1). Checked by hashing, 100,000 such vertices take close to a
// minute; here 5,041, checked against the known counts.
TEST(HashFlooding, ValidParaboloidWithOneHashIsCheckedFast) {
  const std::uint64_t den_hash = hash_limbs({0, 0, 1});
  const Rational den = from_limbs({0, 0, 1});
  std::vector<Vec3> points;
  constexpr int r = 35;
  for (int x = -r; x <= r; ++x)
    for (int y = -r; y <= r; ++y) {
      if (x == 0 && y == 0) continue;  // x^2 + y^2 must fill the top limb
      const Rational rx(x), ry(y);
      const std::uint64_t numerator = numerator_hash_for(den_hash, z_hash_for(rx, ry, target_hash));
      const auto lift = static_cast<std::uint64_t>(x * x + y * y);
      for (std::uint64_t middle = 0;; ++middle) {
        std::vector<std::uint64_t> limbs = limbs_with_hash({middle, lift}, numerator);
        if (limbs.front() % 2 == 0) continue;  // z must be in lowest terms over 2^128
        points.push_back(Vec3{rx, ry, from_limbs(limbs) / den});
        break;
      }
    }
  for (std::size_t i = 0; i < points.size(); i += 101) ASSERT_EQ(hash_value(points[i]), target_hash) << i;
  ConvexPolyhedron hull = convex_hull(points);
  ASSERT_EQ(hull.num_vertices(), points.size());
  std::ostringstream off;
  write_off(off, hull.to_soup());
  std::istringstream in(off.str());
  const auto start = test::cpu_seconds();
  ConvexPolyhedron checked = to_polyhedron(read_off(in, "paraboloid.off"), "paraboloid.off");
  EXPECT_LT(seconds_since(start), 3.0 * slow_factor);
  EXPECT_EQ(checked.num_vertices(), points.size());
  EXPECT_EQ(checked.num_facets(), hull.num_facets());
}

}  // namespace
}  // namespace cvms
