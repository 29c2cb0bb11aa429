// SPDX-License-Identifier: MIT
// Tests of pieces files (cvms/union_io.hpp): the text of a small union
// checked by hand; exact round trips compared with the written pieces by
// their vertex sets (each piece's own vertices, sorted); rounded coordinates;
// every malformed pieces file refused with an error naming the piece and the
// line; a failed write leaving the existing file as it was.
#include "cvms/union_io.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/shapes.hpp"
#include "support/io_expect.hpp"
#include "support/union_oracle.hpp"

namespace cvms {
namespace {

using test::throws_error;

Vec3 v(long x, long y, long z) { return {Rational(x), Rational(y), Rational(z)}; }

ConvexUnion two_pieces() {
  const Rational third(1, 3);
  return ConvexUnion(std::vector<ConvexPolyhedron>{shapes::box(v(0, 0, 0), v(1, 1, 1)),
                                                   shapes::box(Vec3{1, 0, 0}, Vec3{2, third, third})});
}

std::string written(const ConvexUnion& u, Coordinates coordinates = Coordinates::exact) {
  std::ostringstream out;
  write_pieces(out, u, coordinates);
  return out.str();
}

ConvexUnion read_text(const std::string& text, ReadLimits limits = {}) {
  std::istringstream in(text);
  return read_pieces(in, "pieces.obj", limits);
}

TEST(UnionIo, WritesOneObjectPerPieceWithFileWideIndices) {
  const std::string text = written(two_pieces());
  // Two objects, named from 1; eight vertices and six quadrilaterals each;
  // the second piece's faces use vertices 9 to 16.
  EXPECT_EQ(text.find("o piece_1\n"), 0u);
  EXPECT_NE(text.find("\no piece_2\n"), std::string::npos);
  std::istringstream lines(text);
  std::string line;
  int vertices = 0, faces = 0, second = 0;
  while (std::getline(lines, line)) {
    if (line.rfind("o piece_2", 0) == 0) second = vertices;
    if (line.rfind("v ", 0) == 0) ++vertices;
    if (line.rfind("f ", 0) != 0) continue;
    ++faces;
    std::istringstream tokens(line.substr(2));
    int index = 0, count = 0;
    while (tokens >> index) {
      ++count;
      if (faces <= 6) EXPECT_TRUE(index >= 1 && index <= 8) << line;
      else EXPECT_TRUE(index >= 9 && index <= 16) << line;
    }
    EXPECT_EQ(count, 4) << line;
  }
  EXPECT_EQ(vertices, 16);
  EXPECT_EQ(second, 8);
  EXPECT_EQ(faces, 12);
  EXPECT_NE(text.find("v 2 1/3 1/3\n"), std::string::npos);
}

TEST(UnionIo, ExactRoundTripGivesTheSamePieces) {
  const ConvexUnion u(std::vector<ConvexPolyhedron>{shapes::truncated_cube(), shapes::octahedron(),
                                                    shapes::geodesic_sphere(2), shapes::tetrahedron()});
  const ConvexUnion back = read_text(written(u));
  ASSERT_EQ(back.size(), u.size());
  for (std::size_t i = 0; i < u.size(); ++i) {
    EXPECT_EQ(test::vertex_set(back.pieces()[i]), test::vertex_set(u.pieces()[i])) << "piece " << i;
    EXPECT_EQ(back.pieces()[i].num_facets(), u.pieces()[i].num_facets()) << "piece " << i;
  }
}

TEST(UnionIo, DoubleCoordinatesAreTheNearestDoubles) {
  const std::string text = written(two_pieces(), Coordinates::double_);
  EXPECT_NE(text.find("v 2 0.3333333333333333 0.3333333333333333\n"), std::string::npos);
  EXPECT_EQ(read_text(text).size(), 2u);
}

TEST(UnionIo, FileWithoutObjectsIsOnePiece) {
  std::ostringstream out;
  write_obj(out, shapes::cube().to_soup());
  const ConvexUnion u = read_text(out.str());
  ASSERT_EQ(u.size(), 1u);
  EXPECT_EQ(test::vertex_set(u.pieces()[0]), test::vertex_set(shapes::cube()));
}

TEST(UnionIo, FilesOnDiskRoundTripAndFailedWritesKeepTheFile) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "cvms_union_io_test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / "pieces.obj";
  write_pieces(path, two_pieces());
  EXPECT_EQ(read_pieces(path).size(), 2u);
  const std::string before = test::file_bytes(path);
  const Rational huge = Rational(mpz_class(1) << 2000);
  const ConvexUnion far(std::vector<ConvexPolyhedron>{shapes::box(v(0, 0, 0), Vec3{huge, 1, 1})});
  EXPECT_TRUE(throws_error([&] { write_pieces(path, far, Coordinates::double_); }, ErrorCategory::invalid_argument,
                           {"pieces.obj: piece 1: vertex ", "beyond the range of double"}));
  EXPECT_EQ(test::file_bytes(path), before);
  EXPECT_TRUE(throws_error([&] { (void)read_pieces(dir / "missing.obj"); }, ErrorCategory::io, {"missing.obj"}));
  EXPECT_TRUE(throws_error([&] { write_pieces(path, ConvexUnion()); }, ErrorCategory::invalid_argument,
                           {"empty union"}));
  std::filesystem::remove_all(dir);
}

// A unit cube's faces as OBJ lines, its vertices numbered from `first`.
std::string cube_faces(int first) {
  const int f[6][4] = {{1, 4, 3, 2}, {5, 6, 7, 8}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 4, 8, 7}, {4, 1, 5, 8}};
  std::string text;
  for (const auto& face : f) {
    text += "f";
    for (int i : face) text += " " + std::to_string(first + i - 1);
    text += "\n";
  }
  return text;
}

