// SPDX-License-Identifier: MIT
// The tool on solids that need not be convex and on pieces files, run as a
// program on the small solids of test/data/solids, each answer checked
// against an oracle that does not use the code under test:
//  - `decompose`: every piece of the file read back is convex by the test's
//    own plane test, the pieces' volumes by the divergence theorem over
//    their facets (fans of tetrahedra from the origin) sum to the solid's
//    exact volume, and random exact points inside the solid are in some
//    piece, outside in none;
//  - `sum --pieces`: piece k of the output is the exact convex hull of the
//    pairwise vertex sums of the operands' pieces i and j, (i, j) = (k / m,
//    k % m), also with the operand B placed by --negate-b --translate-b;
//  - `check` on a valid non-convex solid (hand-checked counts and volume),
//    on an invalid one, on a pieces file (two boxes of 8 vertices and 6
//    facets), and on a convex one (its report unchanged);
//  - `distance` against the minimum over pieces of the convex distance;
//  - bad pieces files, limits and the convex-only commands' refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/proximity.hpp"
#include "cvms/solid.hpp"
#include "cvms/union_io.hpp"
#include "support/cli_runner.hpp"
#include "support/union_oracle.hpp"

namespace cvms {
namespace {

std::string solid_path(const std::string& name) {
  return (std::filesystem::path(CVMS_TEST_DATA_DIR) / "solids" / (name + ".off")).string();
}

// Each facet of the piece as a point on it and an outward normal from its
// first three corners (facets are strictly convex, so those are not collinear).
struct Plane {
  Vec3 point, normal;
};
std::vector<Plane> planes(const ConvexPolyhedron& p) {
  const PolygonSoup soup = p.to_soup();
  std::vector<Plane> result;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto face = soup.face(f);
    const Vec3& a = soup.points[face[0]];
    result.push_back({a, cross(soup.points[face[1]] - a, soup.points[face[2]] - a)});
  }
  return result;
}

bool in_piece(const ConvexPolyhedron& p, const Vec3& x) {
  for (const Plane& plane : planes(p))
    if (dot(plane.normal, x - plane.point) > 0) return false;
  return true;
}

// Every vertex on or behind every facet plane, and every facet planar.
bool convex_by_planes(const ConvexPolyhedron& p) {
  const PolygonSoup soup = p.to_soup();
  const std::vector<Plane> facet_planes = planes(p);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    for (const Vec3& v : soup.points)
      if (dot(facet_planes[f].normal, v - facet_planes[f].point) > 0) return false;
    for (std::uint32_t i : soup.face(f))
      if (dot(facet_planes[f].normal, soup.points[i] - facet_planes[f].point) != 0) return false;
  }
  return true;
}

