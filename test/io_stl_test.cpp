// SPDX-License-Identifier: MIT
// STL reader: ASCII and binary detection (including binary files whose
// header starts with "solid"), exact float32 coordinates, vertex merging by
// exact position; the bad corpus (test/data/bad/*.stl) one test per file.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <sstream>

#include "cvms/io.hpp"
#include "support/io_expect.hpp"

namespace cvms {
namespace {

using test::data_path;
using test::faces_of;
using test::throws_error;
using test::v3;
using Faces = std::vector<std::vector<std::uint32_t>>;

Rational pow2(int e) {
  mpz_class p;
  mpz_ui_pow_ui(p.get_mpz_t(), 2, static_cast<unsigned long>(e < 0 ? -e : e));
  return e < 0 ? Rational(mpz_class(1), p) : Rational(p);
}

// Binary STL bytes built field by field (independent of the writer).
std::string binary_stl(std::uint32_t declared, const std::vector<std::array<float, 9>>& triangles) {
  std::string out(80, ' ');
  auto u32 = [&out](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
  };
  u32(declared);
  for (const auto& t : triangles) {
    for (int i = 0; i < 3; ++i) u32(0);
    for (float c : t) u32(std::bit_cast<std::uint32_t>(c));
    out.append(2, '\0');
  }
  return out;
}

PolygonSoup stl_from(const std::string& bytes, const ReadLimits& limits = {}) {
  std::istringstream in(bytes);
  return read_stl(in, "mem.stl", limits);
}

TEST(ReadStl, AsciiMixedCaseSeveralSolidsMergedVertices) {
  PolygonSoup soup = read_file(data_path("tetra_ascii.stl"));
  EXPECT_EQ(soup.points, (std::vector<Vec3>{v3(0, 0, 0), v3(0, 1, 0), v3(1, 0, 0), v3(0, 0, 1)}));
  EXPECT_EQ(faces_of(soup), (Faces{{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {2, 1, 3}}));
}

// A strip of 4,998 triangles over 5,000 distinct points, each point shared
// by up to three triangles: points come back once each, in order of first
// appearance, however many blocks the reader's buffer needs for them (the
// reader merges vertices by the addresses of the points it keeps).
TEST(ReadStl, AsciiStripOfManyDistinctVerticesMergesEachOnce) {
  constexpr int n = 5000;
  auto point = [](int i) { return v3(i, (i * i) % 97, i % 3); };
  std::string text = "solid strip\n";
  for (int i = 0; i + 2 < n; ++i) {
    text += "facet normal 0 0 0\nouter loop\n";
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = point(i + k);
      text += "vertex " + to_string(p.x) + " " + to_string(p.y) + " " + to_string(p.z) + "\n";
    }
    text += "endloop\nendfacet\n";
  }
  text += "endsolid strip\n";
  const PolygonSoup soup = stl_from(text);
  ASSERT_EQ(soup.points.size(), static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) ASSERT_EQ(soup.points[static_cast<std::size_t>(i)], point(i)) << i;
  ASSERT_EQ(soup.num_faces(), static_cast<std::size_t>(n - 2));
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto face = soup.face(f);
    ASSERT_EQ(std::vector<std::uint32_t>(face.begin(), face.end()),
              (std::vector<std::uint32_t>{static_cast<std::uint32_t>(f), static_cast<std::uint32_t>(f + 1),
                                          static_cast<std::uint32_t>(f + 2)}))
        << f;
  }
}

TEST(ReadStl, BinaryWithSolidHeaderIsDetectedBySize) {
  PolygonSoup soup = read_file(data_path("tetra_binary_solid_header.stl"));
  // 0.1f = 13421773 * 2^-27, the smallest subnormal 2^-149, FLT_MAX = (2^24 - 1) * 2^104;
  // -0.0 and 0.0 are one position.
  const Rational tenth = Rational(13421773) * pow2(-27);
  EXPECT_EQ(soup.points, (std::vector<Vec3>{v3(tenth, 0, 0), v3(pow2(-149), Rational(3, 2), 0), v3(1, 0, 0),
                                            v3(0, 0, Rational(16777215) * pow2(104))}));
  EXPECT_EQ(faces_of(soup), (Faces{{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {2, 1, 3}}));
}

TEST(ReadStl, BinaryFloatsAreExact) {
  const float a = 1.0f / 3.0f;
  const float b = -1234.5678f;
  PolygonSoup soup = stl_from(binary_stl(1, {{a, b, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f}}));
  ASSERT_EQ(soup.points.size(), 3u);
  // 1/3 as float is 11184811 * 2^-25; -1234.5678f is -10113579 * 2^-13.
  EXPECT_EQ(soup.points[0], v3(Rational(11184811) * pow2(-25), Rational(-10113579) * pow2(-13), 0));
  EXPECT_EQ(soup.points[0].x, rational_from_float(a));
}

TEST(ReadStl, EmptyBinaryAndEmptyAsciiSolids) {
  EXPECT_EQ(stl_from(binary_stl(0, {})).num_faces(), 0u);
  EXPECT_EQ(stl_from("solid empty\nendsolid empty\n").num_faces(), 0u);
}

TEST(ReadStl, Limits) {
  const auto bytes = binary_stl(2, {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 0, 1, 0, 0, 0, 1}});
  EXPECT_TRUE(throws_error([&] { stl_from(bytes, ReadLimits{.max_faces = 1}); }, ErrorCategory::limit,
                           {"mem.stl: byte 80:", "2 triangles"}));
  EXPECT_TRUE(throws_error([&] { stl_from(bytes, ReadLimits{.max_vertices = 3}); }, ErrorCategory::limit,
                           {"mem.stl: byte 170:", "more than 3 distinct vertices"}));
  EXPECT_TRUE(throws_error([&] { stl_from(bytes, ReadLimits{.max_bytes = 100}); }, ErrorCategory::limit,
                           {"mem.stl", "100 bytes"}));
}

std::string ascii_facet(const std::string& normal, const std::string& vertex) {
  return "solid t\nfacet normal " + normal + "\nouter loop\nvertex " + vertex +
         "\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
}

// Normals follow the number rules (no private exponent cap: "1e500" is a
// number), NaN allowed.
TEST(ReadStl, NormalsFollowTheNumberRules) {
  EXPECT_EQ(stl_from(ascii_facet("1e500 0 -1e-500", "0 0 0")).num_faces(), 1u);
  EXPECT_EQ(stl_from(ascii_facet("nan -1.#IND 1.#QNAN", "0 0 0")).num_faces(), 1u);
  EXPECT_TRUE(
      throws_error([] { stl_from(ascii_facet("0 1e99999 0", "0 0 0")); }, ErrorCategory::limit,
                   {"mem.stl:2:", "normal component of facet 0 '1e99999'", "ReadLimits::max_number_bits"}));
  EXPECT_TRUE(throws_error([] { stl_from(ascii_facet("0 up 0", "0 0 0")); }, ErrorCategory::parse,
                           {"mem.stl:2:", "normal component of facet 0 is not a number: 'up'"}));
}

// Every MSVC spelling of a non-finite value is refused as a coordinate.
TEST(ReadStl, MsvcNonFiniteCoordinatesAreRefused) {
  for (const char* token : {"1.#INF", "-1.#INF", "1.#IND", "-1.#IND00", "1.#QNAN", "1.#qnan0", "+1.#Inf"})
    EXPECT_TRUE(throws_error([&] { stl_from(ascii_facet("0 0 1", std::string("0 0 ") + token)); },
                             ErrorCategory::parse,
                             {"mem.stl:4:", "z coordinate of vertex 0 of facet 0 is not finite"}))
        << token;
}

// ---- the bad corpus: one test per file --------------------------------------

::testing::AssertionResult bad(std::string_view name, ErrorCategory category,
                               std::initializer_list<std::string_view> needles) {
  std::string file = "bad/" + std::string(name);
  auto result = throws_error([&] { read_file(data_path(file)); }, category, needles);
  if (!result) return result;
  return throws_error([&] { read_file(data_path(file)); }, category, {name});
}

TEST(ReadStlBad, EmptyFile) { EXPECT_TRUE(bad("empty.stl", ErrorCategory::parse, {"empty input"})); }
TEST(ReadStlBad, BinaryCountLargerThanTheData) {
  EXPECT_TRUE(bad("binary_count_mismatch.stl", ErrorCategory::parse,
                  {"binary_count_mismatch.stl: byte 184:", "declares 10 triangles", "has 184",
                   "truncated in triangle 2"}));
}
TEST(ReadStlBad, BinaryCountSmallerThanTheData) {
  EXPECT_TRUE(
      bad("binary_trailing_bytes.stl", ErrorCategory::parse,
          {"binary_trailing_bytes.stl: byte 134:", "declares 1 triangles", "50 bytes after the last"}));
}
TEST(ReadStlBad, BinaryLyingCount) {
  EXPECT_TRUE(bad("binary_lying_count.stl", ErrorCategory::parse,
                  {"binary_lying_count.stl: byte 134:", "declares 4294967295 triangles"}));
}
TEST(ReadStlBad, BinaryNan) {
  // Triangle 1 starts at byte 134, its vertex 1 at 134 + 12 + 12, whose y at +4.
  EXPECT_TRUE(bad("binary_nan.stl", ErrorCategory::parse,
                  {"binary_nan.stl: byte 162:", "triangle 1 vertex 1", "nan"}));
}
TEST(ReadStlBad, BinaryInf) {
  EXPECT_TRUE(bad("binary_inf.stl", ErrorCategory::parse,
                  {"binary_inf.stl: byte 96:", "triangle 0 vertex 0", "inf"}));
}
TEST(ReadStlBad, TooShortForBinary) {
  EXPECT_TRUE(bad("short_binary.stl", ErrorCategory::parse, {"short_binary.stl: byte 0:", "40 bytes"}));
}
TEST(ReadStlBad, SolidHeaderButBinaryWithWrongCount) {
  EXPECT_TRUE(bad("solid_header_count_mismatch.stl", ErrorCategory::parse,
                  {"solid_header_count_mismatch.stl:", "not binary either", "declares 7 triangles"}));
}
TEST(ReadStlBad, AsciiTruncated) {
  EXPECT_TRUE(bad("ascii_truncated.stl", ErrorCategory::parse,
                  {"ascii_truncated.stl:5:", "end of input", "expected 'vertex'"}));
}
TEST(ReadStlBad, AsciiMisspelledKeyword) {
  EXPECT_TRUE(bad("ascii_bad_keyword.stl", ErrorCategory::parse,
                  {"ascii_bad_keyword.stl:3:", "expected 'loop'", "'lop'"}));
}
TEST(ReadStlBad, AsciiInfinity) {
  EXPECT_TRUE(bad("ascii_inf.stl", ErrorCategory::parse,
                  {"ascii_inf.stl:6:", "z coordinate of vertex 2 of facet 0", "'-Infinity'"}));
}
TEST(ReadStlBad, AsciiFourVertices) {
  EXPECT_TRUE(bad("ascii_four_vertices.stl", ErrorCategory::parse,
                  {"ascii_four_vertices.stl:7:", "expected 'endloop'", "'vertex'"}));
}
TEST(ReadStlBad, AsciiTrailingGarbage) {
  EXPECT_TRUE(bad("ascii_trailing_garbage.stl", ErrorCategory::parse,
                  {"ascii_trailing_garbage.stl:10:", "'garbage' after 'endsolid'"}));
}
TEST(ReadStlBad, BinaryJunk) {
  EXPECT_TRUE(bad("binary_junk.stl", ErrorCategory::parse, {"binary_junk.stl: byte ", "declares"}));
}

}  // namespace
}  // namespace cvms
