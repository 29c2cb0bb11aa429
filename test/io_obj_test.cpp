// SPDX-License-Identifier: MIT
// OBJ reader: face-vertex forms, relative and forward indices, ignored
// statements, against hand-written soups; the bad corpus (test/data/bad/*.obj)
// one test per file.
#include <gtest/gtest.h>

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

PolygonSoup obj_from(const std::string& text, const ReadLimits& limits = {}) {
  std::istringstream in(text);
  return read_obj(in, "text.obj", limits);
}

TEST(ReadObj, CubeWithAllFaceVertexFormsAndIgnoredStatements) {
  PolygonSoup soup = read_file(data_path("cube.obj"));
  EXPECT_EQ(soup.points, (std::vector<Vec3>{v3(0, 0, 0), v3(1, 0, 0), v3(1, 1, 0), v3(0, 1, 0), v3(0, 0, 1),
                                            v3(1, 0, 1), v3(1, 1, 1), v3(0, 1, 1)}));
  EXPECT_EQ(faces_of(soup),
            (Faces{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}));
}

TEST(ReadObj, RelativeIndices) {
  PolygonSoup soup = read_file(data_path("tetra_relative.obj"));
  EXPECT_EQ(soup.points, (std::vector<Vec3>{v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 1)}));
  EXPECT_EQ(faces_of(soup), (Faces{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}));
}

TEST(ReadObj, ForwardReferencesAreResolvedAtTheEnd) {
  PolygonSoup soup = obj_from("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  EXPECT_EQ(faces_of(soup), (Faces{{0, 1, 2}}));
}

TEST(ReadObj, ExactCoordinatesAndCommentsEverywhere) {
  PolygonSoup soup =
      obj_from("v 0.1 1/3 -2e-3 # a comment\n  v\t1e400 0 0\n#\nf 1 2 2 # degenerate is not our job\n");
  mpz_class ten400;
  mpz_ui_pow_ui(ten400.get_mpz_t(), 10, 400);
  EXPECT_EQ(soup.points[0], v3(Rational(1, 10), Rational(1, 3), Rational(-1, 500)));
  EXPECT_EQ(soup.points[1], v3(Rational(ten400), 0, 0));
  EXPECT_EQ(faces_of(soup), (Faces{{0, 1, 1}}));
}

TEST(ReadObj, VertexLimit) {
  EXPECT_TRUE(throws_error([] { obj_from("v 0 0 0\nv 1 0 0\nv 0 1 0\n", ReadLimits{.max_vertices = 2}); },
                           ErrorCategory::limit, {"text.obj:3:", "limit of 2"}));
  EXPECT_TRUE(throws_error(
      [] { obj_from("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n", ReadLimits{.max_faces = 1}); },
      ErrorCategory::limit, {"text.obj:5:", "2 faces"}));
}

TEST(ReadObj, FaceTokenSyntax) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(faces_of(obj_from(v + "f 1/1/1 2//2 -1/3\n")), (Faces{{0, 1, 2}}));
  for (const char* token : {"1/", "1//", "/1", "1/a", "a", "1/1/1/1", "+", "0"})
    EXPECT_TRUE(throws_error([&] { obj_from(v + "f 1 2 " + token + "\n"); }, ErrorCategory::parse,
                             {"text.obj:4:", "face 1"}))
        << token;
}

// Huge indices are shown as typed, not saturated to +-9223372036854775807.
TEST(ReadObj, HugeIndicesAreShownAsTyped) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_TRUE(
      throws_error([&] { obj_from(v + "f 1 2 99999999999999999999999/4\n"); }, ErrorCategory::parse,
                   {"text.obj:4: face 1 has index 99999999999999999999999, beyond the 32-bit range"}));
  EXPECT_TRUE(throws_error([&] { obj_from(v + "f -99999999999999999999999 1 2\n"); }, ErrorCategory::parse,
                           {"face 1 has relative index -99999999999999999999999 but only 3"}));
}