class CliPieces : public test::CliTest {
 protected:
  CliPieces() : CliTest("cli_pieces_") {}
  void SetUp() override {
#ifndef CVMS_CLI_PATH
    GTEST_SKIP() << "the cvms tool is not built (CVMS_BUILD_TOOLS=OFF)";
#endif
  }
  [[nodiscard]] std::filesystem::path at(const std::string& name) const { return dir_.path() / name; }
  [[nodiscard]] std::string read(const std::string& name) const {
    std::ifstream in(at(name));
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  test::CliOutcome ok(const std::string& args) const {
    test::CliOutcome o = run(args);
    EXPECT_EQ(o.code, 0) << "cvms " << args << "\n" << o.err;
    return o;
  }
  void expect_failure(const std::string& args, const std::string& message) const {
    const test::CliOutcome o = run(args);
    EXPECT_EQ(o.code, 1) << "cvms " << args;
    EXPECT_NE(o.err.find(message), std::string::npos) << "cvms " << args << "\n" << o.err;
  }
};

TEST_F(CliPieces, DecomposedPiecesAreConvexFillTheSolidAndPartitionItsVolume) {
  const std::pair<const char*, std::size_t> solids[] = {
      {"l_block", 2},      {"star_prism", 5}, {"box_with_hole", 4},   {"cavity_cube", 6},    {"nested_shells", 7},
      {"two_cubes", 2},    {"decimal_box", 1}, {"split_top_cube", 1}, {"collinear_cube", 1}};
  for (const auto& [name, expected_pieces] : solids) {
    SCOPED_TRACE(name);
    const test::CliOutcome o = ok("decompose " + solid_path(name) + " -o pieces.obj");
    EXPECT_NE(o.out.find("convex pieces " + std::to_string(expected_pieces) + "\n"), std::string::npos) << o.out;
    const std::string text = read("pieces.obj");
    std::size_t objects = 0;
    for (std::size_t at = text.find("o piece_"); at != std::string::npos; at = text.find("\no piece_", at + 1))
      ++objects;
    EXPECT_EQ(objects, expected_pieces);
    const ConvexUnion pieces = read_pieces(at("pieces.obj"));
    ASSERT_EQ(pieces.size(), expected_pieces);
    const Solid solid = read_solid(solid_path(name));
    Rational total = 0;
    for (const ConvexPolyhedron& piece : pieces.pieces()) {
      EXPECT_TRUE(convex_by_planes(piece));
      total += test::volume_by_tetrahedra(piece);
    }
    EXPECT_EQ(total, solid.volume());
    // Random exact points of the bounding box (steps of 1/7 of it).
    const std::uint64_t seed = 49;
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    Vec3 lo = solid.vertices()[0], hi = lo;
    for (const Vec3& v : solid.vertices()) {
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
      hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
    }
    auto coordinate = [&](const Rational& a, const Rational& b) -> Rational {
      return a + (b - a) * Rational(static_cast<long>(rng() % 71), 70);
    };
    for (int k = 0; k < 200; ++k) {
      const Vec3 p{coordinate(lo.x, hi.x), coordinate(lo.y, hi.y), coordinate(lo.z, hi.z)};
      const Location where = solid.locate(p);
      if (where == Location::boundary) continue;
      const bool in_some = std::any_of(pieces.pieces().begin(), pieces.pieces().end(),
                                       [&](const ConvexPolyhedron& piece) { return in_piece(piece, p); });
      EXPECT_EQ(in_some, where == Location::inside) << "point " << k;
    }
  }
}

// Piece k of the sum file is the hull of a_i + b_j (each b_j mapped by
// `place`), (i, j) = (k / m, k % m).
template <class Place>
void expect_pairwise_hulls(const ConvexUnion& a, const ConvexUnion& b, const ConvexUnion& sum, Place&& place) {
  ASSERT_EQ(sum.size(), a.size() * b.size());
  for (std::size_t k = 0; k < sum.size(); ++k) {
    std::vector<Vec3> sums;
    for (const Vec3& p : a.pieces()[k / b.size()].mesh().positions())
      for (const Vec3& q : b.pieces()[k % b.size()].mesh().positions()) sums.push_back(p + place(q));
    EXPECT_EQ(test::vertex_set(sum.pieces()[k]), test::vertex_set(convex_hull(sums))) << "piece " << k;
    EXPECT_TRUE(convex_by_planes(sum.pieces()[k])) << "piece " << k;
  }
}

TEST_F(CliPieces, SumOfPiecesIsTheHullOfPairwiseVertexSumsOfEachPiecePair) {
  const std::pair<const char*, const char*> pairs[] = {
      {"l_block", "star_prism"}, {"box_with_hole", "l_block"}, {"cavity_cube", "two_cubes"}};
  for (const auto& [first, second] : pairs) {
    SCOPED_TRACE(std::string(first) + " + " + second);
    ok(std::string("decompose ") + solid_path(first) + " -o a.obj");
    ok(std::string("decompose ") + solid_path(second) + " -o b.obj");
    ok("sum a.obj b.obj --pieces -o s.obj");
    expect_pairwise_hulls(read_pieces(at("a.obj")), read_pieces(at("b.obj")), read_pieces(at("s.obj")),
                          [](const Vec3& q) { return q; });
    // The solids themselves decompose to the same pieces, in the same order.
    ok(std::string("sum ") + solid_path(first) + " " + solid_path(second) + " --pieces --threads 2 -o direct.obj");
    EXPECT_EQ(read("direct.obj"), read("s.obj"));
  }
}

TEST_F(CliPieces, PlacementOptionsMoveEveryPiece) {
  ok("decompose " + solid_path("l_block") + " -o a.obj");
  ok("decompose " + solid_path("star_prism") + " -o b.obj");
  ok("sum a.obj b.obj --pieces --translate-b 1 1/2 -3 --negate-b -o s.obj");
  const Vec3 t{Rational(1), Rational(1, 2), Rational(-3)};
  expect_pairwise_hulls(read_pieces(at("a.obj")), read_pieces(at("b.obj")), read_pieces(at("s.obj")),
                        [&](const Vec3& q) { return -(q + t); });
}

TEST_F(CliPieces, PiecesFileWithoutPiecesIsRefusedWithTheWayOut) {
  dir_.write("out.off", "untouched");
  ok("decompose " + solid_path("l_block") + " -o l.obj");
  expect_failure("sum l.obj " + solid_path("decimal_box") + " -o out.off",
                 "l.obj: a pieces file of 2 convex pieces, not a convex set: pass --pieces");
  EXPECT_EQ(read("out.off"), "untouched");
  // An invalid solid gets the solid's located defect.
  expect_failure("sum " + solid_path("decimal_box") + " " + solid_path("open_box"),
                 "open_box.off: open surface: edge (4, 5)");
  const test::CliOutcome o = run("sum " + solid_path("l_block") + " " + solid_path("l_block") + " --pieces -o s.off");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.err.find("pieces are written as OBJ objects"), std::string::npos) << o.err;
}