const char* cube_vertices = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";

TEST(UnionIo, HandWrittenFileReadsAsTwoCubes) {
  const std::string text = std::string("o a\n") + cube_vertices + cube_faces(1) + "o b\n" + cube_faces(1);
  const ConvexUnion u = read_text(text);
  ASSERT_EQ(u.size(), 2u);  // the same cube twice: pieces may overlap
  EXPECT_EQ(test::vertex_set(u.pieces()[1]), test::vertex_set(shapes::box(v(0, 0, 0), v(1, 1, 1))));
}

TEST(UnionIo, BadFilesGetLocatedErrors) {
  // Line numbers: "o a" is line 1, the vertices lines 2-9, faces 10-15.
  const std::string good = std::string("o a\n") + cube_vertices + cube_faces(1);
  EXPECT_TRUE(throws_error([&] { (void)read_text(cube_vertices + cube_faces(1) + "o late\n" + cube_faces(1)); },
                           ErrorCategory::parse, {"pieces.obj:15:", "6 faces come before the first 'o'"}));
  EXPECT_TRUE(throws_error([&] { (void)read_text(good + "o empty\no next\n" + cube_faces(1)); }, ErrorCategory::parse,
                           {"pieces.obj:16: piece 2 ('empty') has no faces"}));
  // An open piece: the second object lacks its last face.
  std::string open_faces = cube_faces(1);
  open_faces.erase(open_faces.rfind("f "));
  EXPECT_TRUE(throws_error([&] { (void)read_text(good + "o open\n" + open_faces); }, ErrorCategory::topology,
                           {"pieces.obj:16: piece 2 ('open'): "}));
  // A non-convex piece: an L-shaped prism in one object (relative indices).
  const std::string l_prism =
      "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\n"
      "v 0 0 1\nv 2 0 1\nv 2 1 1\nv 1 1 1\nv 1 2 1\nv 0 2 1\n"
      "o L\nf -7 -8 -9 -10 -11 -12\nf -6 -5 -4 -3 -2 -1\nf -12 -11 -5 -6\nf -11 -10 -4 -5\nf -10 -9 -3 -4\n"
      "f -9 -8 -2 -3\nf -8 -7 -1 -2\nf -7 -12 -6 -1\n";
  EXPECT_TRUE(throws_error([&] { (void)read_text(good + l_prism); }, ErrorCategory::not_convex,
                           {"pieces.obj:28: piece 2 ('L'): "}));
  EXPECT_TRUE(throws_error([&] { (void)read_text(good + "f 1 2 x\n"); }, ErrorCategory::parse, {"pieces.obj:16:"}));
  EXPECT_TRUE(throws_error([&] { (void)read_text(""); }, ErrorCategory::parse, {"pieces.obj: empty input"}));
  EXPECT_TRUE(throws_error([&] { (void)read_text("o only\nv 0 0 0\n"); }, ErrorCategory::parse,
                           {"pieces.obj:1: piece 1 ('only') has no faces"}));
  EXPECT_TRUE(throws_error([&] { (void)read_text("o " + std::string(100, 'n') + "\nv 0 0 0\n"); },
                           ErrorCategory::parse, {"piece 1 ('" + std::string(64, 'n') + "...') has no faces"}));
  ReadLimits small;
  small.max_bytes = 64;
  EXPECT_TRUE(throws_error([&] { (void)read_text(good, small); }, ErrorCategory::limit, {"pieces.obj"}));
}

}  // namespace
}  // namespace cvms
