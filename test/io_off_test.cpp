// SPDX-License-Identifier: MIT
// OFF reader: every accepted syntax variant against hand-written expected
// soups, and every file of the bad corpus (test/data/bad/*.off) for its
// error category, file name and line.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
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

PolygonSoup off_from(const std::string& text, const ReadLimits& limits = {}) {
  std::istringstream in(text);
  return read_off(in, "text.off", limits);
}

// A stream buffer that hands out one byte at a time and cannot seek, like a
// pipe: every line crosses a read boundary.
class TrickleBuffer : public std::streambuf {
 public:
  explicit TrickleBuffer(std::string data) : data_(std::move(data)) {}

 protected:
  int_type underflow() override {
    if (pos_ >= data_.size()) return traits_type::eof();
    current_ = data_[pos_++];
    setg(&current_, &current_, &current_ + 1);
    return traits_type::to_int_type(current_);
  }

 private:
  std::string data_;
  std::size_t pos_ = 0;
  char current_ = 0;
};

const Faces cube_faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
const std::vector<Vec3> cube_points = {v3(0, 0, 0), v3(1, 0, 0), v3(1, 1, 0), v3(0, 1, 0),
                                       v3(0, 0, 1), v3(1, 0, 1), v3(1, 1, 1), v3(0, 1, 1)};
const Faces tetra_faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
const std::vector<Vec3> tetra_points = {v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 1)};

TEST(ReadOff, CubeWithCommentsAndBlankLines) {
  PolygonSoup soup = read_file(data_path("cube.off"));
  EXPECT_EQ(soup.points, cube_points);
  EXPECT_EQ(faces_of(soup), cube_faces);
}

TEST(ReadOff, CountsOnHeaderLineCrlfNoFinalNewline) {
  PolygonSoup soup = read_file(data_path("tetra_crlf.off"));
  EXPECT_EQ(soup.points, tetra_points);
  EXPECT_EQ(faces_of(soup), tetra_faces);
}

TEST(ReadOff, CoffColorsOnVerticesAndFacesAreIgnored) {
  PolygonSoup soup = read_file(data_path("tetra_colors.off"));
  EXPECT_EQ(soup.points, tetra_points);
  EXPECT_EQ(faces_of(soup), tetra_faces);
}

TEST(ReadOff, CoordinatesAreExact) {
  PolygonSoup soup = read_file(data_path("tetra_exact.off"));
  ASSERT_EQ(soup.points.size(), 4u);
  mpz_class ten400, ten300;
  mpz_ui_pow_ui(ten400.get_mpz_t(), 10, 400);
  mpz_ui_pow_ui(ten300.get_mpz_t(), 10, 300);
  EXPECT_EQ(soup.points[0], v3(Rational(ten400), Rational(1, 10), Rational(-25000000)));
  EXPECT_EQ(soup.points[1], v3(Rational(1, 3), Rational(-7, 2), Rational(1, 2)));
  EXPECT_EQ(soup.points[2], v3(Rational(5), Rational(2), Rational(mpz_class(1), ten300)));
  EXPECT_EQ(soup.points[3], v3(0, 0, 0));
}

