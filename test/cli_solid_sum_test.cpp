// SPDX-License-Identifier: MIT
// `cvms sum A B -o S` when an operand is a solid that is not convex: the
// boundary of A + B as one solid, run as a program on the small solids of
// test/data/solids, each answer checked against values derived by hand (the
// L-shape, the box with a hole and the cube with a cavity summed with boxes
// have volumes, vertices and genus that follow from the boxes' extents), or
// against brute force over the pieces' pairwise sums, or against the same
// command on an operand the test placed itself:
//  - every output format reads back as a valid solid that `cvms check`
//    accepts (a 2-manifold set), with the hand-derived volume and vertices;
//  - --float writes each vertex as its nearest double;
//  - the placement options act as on a file placed by the test;
//  - --threads gives the same bytes; an operand on standard input gives the
//    bytes of the same file;
//  - two lobes touching at a point give a closed shell per lobe, which
//    `cvms check` reads back and sums again (volumes by hand); solids whose
//    cubes share an edge or a corner by index are read, checked and summed;
//    shells whose wedges overlap along an edge are refused, located;
//  - limits name their option and leave an existing output untouched;
//    refusals: three operands, a flat operand, --float outer, a pieces file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cvms/decomposition.hpp"
#include "cvms/io.hpp"
#include "cvms/solid.hpp"
#include "support/cli_runner.hpp"
#include "support/union_oracle.hpp"