TEST_F(CliPieces, LimitsNameTheirOptionAndLeaveTheOutputAlone) {
  dir_.write("s.obj", "untouched");
  expect_failure("sum " + solid_path("star_prism") + " " + solid_path("l_block") + " --pieces --max-pieces 3 -o s.obj",
                 "raise it with --max-pieces");
  expect_failure("decompose " + solid_path("star_prism") + " --max-pieces 2 -o s.obj", "raise it with --max-pieces");
  expect_failure("sum " + solid_path("star_prism") + " " + solid_path("l_block") + " --pieces --max-facets 20 -o s.obj",
                 "raise it with --max-facets");
  EXPECT_EQ(read("s.obj"), "untouched");
}

// A pieces file is an input like any other: its estimated memory is taken
// from --max-memory before it is read, by every command that reads one.
TEST_F(CliPieces, PiecesFilesAreReadWithinTheMemoryBudget) {
  ok("decompose " + solid_path("star_prism") + " -o p.obj");
  const std::string refused = "an input of ";
  expect_failure("check p.obj --max-memory 1K", refused);
  expect_failure("distance p.obj " + solid_path("l_block") + " --max-memory 1K", refused);
  dir_.write("s.obj", "untouched");
  expect_failure("sum p.obj " + solid_path("l_block") + " --pieces --max-memory 1K -o s.obj", refused);
  EXPECT_EQ(read("s.obj"), "untouched");
  ok("check p.obj --max-memory 1M");
}

TEST_F(CliPieces, CheckReportsAValidNonConvexSolid) {
  test::CliOutcome o = ok("check " + solid_path("l_block"));
  EXPECT_EQ(o.out, solid_path("l_block") +
                       ": solid (not convex)\nshells 1, cavities 0, genus 0\nV 12, facets 8, reflex edges 1\n"
                       "volume 3\nconvex pieces 2\n");
  o = ok("check --json " + solid_path("box_with_hole"));
  for (const char* member : {"\"kind\": \"solid\"", "\"convex\": false", "\"shells\": 1", "\"cavities\": 0",
                             "\"genus\": 1", "\"volume\": \"8\"", "\"pieces\": 4", "\"reflex_edges\": 4"})
    EXPECT_NE(o.out.find(member), std::string::npos) << member << "\n" << o.out;
  o = ok("check " + solid_path("cavity_cube"));
  EXPECT_NE(o.out.find("shells 2, cavities 1, genus 0\n"), std::string::npos) << o.out;
  expect_failure("check " + solid_path("open_box"), "open_box.off: open surface: edge (4, 5)");
  expect_failure("check " + solid_path("overlapping_cubes"), "intersect (self-intersecting surface)");
  ok("decompose " + solid_path("l_block") + " -o l.obj");
  o = ok("check l.obj");
  EXPECT_EQ(o.out, "l.obj: pieces file\nconvex pieces 2\nV 16, F 12 (over all pieces)\n");
  o = ok("check " + solid_path("decimal_box"));
  EXPECT_NE(o.out.find(": convex polyhedron\ndimension 3\n"), std::string::npos) << o.out;
}