TEST(ReadOff, HeaderVariantsWithTheirExtraValues) {
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  // NOFF: normals (3 values); STOFF: texture (2); CNOFF: color (3 or 4) + normal.
  EXPECT_EQ(off_from("NOFF\n4 4 0\n0 0 0 1 1 1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n" + faces).points,
            tetra_points);
  EXPECT_EQ(off_from("STOFF\n4 4 0\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n0 0 1 1 1\n" + faces).points,
            tetra_points);
  EXPECT_EQ(
      off_from(
          "CNOFF\n4 4 0\n0 0 0 1 1 1 9 9 9\n1 0 0 1 0 0 9 9 9 9\n0 1 0 0 1 0 9 9 9\n0 0 1 0 0 1 9 9 9\n" +
          faces)
          .points,
      tetra_points);
  // Counts without E, a comment right after the keyword, counts after the keyword.
  EXPECT_EQ(faces_of(off_from("OFF # comment\n4 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces)), tetra_faces);
  EXPECT_EQ(faces_of(off_from("OFF 4 4 6 # counts here\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces)), tetra_faces);
}

TEST(ReadOff, PolygonalFacesAndZeroCounts) {
  PolygonSoup soup = off_from("OFF\n5 1 0\n0 0 0\n1 0 0\n2 1 0\n1 2 0\n0 1 0\n5 0 1 2 3 4\n");
  EXPECT_EQ(faces_of(soup), (Faces{{0, 1, 2, 3, 4}}));
  PolygonSoup empty = off_from("OFF\n0 0 0\n");
  EXPECT_TRUE(empty.points.empty());
  EXPECT_EQ(empty.num_faces(), 0u);
}

TEST(ReadOff, NonSeekableStreamDeliveringOneByteAtATime) {
  std::ifstream file(data_path("cube.off"), std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  TrickleBuffer buffer(text);
  std::istream in(&buffer);
  PolygonSoup soup = read_off(in, "<stdin>");
  EXPECT_EQ(soup.points, cube_points);
  EXPECT_EQ(faces_of(soup), cube_faces);
}

TEST(ReadOff, LimitsOnCountsAndNumberLength) {
  const std::string tetra = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  EXPECT_TRUE(throws_error([&] { off_from(tetra, ReadLimits{.max_vertices = 3}); }, ErrorCategory::limit,
                           {"text.off:2:", "4 vertices", "limit of 3"}));
  EXPECT_TRUE(throws_error([&] { off_from(tetra, ReadLimits{.max_faces = 3}); }, ErrorCategory::limit,
                           {"text.off:2:", "4 faces"}));
  EXPECT_TRUE(throws_error([&] { off_from(tetra, ReadLimits{.max_bytes = 20}); }, ErrorCategory::limit,
                           {"text.off", "20 bytes"}));
  EXPECT_TRUE(
      throws_error([&] { off_from("OFF\n1 0 0\n12345678901 0 0\n", ReadLimits{.max_number_chars = 10}); },
                   ErrorCategory::limit, {"text.off:3:", "11 characters"}));
  EXPECT_NO_THROW(off_from("OFF\n1 0 0\n1234567890 0 0\n", ReadLimits{.max_number_chars = 10}));
}

TEST(ReadOff, ExponentAtTheCapIsExactBeyondIsALimit) {
  // The exponent cap alone: the bit caps (which refuse 1e100000 by default) raised.
  const ReadLimits wide{.max_number_bits = 1u << 20, .max_number_bits_per_byte = 1u << 20};
  PolygonSoup soup = off_from("OFF\n1 0 0\n1e100000 -1e-100000 0\n", wide);
  mpz_class big;
  mpz_ui_pow_ui(big.get_mpz_t(), 10, 100000);
  EXPECT_EQ(soup.points[0], v3(Rational(big), Rational(mpz_class(-1), big), 0));
  EXPECT_TRUE(throws_error([&] { off_from("OFF\n1 0 0\n0 1e100001 0\n", wide); }, ErrorCategory::limit,
                           {"text.off:3:", "y coordinate of vertex 0", "exponent"}));
  EXPECT_TRUE(throws_error([] { off_from("OFF\n1 0 0\n0 1e100001 0\n"); }, ErrorCategory::limit,
                           {"text.off:3:", "y coordinate of vertex 0", "exponent"}));
}

// Colors and COFF/NOFF vertex values follow the number rules (ReadLimits,
// max_number_chars), with no private exponent cap ("1e11" is a number).
TEST(ReadOff, ColorsAndNormalsFollowTheNumberRules) {
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const std::string points = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  EXPECT_EQ(off_from("OFF\n4 4 0\n" + points + "3 0 2 1 1e11 0.5 0 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n").points,
            tetra_points);
  EXPECT_TRUE(
      throws_error([&] { off_from("OFF\n4 4 0\n" + points + "3 0 2 1 1e99999\n"); }, ErrorCategory::limit,
                   {"text.off:7:", "color value of face 0 '1e99999'", "ReadLimits::max_number_bits"}));
  EXPECT_TRUE(throws_error(
      [&] {
        off_from("OFF\n4 4 0\n" + points + "3 0 2 1 " + std::string(2000, '7') + "\n",
                 {.max_number_chars = 1000});
      },
      ErrorCategory::limit,
      {"text.off:7:", "color value of face 0 has 2000 characters", "max_number_chars"}));
  EXPECT_TRUE(throws_error([&] { off_from("OFF\n4 4 0\n" + points + "3 0 2 1 red\n"); }, ErrorCategory::parse,
                           {"text.off:7:", "color value of face 0 is not a number: 'red'"}));
  EXPECT_TRUE(throws_error(
      [&] { off_from("COFF\n4 4 0\n0 0 0 1 1 abc\n1 0 0 1 1 1\n0 1 0 1 1 1\n0 0 1 1 1 1\n" + faces); },
      ErrorCategory::parse, {"text.off:3:", "color value of vertex 0 is not a number: 'abc'"}));
  EXPECT_TRUE(throws_error(
      [&] { off_from("NOFF\n4 4 0\n0 0 0 1 1 1\n1 0 0 nan 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n" + faces); },
      ErrorCategory::parse, {"text.off:4:", "normal component of vertex 1 is not finite: 'nan'"}));
  EXPECT_TRUE(
      throws_error([&] { off_from("CNOFF\n4 4 0\n0 0 0 1 1 1 9 9 1e-99999\n" + points.substr(6) + faces); },
                   ErrorCategory::limit, {"text.off:3:", "of vertex 0 '1e-99999'", "denominator"}));
}

// Huge indices are shown as typed, not saturated to 18446744073709551615.
TEST(ReadOff, HugeIndicesAreShownAsTyped) {
  const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_TRUE(throws_error([&] { off_from(head + "3 0 1 123456789012345678901234567890\n"); },
                           ErrorCategory::parse,
                           {"text.off:6: face 0 has index 123456789012345678901234567890 but there are 3"}));
  EXPECT_TRUE(throws_error([&] { off_from(head + "99999999999999999999999 0 1 2\n"); }, ErrorCategory::parse,
                           {"face 0 declares 99999999999999999999999 vertices but lists 3"}));
}

// Face indices in every spelling next to the one-pass reading of plain
// digits: separators (tab, carriage return, a comment right after the
// digits), leading zeros, 19 and 20 digits, and what the general route
// reads or refuses (a sign, a letter, a '#' inside the token). The
// expected indices and messages are written out by hand.
TEST(ReadOff, FaceIndexSpellings) {
  const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  const struct {
    const char* face;
    std::vector<std::uint32_t> indices;  // empty: refused with `message`
    const char* message;
  } cases[] = {
      {"3 0 1 2", {0, 1, 2}, nullptr},
      {"3\t2\t0\t1\t", {2, 0, 1}, nullptr},
      {"3 0 1 2\r", {0, 1, 2}, nullptr},
      {"3 0 1 2#comment", {0, 1, 2}, nullptr},
      {"3 0 1 2 # comment", {0, 1, 2}, nullptr},
      {"3 0000000000000000002 0 1", {2, 0, 1}, nullptr},   // 19 digits
      {"3 00000000000000000001 2 0", {1, 2, 0}, nullptr},  // 20 digits
      {"3 0 1 2 0.5 0.5 0.5", {0, 1, 2}, nullptr},         // a color
      {"3 0 1 +2", {}, "text.off:6: face 0: index '+2' is not a non-negative integer"},
      {"3 0 1 2x", {}, "text.off:6: face 0: index '2x' is not a non-negative integer"},
      {"3 0 1 -1", {}, "text.off:6: face 0: index '-1' is not a non-negative integer"},
      {"3 0 1 1.#INF", {}, "text.off:6: face 0: index '1.#INF' is not a non-negative integer"},
      {"3 0 1 3", {}, "text.off:6: face 0 has index 3 but there are 3 vertices"},
      {"3 0 1 0000000000000000003", {}, "text.off:6: face 0 has index 0000000000000000003 but there are 3"},
      {"3 0 1 9999999999999999999", {}, "text.off:6: face 0 has index 9999999999999999999 but there are 3"},
      {"3 0 1", {}, "text.off:6: face 0 declares 3 vertices but lists 2"},
      {"3 0 1 #2", {}, "text.off:6: face 0 declares 3 vertices but lists 2"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.face);
    const std::string text = head + c.face + "\n";
    if (c.message == nullptr) {
      EXPECT_EQ(faces_of(off_from(text)), Faces{c.indices});
    } else {
      EXPECT_TRUE(throws_error([&] { off_from(text); }, ErrorCategory::parse, {c.message}));
    }
  }
}

// ---- the bad corpus: one test per file --------------------------------------

::testing::AssertionResult bad(std::string_view name, ErrorCategory category,
                               std::initializer_list<std::string_view> needles) {
  std::string file = "bad/" + std::string(name);
  auto result = throws_error([&] { read_file(data_path(file)); }, category, needles);
  if (!result) return result;
  return throws_error([&] { read_file(data_path(file)); }, category, {name});
}

TEST(ReadOffBad, EmptyFile) { EXPECT_TRUE(bad("empty.off", ErrorCategory::parse, {"empty input"})); }
TEST(ReadOffBad, OnlyComments) {
  EXPECT_TRUE(bad("comments_only.off", ErrorCategory::parse, {"comments_only.off:3:", "'OFF' header"}));
}
TEST(ReadOffBad, MissingHeader) {
  EXPECT_TRUE(bad("no_header.off", ErrorCategory::parse,
                  {"no_header.off:1:", "expected an 'OFF' header, found '8'"}));
}
TEST(ReadOffBad, TruncatedVertices) {
  EXPECT_TRUE(bad("truncated_vertices.off", ErrorCategory::parse,
                  {"truncated_vertices.off:7:", "end of input", "8 vertices but only 5"}));
}
TEST(ReadOffBad, TruncatedFaces) {
  EXPECT_TRUE(
      bad("truncated_faces.off", ErrorCategory::parse, {"truncated_faces.off:8:", "4 faces but only 2"}));
}
TEST(ReadOffBad, IndexOutOfRange) {
  EXPECT_TRUE(bad("index_out_of_range.off", ErrorCategory::parse,
                  {"index_out_of_range.off:14: face 3 has index 12 but there are 8 vertices"}));
}
TEST(ReadOffBad, NanCoordinate) {
  EXPECT_TRUE(bad("nan.off", ErrorCategory::parse,
                  {"nan.off:4:", "x coordinate of vertex 1", "not finite", "'nan'"}));
}
TEST(ReadOffBad, InfCoordinate) {
  EXPECT_TRUE(bad("inf.off", ErrorCategory::parse, {"inf.off:5:", "y coordinate of vertex 2", "'-inf'"}));
}
TEST(ReadOffBad, LyingHeaderBeyondTheLimit) {
  EXPECT_TRUE(
      bad("lying_header.off", ErrorCategory::limit, {"lying_header.off:2:", "1000000000000 vertices"}));
}
TEST(ReadOffBad, LyingHeaderWithinTheLimit) {
  EXPECT_TRUE(bad("lying_header_within_limits.off", ErrorCategory::parse,
                  {"lying_header_within_limits.off:6:", "40000000 vertices but only 4"}));
}
TEST(ReadOffBad, TrailingGarbage) {
  EXPECT_TRUE(bad("trailing_garbage.off", ErrorCategory::parse,
                  {"trailing_garbage.off:13:", "unexpected 'hello'", "4 faces"}));
}
TEST(ReadOffBad, MalformedNumber) {
  EXPECT_TRUE(bad("bad_number.off", ErrorCategory::parse, {"bad_number.off:4:", "not a number: '1.2.3'"}));
}
TEST(ReadOffBad, FaceListsFewerIndicesThanDeclared) {
  EXPECT_TRUE(bad("face_count_mismatch.off", ErrorCategory::parse,
                  {"face_count_mismatch.off:8:", "face 1 declares 4 vertices but lists 3"}));
}
TEST(ReadOffBad, FaceWithTwoVertices) {
  EXPECT_TRUE(
      bad("two_vertex_face.off", ErrorCategory::parse, {"two_vertex_face.off:9:", "face 2 has 2 vertices"}));
}
TEST(ReadOffBad, NegativeCount) {
  EXPECT_TRUE(bad("negative_count.off", ErrorCategory::parse, {"negative_count.off:2:", "'-4'"}));
}
TEST(ReadOffBad, ExponentBeyondTheCap) {
  EXPECT_TRUE(bad("huge_exponent.off", ErrorCategory::limit, {"huge_exponent.off:4:", "exponent"}));
}
TEST(ReadOffBad, FourDimensional) {
  EXPECT_TRUE(bad("four_d.off", ErrorCategory::parse, {"four_d.off:1:", "only 3D"}));
}
TEST(ReadOffBad, PlainOffVertexWithFourValues) {
  EXPECT_TRUE(bad("extra_vertex_value.off", ErrorCategory::parse,
                  {"extra_vertex_value.off:3:", "vertex 0 has 4 values, expected 3"}));
}
TEST(ReadOffBad, CountBeyond64Bits) {
  EXPECT_TRUE(bad("count_overflow.off", ErrorCategory::limit,
                  {"count_overflow.off:2:", "vertex count", "beyond 2^64-1"}));
}
TEST(ReadOffBad, TooManyValuesAfterFaceIndices) {
  EXPECT_TRUE(bad("too_many_face_values.off", ErrorCategory::parse,
                  {"too_many_face_values.off:8:", "face 1 has more than 4 values"}));
}
TEST(ReadOffBad, MissingCoordinate) {
  EXPECT_TRUE(bad("missing_coordinate.off", ErrorCategory::parse,
                  {"missing_coordinate.off:4:", "missing z coordinate of vertex 1"}));
}
TEST(ReadOffBad, BinaryJunk) {
  EXPECT_TRUE(
      bad("binary_junk.off", ErrorCategory::parse, {"binary_junk.off:1:", "a NUL byte at byte 157", "binary data"}));
}

}  // namespace
}  // namespace cvms