namespace cvms {
namespace {

std::string solid_path(const std::string& name) {
  return (std::filesystem::path(CVMS_TEST_DATA_DIR) / "solids" / (name + ".off")).string();
}

std::string cube_path() {
  return (std::filesystem::path(CVMS_TEST_DATA_DIR) / ".." / ".." / "examples" / "data" / "cube.off")
      .string();
}

std::set<Vec3> coordinates(const Solid& s) { return {s.vertices().begin(), s.vertices().end()}; }

Vec3 v(const Rational& x, const Rational& y, const Rational& z) { return {x, y, z}; }

// The L of side 3 without its 1 x 1 corner, z in [0, 2]: l_block + cube.
std::set<Vec3> l_sum_vertices() {
  std::set<Vec3> out;
  for (int z : {0, 2})
    for (const auto& [x, y] :
         std::initializer_list<std::pair<int, int>>{{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 3}, {0, 3}})
      out.insert(v(x, y, z));
  return out;
}

class CliSolidSum : public test::CliTest {
 protected:
  CliSolidSum() : CliTest("cli_solid_sum_") {}
  void SetUp() override {
#ifndef CVMS_CLI_PATH
    GTEST_SKIP() << "the cvms tool is not built (CVMS_BUILD_TOOLS=OFF)";
#endif
  }
  [[nodiscard]] std::filesystem::path at(const std::string& name) const { return dir_.path() / name; }
  [[nodiscard]] std::string read(const std::string& name) const { return test::slurp(at(name)); }
  test::CliOutcome ok(const std::string& args) const {
    test::CliOutcome o = run(args);
    EXPECT_EQ(o.code, 0) << "cvms " << args << "\n" << o.err;
    return o;
  }
  void expect_failure(const std::string& args, const std::string& message, int code = 1) const {
    const test::CliOutcome o = run(args);
    EXPECT_EQ(o.code, code) << "cvms " << args;
    EXPECT_NE(o.err.find(message), std::string::npos) << "cvms " << args << "\n" << o.err;
  }
};

TEST_F(CliSolidSum, LShapePlusCubeInEveryFormatIsTheLOfSideThree) {
  for (const char* extension : {"off", "obj", "stl", "ply"}) {
    SCOPED_TRACE(extension);
    const std::string out = std::string("s.") + extension;
    ok("sum " + solid_path("l_block") + " " + cube_path() + " -o " + out);
    const Solid s = read_solid(at(out));
    EXPECT_EQ(s.volume(), 16);
    EXPECT_EQ(coordinates(s), l_sum_vertices());
    EXPECT_EQ(s.num_facets(), 8u);
    const test::CliOutcome o = ok("check " + out);
    EXPECT_NE(o.out.find("solid (not convex)"), std::string::npos) << o.out;
  }
  // The operands the other way round, and B convex given first: the same set.
  ok("sum " + cube_path() + " " + solid_path("l_block") + " -o swapped.off");
  EXPECT_EQ(coordinates(read_solid(at("swapped.off"))), l_sum_vertices());
}

TEST_F(CliSolidSum, HoleStaysOpenAndCavityShrinksWithADecimalBox) {
  // box_with_hole: [0,3]^2 x [0,1] minus [1,2]^2; decimal_box:
  // [0.1,0.35] x [-0.2,0.15] x [1.05,1.3]. The hole keeps the points x whose
  // x - B lies inside it: [1.35,2.1] x [1.15,1.8], 0.75 x 0.65; the outside
  // grows to 3.25 x 3.35 x 1.25. Volume (3.25 * 3.35 - 0.75 * 0.65) * 1.25 = 13.
  ok("sum " + solid_path("box_with_hole") + " " + solid_path("decimal_box") + " -o hole.off");
  const Solid hole = read_solid(at("hole.off"));
  EXPECT_EQ(hole.volume(), 13);
  EXPECT_EQ(hole.genus(), 1u);
  EXPECT_EQ(hole.vertices().size(), 16u);
  EXPECT_TRUE(coordinates(hole).count(v(Rational(27, 20), Rational(23, 20), Rational(21, 20))));
  test::CliOutcome o = ok("check hole.off");
  EXPECT_NE(o.out.find("genus 1"), std::string::npos) << o.out;
  // cavity_cube: [0,3]^3 minus [1,2]^3. The cavity shrinks to 0.75 x 0.65 x
  // 0.75, the outside grows to 3.25 x 3.35 x 3.25.
  ok("sum " + solid_path("cavity_cube") + " " + solid_path("decimal_box") + " -o cavity.off");
  const Solid cavity = read_solid(at("cavity.off"));
  EXPECT_EQ(cavity.volume(), Rational(325 * 335 * 325 - 75 * 65 * 75) / 1000000);
  EXPECT_EQ(cavity.num_cavities(), 1u);
  o = ok("check cavity.off");
  EXPECT_NE(o.out.find("shells 2, cavities 1"), std::string::npos) << o.out;
}

TEST_F(CliSolidSum, CavityFilledExactlyByTheGrownInnerCube) {
  // nested_shells: [0,5]^3 with the cavity [1,4]^3 holding the cube [2,3]^3.
  // Plus the unit cube the cavity shrinks to [2,4]^3 and the inner cube
  // grows to [2,4]^3: the sum is the cube [0,6]^3.
  ok("sum " + solid_path("nested_shells") + " " + cube_path() + " -o s.off");
  const Solid s = read_solid(at("s.off"));
  EXPECT_TRUE(s.is_convex());
  EXPECT_EQ(s.volume(), 216);
  EXPECT_EQ(coordinates(s).size(), 8u);
}

TEST_F(CliSolidSum, TwoNonConvexSolidsAgreeWithTheBruteForceOverThePieces) {
  ok("sum " + solid_path("l_block") + " " + solid_path("star_prism") + " --threads 2 -o s.off");
  ok("sum " + solid_path("l_block") + " " + solid_path("star_prism") + " -o one.off");
  EXPECT_EQ(read("s.off"), read("one.off"));
  const Solid s = read_solid(at("s.off"));
  const ConvexUnion pieces =
      minkowski_sum_pieces(read_solid(solid_path("l_block")), read_solid(solid_path("star_prism")));
  std::mt19937_64 rng(2026);
  for (int k = 0; k < 400; ++k) {
    const Vec3 p = test::random_exact_point(rng, 7);
    EXPECT_EQ(s.contains(p), test::union_contains_brute_force(pieces, p)) << "seed 2026, point " << k;
  }
  for (const Vec3& p : s.vertices()) EXPECT_TRUE(test::union_contains_brute_force(pieces, p));
}

// The solid's soup mapped by x -> -(x + t), its faces reversed (the map
// turns orientation), written as OFF.
void write_negated_translated(const std::string& from, const std::filesystem::path& to, const Vec3& t) {
  PolygonSoup soup = read_file(from);
  PolygonSoup placed;
  for (const Vec3& p : soup.points) placed.points.push_back(-(p + t));
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto face = soup.face(f);
    placed.add_face(std::vector<std::uint32_t>(face.rbegin(), face.rend()));
  }
  write_file(to, placed);
}

TEST_F(CliSolidSum, PlacementOptionsActAsOnAFilePlacedByHand) {
  write_negated_translated(solid_path("star_prism"), at("placed.off"), v(1, Rational(1, 2), -3));
  ok("sum " + solid_path("l_block") + " " + solid_path("star_prism") +
     " --translate-b 1 1/2 -3 --negate-b -o a.off");
  ok("sum " + solid_path("l_block") + " placed.off -o b.off");
  EXPECT_EQ(read("a.off"), read("b.off"));
  // A quarter turn about z of the L: (x, y) -> (-y, x). L + cube turned
  // back is L + [0,1] x [-1,0] x [0,1], the sum above moved by (0, -1, 0).
  ok("sum " + solid_path("l_block") + " " + cube_path() + " --rotate-a 0 -1 0 1 0 0 0 0 1 -o turned.off");
  std::set<Vec3> expected;
  for (const Vec3& p : l_sum_vertices()) expected.insert(v(-(p.y - 1), p.x, p.z));
  EXPECT_EQ(coordinates(read_solid(at("turned.off"))), expected);
}

TEST_F(CliSolidSum, FloatWritesTheNearestDoubleOfEachVertex) {
  ok("sum " + solid_path("l_block") + " " + cube_path() + " --translate-b 1/3 0 1/7 -o exact.off");
  ok("sum " + solid_path("l_block") + " " + cube_path() + " --translate-b 1/3 0 1/7 --float -o float.off");
  const PolygonSoup exact = read_file(at("exact.off")), rounded = read_file(at("float.off"));
  ASSERT_EQ(exact.points.size(), rounded.points.size());
  int inexact = 0;
  for (std::size_t i = 0; i < exact.points.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      // The decimal written reads (strtod rounds correctly) as the double
      // nearest the exact value: no neighbouring double is nearer.
      const double d = std::strtod(to_string(rounded.points[i][c]).c_str(), nullptr);
      const Rational error = abs(Rational(d) - exact.points[i][c]);
      for (double neighbour : {std::nextafter(d, -HUGE_VAL), std::nextafter(d, HUGE_VAL)})
        EXPECT_LE(error, abs(Rational(neighbour) - exact.points[i][c])) << "vertex " << i;
      inexact += rounded.points[i][c] != exact.points[i][c] ? 1 : 0;
    }
  EXPECT_GT(inexact, 0);  // thirds and sevenths are no doubles
  EXPECT_EQ(exact.face_indices, rounded.face_indices);
  dir_.write("kept.off", "untouched");
  expect_failure("sum " + solid_path("l_block") + " " + cube_path() + " --float=outer -o kept.off",
                 "--float outer writes convex sets only", 2);
  EXPECT_EQ(read("kept.off"), "untouched");
}

TEST_F(CliSolidSum, LobesTouchingAtAPointAreOneClosedShellEach) {
  // two_cubes: [0,1]^3 and [2,3]^3; plus the unit cube they meet at (2,2,2).
  ok("sum " + solid_path("two_cubes") + " " + cube_path() + " -o s.off");
  const PolygonSoup soup = read_file(at("s.off"));
  EXPECT_EQ(soup.points.size(), 16u);
  EXPECT_EQ(std::count(soup.points.begin(), soup.points.end(), v(2, 2, 2)), 2);
  // cvms check reads it back: two shells touching at one point.
  const test::CliOutcome o = run("check s.off");
  EXPECT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.out.find("shells 2, cavities 0, genus 0"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("volume 16"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("parts touch: 1 point is held by several vertices"), std::string::npos) << o.out;
  // Summed again with the unit cube: [0,3]^3 and [2,5]^3, one shell of
  // volume 27 + 27 - 1 (by hand), read back once more.
  ok("sum s.off " + cube_path() + " -o again.off");
  const test::CliOutcome again = run("check again.off");
  EXPECT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.out.find("shells 1,"), std::string::npos) << again.out;
  EXPECT_NE(again.out.find("volume 53"), std::string::npos) << again.out;
  EXPECT_EQ(again.out.find("parts touch"), std::string::npos) << again.out;
}

TEST_F(CliSolidSum, SolidsGivenWithSharedIndicesWhereCubesTouch) {
  // Two unit cubes sharing an edge, then a corner, given with shared indices:
  // check reports both shells; each plus the unit cube is one shell of
  // volume 8 + 8 - 2 and 8 + 8 - 1 (by hand).
  for (const auto& [name, volume] : {std::pair{"cubes_sharing_edge", "14"}, std::pair{"cubes_sharing_corner", "15"}}) {
    const test::CliOutcome o = run("check " + solid_path(name));
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_NE(o.out.find("shells 2, cavities 0, genus 0"), std::string::npos) << o.out;
    ok("sum " + solid_path(name) + " " + cube_path() + " -o s.off");
    const test::CliOutcome sum = run("check s.off");
    EXPECT_NE(sum.out.find(std::string("volume ") + volume + "\n"), std::string::npos) << name << sum.out;
  }
}

TEST_F(CliSolidSum, AnOperandOnStandardInputIsReadOnceAsASolid) {
  ok("sum " + solid_path("l_block") + " " + cube_path() + " -o file.off");
  ok("sum - " + cube_path() + " -o stdin.off < " + solid_path("l_block"));
  EXPECT_EQ(read("stdin.off"), read("file.off"));
}

TEST_F(CliSolidSum, CrossingShellsAreRefusedWithTheirFaces) {
  // An inward unit cube along an outward one's edge: their wedges overlap.
  dir_.write("crossing.off",
             "OFF\n16 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
             "1 1 0\n2 1 0\n1 2 0\n2 2 0\n1 1 1\n2 1 1\n1 2 1\n2 2 1\n"
             "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n"
             "4 9 11 10 8\n4 14 15 13 12\n4 12 13 9 8\n4 11 15 14 10\n4 10 14 12 8\n4 13 15 11 9\n");
  expect_failure("check crossing.off", "crossing.off: the faces on edge (3, 7) do not alternate in direction");
  expect_failure("sum crossing.off " + cube_path() + " -o s.off", "do not alternate in direction");
}

TEST_F(CliSolidSum, LimitsNameTheirOptionAndKeepTheOutput) {
  dir_.write("out.off", "untouched");
  expect_failure("sum " + solid_path("l_block") + " " + cube_path() + " --max-facets 10 -o out.off",
                 "raise it with --max-facets");
  expect_failure(
      "sum " + solid_path("l_block") + " " + solid_path("star_prism") + " --max-facets 10 -o out.off",
      "raise it with --max-facets");
  expect_failure(
      "sum " + solid_path("l_block") + " " + solid_path("star_prism") + " --max-pieces 1 -o out.off",
      "raise it with --max-pieces");
  EXPECT_EQ(read("out.off"), "untouched");
}

TEST_F(CliSolidSum, RefusalsSayWhy) {
  expect_failure(
      "sum " + solid_path("l_block") + " " + cube_path() + " " + cube_path() + " -o s.off",
      "l_block.off: a solid with 1 reflex edge, not a convex set: a sum of more than two operands takes "
      "convex sets only");
  dir_.write("square.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  expect_failure(
      "sum " + solid_path("l_block") + " square.off -o s.off",
      "square.off: a convex polygon: a solid that is not convex is summed with polyhedra and solids only");
  ok("decompose " + solid_path("l_block") + " -o l.obj");
  expect_failure("sum l.obj " + cube_path() + " -o s.off",
                 "l.obj: a pieces file of 2 convex pieces, not a convex set: pass --pieces");
  expect_failure("sum " + solid_path("open_box") + " " + solid_path("l_block") + " -o s.off",
                 "open_box.off: open surface");
  EXPECT_FALSE(std::filesystem::exists(at("s.off")));
}

TEST_F(CliSolidSum, StatsNameTheRoad) {
  test::CliOutcome o = ok("sum " + solid_path("l_block") + " " + cube_path() + " --stats -o s.off");
  EXPECT_NE(o.out.find("road: faces of the solid + the convex operand, united"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("A+B: solid, not convex, V 12, facets 8, shells 1"), std::string::npos) << o.out;
  o = ok("sum " + solid_path("l_block") + " " + solid_path("l_block") + " --stats -o s.off");
  EXPECT_NE(o.out.find("road: pairwise sums of convex pieces, united"), std::string::npos) << o.out;
}

}  // namespace
}  // namespace cvms