TEST_F(CliPieces, DistanceOfSolidsAndPiecesFilesIsTheMinimumOverPieces) {
  // A unit cube at x in [3, 4] beside the L block ([0,2]x[0,1] u [0,1]x[0,2]).
  dir_.write("cube.off",
             "OFF\n8 6 0\n3 0 0\n4 0 0\n3 1 0\n4 1 0\n3 0 1\n4 0 1\n3 1 1\n4 1 1\n"
             "4 0 4 6 2\n4 1 3 7 5\n4 0 1 5 4\n4 2 6 7 3\n4 0 2 3 1\n4 4 5 7 6\n");
  test::CliOutcome o = ok("distance " + solid_path("l_block") + " cube.off");
  EXPECT_NE(o.out.find("squared_distance 1\ndistance 1\n"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("intersect no\npiece_a 1\n"), std::string::npos) << o.out;
  ok("decompose " + solid_path("star_prism") + " -o star.obj");
  const ConvexUnion star = read_pieces(at("star.obj"));
  const ConvexPolyhedron cube = read_polyhedron(at("cube.off"));
  Rational best = squared_distance(star.pieces()[0], cube).squared_distance;
  for (const ConvexPolyhedron& piece : star.pieces())
    best = std::min(best, squared_distance(piece, cube).squared_distance);
  o = ok("distance cube.off star.obj --json");
  EXPECT_NE(o.out.find("\"squared_distance\": \"" + to_string(best) + "\""), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\"piece_b\": "), std::string::npos) << o.out;
  o = ok("distance star.obj " + solid_path("star_prism"));
  EXPECT_NE(o.out.find("squared_distance 0\n"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("intersect yes\n"), std::string::npos) << o.out;
  expect_failure("penetration star.obj cube.off", "star.obj: a pieces file of 5 convex pieces, not a convex set");
  expect_failure("penetration cube.off " + solid_path("l_block"), "a solid with 1 reflex edge, not a convex set");
}

TEST_F(CliPieces, DecomposeToStdoutReportsOnStderrAndJson) {
  ok("decompose " + solid_path("star_prism") + " -o star.obj");
  test::CliOutcome o = ok("decompose " + solid_path("star_prism"));
  EXPECT_EQ(o.out, read("star.obj"));
  EXPECT_NE(o.err.find("convex pieces 5\ntime: "), std::string::npos) << o.err;
  o = ok("decompose --json " + solid_path("star_prism") + " -o star2.obj");
  for (const char* member : {"\"kind\": \"solid\"", "\"reflex_edges\": 4", "\"volume\": \"32\"", "\"pieces\": 5",
                             "\"time_ms\": "})
    EXPECT_NE(o.out.find(member), std::string::npos) << member << "\n" << o.out;
  EXPECT_EQ(read("star2.obj"), read("star.obj"));
  // The rounded file reads back as five convex pieces (its decimals are short).
  ok("decompose --float " + solid_path("star_prism") + " -o star_float.obj");
  ASSERT_EQ(read_pieces(at("star_float.obj")).size(), 5u);
  // Stdin is OFF.
  o = run("decompose - -o stdin.obj < " + solid_path("l_block"));
  EXPECT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(read_pieces(at("stdin.obj")).size(), 2u);
}

TEST_F(CliPieces, BadPiecesFilesGetLocatedErrors) {
  const std::string cube_vertices = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
  const std::string cube_faces = "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  dir_.write("open.obj", "o a\n" + cube_vertices + cube_faces + "o b\n" + cube_faces.substr(0, 40));
  expect_failure("distance open.obj open.obj", "open.obj:16: piece 2 ('b'):");
  dir_.write("empty_piece.obj", "o a\n" + cube_vertices + cube_faces + "o b\no c\n" + cube_faces);
  expect_failure("sum empty_piece.obj empty_piece.obj --pieces -o s.obj", "empty_piece.obj:16: piece 2 ('b') has no faces");
  dir_.write("junk.obj", "o a\n" + cube_vertices + "o b\nf 1 2 x\n");
  expect_failure("distance junk.obj junk.obj", "junk.obj:11:");
}

}  // namespace
}  // namespace cvms