// "v -1.#IND 0 1.#QNAN" is named as not finite, not "missing y coordinate"
// (a '#' inside a token does not start a comment).
TEST(ReadObj, MsvcNonFiniteSpellingsAreNamed) {
  EXPECT_TRUE(throws_error([] { obj_from("v -1.#IND 0 1.#QNAN\n"); }, ErrorCategory::parse,
                           {"text.obj:1:", "x coordinate of vertex 1 is not finite: '-1.#IND'"}));
  EXPECT_TRUE(throws_error([] { obj_from("v 0 0 1.#QNAN\n"); }, ErrorCategory::parse,
                           {"z coordinate of vertex 1 is not finite: '1.#QNAN'"}));
  EXPECT_TRUE(throws_error([] { obj_from("v 0 0 0 1 1 1.#inf00\n"); }, ErrorCategory::parse,
                           {"color value of vertex 1 is not finite: '1.#inf00'"}));
  // A comment right after a number is still a comment.
  EXPECT_EQ(obj_from("v 0 0 1.#comment\n").points, (std::vector<Vec3>{v3(0, 0, 1)}));
}

// ---- the bad corpus: one test per file --------------------------------------

::testing::AssertionResult bad(std::string_view name, ErrorCategory category,
                               std::initializer_list<std::string_view> needles) {
  std::string file = "bad/" + std::string(name);
  auto result = throws_error([&] { read_file(data_path(file)); }, category, needles);
  if (!result) return result;
  return throws_error([&] { read_file(data_path(file)); }, category, {name});
}

TEST(ReadObjBad, EmptyFile) { EXPECT_TRUE(bad("empty.obj", ErrorCategory::parse, {"empty input"})); }
TEST(ReadObjBad, IndexZero) {
  EXPECT_TRUE(bad("index_zero.obj", ErrorCategory::parse, {"index_zero.obj:4:", "face 1", "'0'"}));
}
TEST(ReadObjBad, IndexOutOfRange) {
  EXPECT_TRUE(bad("index_out_of_range.obj", ErrorCategory::parse,
                  {"index_out_of_range.obj:6: face 2 has index 9 but there are 4 vertices"}));
}
TEST(ReadObjBad, RelativeIndexOutOfRange) {
  EXPECT_TRUE(bad("relative_out_of_range.obj", ErrorCategory::parse,
                  {"relative_out_of_range.obj:4:", "relative index -5", "only 3 vertices"}));
}
TEST(ReadObjBad, NanCoordinate) {
  EXPECT_TRUE(bad("nan.obj", ErrorCategory::parse, {"nan.obj:2:", "y coordinate of vertex 2", "'NaN'"}));
}
TEST(ReadObjBad, WeightOtherThanOne) {
  EXPECT_TRUE(bad("w_not_one.obj", ErrorCategory::parse, {"w_not_one.obj:2:", "w = '2'"}));
}
TEST(ReadObjBad, UnknownStatement) {
  EXPECT_TRUE(bad("unknown_statement.obj", ErrorCategory::parse, {"unknown_statement.obj:2:", "'vertex'"}));
}
TEST(ReadObjBad, MalformedFaceToken) {
  EXPECT_TRUE(bad("bad_face_token.obj", ErrorCategory::parse, {"bad_face_token.obj:4:", "'1/2/3/4'"}));
}
TEST(ReadObjBad, FreeFormGeometry) {
  EXPECT_TRUE(bad("free_form.obj", ErrorCategory::parse, {"free_form.obj:4:", "free-form", "'cstype'"}));
}
TEST(ReadObjBad, FaceWithTwoVertices) {
  EXPECT_TRUE(
      bad("two_vertex_face.obj", ErrorCategory::parse, {"two_vertex_face.obj:4:", "face 1 has 2 vertices"}));
}
TEST(ReadObjBad, NoVertices) {
  EXPECT_TRUE(bad("no_vertices.obj", ErrorCategory::parse, {"no_vertices.obj:3:", "no vertices"}));
}
TEST(ReadObjBad, VertexWithFiveValues) {
  EXPECT_TRUE(bad("five_values.obj", ErrorCategory::parse, {"five_values.obj:2:", "vertex 2 has 5 values"}));
}
TEST(ReadObjBad, BinaryJunk) {
  EXPECT_TRUE(bad("binary_junk.obj", ErrorCategory::parse, {"binary_junk.obj:1:", "a NUL byte at byte 157", "binary data"}));
}

}  // namespace
}  // namespace cvms
