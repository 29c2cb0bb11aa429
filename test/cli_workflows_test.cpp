// SPDX-License-Identifier: MIT
// The tool's one-command workflows run as a program on real files:
//  - `sum --negate-b/--translate-b/--quaternion-b/--rotate-b` against the
//    sum with the operand moved by hand (canonical output through a third
//    operand {0}, so equal sets give equal bytes);
//  - `diff` on rows and points of the plane: the tube-MPC tightening of the
//    box |x| <= 5, |y| <= 2 by the disturbance box |w1| <= 1/2,
//    |w2| <= 1/4 is |x| <= 9/2, |y| <= 7/4 (hand-checked rows);
//  - --json parsed by Python's json module; --version.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "support/cli_runner.hpp"

namespace {

constexpr const char* box_off =
    "OFF\n8 6 0\n0 0 0\n1 0 0\n0 2 0\n1 2 0\n0 0 3\n1 0 3\n0 2 3\n1 2 3\n"
    "4 0 4 6 2\n4 1 3 7 5\n4 0 1 5 4\n4 2 6 7 3\n4 0 2 3 1\n4 4 5 7 6\n";
// The tetrahedron and its images, moved by hand.
constexpr const char* tet_faces = "3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n";
constexpr const char* tet_points = "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n";
constexpr const char* negated_points = "-1 -1 -1\n-1 1 1\n1 -1 1\n1 1 -1\n";
// x -> -(x + (-1, 1/2, 1/3)).
constexpr const char* moved_negated_points = "0 -1.5 -4/3\n0 0.5 2/3\n2 -1.5 2/3\n2 0.5 -4/3\n";
// 90 degrees about z: (x, y, z) -> (-y, x, z).
constexpr const char* turned_points = "-1 1 1\n1 1 -1\n-1 -1 -1\n1 -1 1\n";

std::string tetrahedron(const char* points, bool reversed) {
  return std::string("OFF\n4 4 0\n") + points + (reversed ? "3 2 1 0\n3 1 3 0\n3 3 2 0\n3 2 3 1\n" : tet_faces);
}

class CliWorkflows : public cvms::test::CliTest {
 protected:
  CliWorkflows() : CliTest("cli_workflows_") {}
  void SetUp() override {
#ifndef CVMS_CLI_PATH
    GTEST_SKIP() << "the cvms tool is not built (CVMS_BUILD_TOOLS=OFF)";
#endif
    dir_.write("box.off", box_off);
    dir_.write("tet.off", tetrahedron(tet_points, false));
    dir_.write("neg.off", tetrahedron(negated_points, true));
    dir_.write("moved.off", tetrahedron(moved_negated_points, true));
    dir_.write("turned.off", tetrahedron(turned_points, false));
    dir_.write("zero.xyz", "0 0 0\n");
    dir_.write("X.rows", "# states: |x| <= 5, |y| <= 2\n1 0 5\n-1 0 5\n0 1 2\n0 -1 2\n");
    dir_.write("W.rows", "# disturbance\n1 0 0.5\n-1 0 0.5\n0 1 0.25\n0 -1 0.25\n");
  }
  [[nodiscard]] std::string read(const std::string& name) const {
    std::ifstream in(dir_.path() / name);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  // Runs `cvms args` and expects success.
  void ok(const std::string& args) const {
    const cvms::test::CliOutcome o = run(args);
    ASSERT_EQ(o.code, 0) << "cvms " << args << "\n" << o.err;
  }
  // Both sums, each written canonically (three operands), byte for byte.
  void expect_same_sum(const std::string& placed_args, const std::string& by_hand) const {
    SCOPED_TRACE(placed_args);
    ok("sum box.off tet.off zero.xyz " + placed_args + " -o placed.off");
    ok("sum box.off " + by_hand + " zero.xyz -o hand.off");
    EXPECT_EQ(read("placed.off"), read("hand.off"));
    EXPECT_FALSE(read("hand.off").empty());
  }
};

TEST_F(CliWorkflows, NegateTranslateAndRotateEqualTheOperandMovedByHand) {
  expect_same_sum("--negate-b", "neg.off");
  expect_same_sum("--translate-b -1 0.5 1/3 --negate-b", "moved.off");
  expect_same_sum("--quaternion-b 1 0 0 1", "turned.off");
  expect_same_sum("--quaternion-b 7 0 0 7", "turned.off");  // not normalised
  expect_same_sum("--rotate-b 0 -1 0 1 0 0 0 0 1", "turned.off");
  expect_same_sum("--linear-b 0 -1 0 1 0 0 0 0 1", "turned.off");
}

TEST_F(CliWorkflows, PlacingAIsTheSameAsPlacingB) {
  ok("sum tet.off box.off --negate-a -o a.off");
  ok("sum neg.off box.off -o hand.off");
  ok("check a.off");
  ok("sum a.off zero.xyz zero.xyz -o a_canonical.off");
  ok("sum hand.off zero.xyz zero.xyz -o hand_canonical.off");
  EXPECT_EQ(read("a_canonical.off"), read("hand_canonical.off"));
}

TEST_F(CliWorkflows, NotARotationIsRefusedAndTheOutputIsLeftAlone) {
  dir_.write("out.off", "untouched");
  const auto expect_usage = [&](const std::string& args, const std::string& message) {
    SCOPED_TRACE(args);
    const cvms::test::CliOutcome o = run("sum box.off tet.off " + args + " -o out.off");
    EXPECT_EQ(o.code, 2);
    EXPECT_NE(o.err.find(message), std::string::npos) << o.err;
    EXPECT_EQ(read("out.off"), "untouched");
  };
  expect_usage("--rotate-b 0 1 0 1 0 0 0 0 1", "--rotate-b: not a rotation (determinant -1, a reflection)");
  expect_usage("--rotate-b 1 1 0 1 0 0 0 0 1", "--rotate-b: not a rotation (its columns are not orthonormal");
  expect_usage("--quaternion-a 0 0 0 0", "--quaternion-a: the zero quaternion is no rotation");
  expect_usage("--linear-b 1 0 0 0 1 0 0 0 0", "--linear-b: the matrix is singular");
  expect_usage("--translate-b 1 x 2", "--translate-b: 'x' is not a number");
  expect_usage("--translate-b 1 2", "--translate-b");
  expect_usage("--rotate-b 1 0 0 0 1 0 0 0 1 --quaternion-b 1 0 0 0", "excludes");
}

TEST_F(CliWorkflows, TubeMpcTighteningFromRowsOfThePlane) {
  cvms::test::CliOutcome o = run("diff X.rows W.rows -o Z.rows");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(o.out, "difference: convex polygon\ndimension 2, V 4\nplane: normal 0 0 1, offset 0\n");
  EXPECT_EQ(read("Z.rows"), "# a b c: a*x + b*y <= c\n0 -4 7\n2 0 9\n0 4 7\n-2 0 9\n");
  ok("diff X.rows W.rows -o Z.ine");
  EXPECT_EQ(read("Z.ine"), "H-representation\nbegin\n4 3 integer\n7 0 4\n9 -2 0\n7 0 -4\n9 2 0\nend\n");
  ok("diff X.rows W.rows -o Z.xyz");
  EXPECT_EQ(read("Z.xyz"), "-4.5 -1.75\n4.5 -1.75\n4.5 1.75\n-4.5 1.75\n");
  ok("diff X.rows W.rows -o Z.ext");
  EXPECT_EQ(read("Z.ext"), "V-representation\nbegin\n4 3 rational\n1 -4.5 -1.75\n1 4.5 -1.75\n1 4.5 1.75\n1 -4.5 1.75\nend\n");
  // Every form read back gives the same rows.
  for (const char* form : {"Z.ine", "Z.xyz", "Z.ext"}) {
    SCOPED_TRACE(form);
    ok(std::string("diff ") + form + " zero.xyz -o back.rows");
    EXPECT_NE(read("back.rows"), read("Z.rows"));  // zero.xyz is a point of space: 3-D rows
    dir_.write("zero2.xyz", "0 0\n");
    ok(std::string("diff ") + form + " zero2.xyz -o back.rows");
    EXPECT_EQ(read("back.rows"), read("Z.rows"));
  }
  // A polygon as a mesh in z = 0, and the disturbance as points of the plane.
  dir_.write("W.pts", "0.5 0.25\n-0.5 0.25\n-0.5 -0.25\n0.5 -0.25\n");
  ok("diff X.rows W.pts -o Z2.rows");
  EXPECT_EQ(read("Z2.rows"), read("Z.rows"));
  ok("diff X.rows W.rows -o Z.off");
  EXPECT_EQ(read("Z.off"), "OFF\n4 1 0\n-4.5 -1.75 0\n4.5 -1.75 0\n4.5 1.75 0\n-4.5 1.75 0\n4 0 1 2 3\n");
}

TEST_F(CliWorkflows, DiffOfSpaceRowsAndMeshes) {
  dir_.write("cube.rows", "1 0 0 2\n-1 0 0 0\n0 1 0 2\n0 -1 0 0\n0 0 1 2\n0 0 -1 0\n");
  dir_.write("unit.xyz", "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n");
  ok("diff cube.rows unit.xyz -o d.ine");
  EXPECT_EQ(read("d.ine"), "H-representation\nbegin\n6 4 integer\n1 -1 0 0\n0 1 0 0\n1 0 -1 0\n0 0 1 0\n1 0 0 -1\n0 0 0 1\nend\n");
}

TEST_F(CliWorkflows, AmbiguousAndMismatchedFilesAreClearErrors) {
  dir_.write("X.txt", "1 0 5\n");
  cvms::test::CliOutcome o = run("diff X.txt W.rows -o Z.rows");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.err.find("'X.txt': a .txt of numbers could be rows or points"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("name it .rows or .hrep for rows, .xyz or .pts for points"), std::string::npos) << o.err;
  dir_.write("rows_as_points.xyz", "1 0 0 5\n");
  o = run("diff X.rows rows_as_points.xyz -o Z.rows");
  EXPECT_EQ(o.code, 1);
  EXPECT_EQ(o.err, "cvms: parse: rows_as_points.xyz:1: point 1 has more than 3 numbers\n");
  dir_.write("mixed.rows", "1 0 5\n1 0 0 5\n");
  o = run("diff mixed.rows W.rows -o Z.rows");
  EXPECT_EQ(o.code, 1);
  EXPECT_NE(o.err.find("mixed.rows:2: row 2 has 4 numbers, row 1 has 3"), std::string::npos) << o.err;
  dir_.write("Z.rows", "untouched");
  o = run("diff X.rows W.rows -o Z.rows --float");
  EXPECT_EQ(o.code, 2);
  EXPECT_EQ(read("Z.rows"), "untouched");
  dir_.write("open.rows", "1 0 5\n");
  o = run("diff open.rows W.rows -o Z.rows");
  EXPECT_EQ(o.code, 1);
  EXPECT_NE(o.err.find("open.rows: the half-spaces do not bound"), std::string::npos) << o.err;
  EXPECT_EQ(read("Z.rows"), "untouched");
}

// Python's json module is the independent parser; the values are hand-checked.
TEST_F(CliWorkflows, JsonIsOneValidObject) {
  dir_.write("far.off", "OFF\n4 4 0\n3 0 0\n4 0 0\n3 1 0\n3 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const auto check_json = [&](const std::string& args, const std::string& expected) {
    SCOPED_TRACE(args);
    const cvms::test::CliOutcome o = run(args);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(std::count(o.out.begin(), o.out.end(), '\n'), 1) << o.out;  // one line
    dir_.write("out.json", o.out);
    dir_.write("check.py", "import json, sys\nd = json.load(open(sys.argv[1]))\nexpected = " + expected +
                               "\nif d != expected:\n    print(d)\n    sys.exit(1)\n");
    const std::string command =
        "/usr/bin/python3 " + (dir_.path() / "check.py").string() + " " + (dir_.path() / "out.json").string();
    EXPECT_EQ(std::system(command.c_str()), 0) << read("out.json");
  };
  if (std::system("/usr/bin/python3 -c 'import json' 2>/dev/null") != 0) GTEST_SKIP() << "no /usr/bin/python3";
  check_json("distance box.off far.off --json",
             "{'squared_distance': '4', 'squared_distance_double': 4, 'distance': 2, 'witness_a': ['1', '0', '0'], "
             "'witness_a_double': [1, 0, 0], 'witness_b': ['3', '0', '0'], 'witness_b_double': [3, 0, 0], "
             "'intersect': False}");
  check_json("penetration box.off tet.off --json",
             "{'squared_depth': '1', 'squared_depth_double': 1, 'depth': 1, 'direction': ['-1', '0', '0'], "
             "'direction_double': [-1, 0, 0], 'witness_a': ['0', '0.375', '0.375'], 'witness_a_double': [0, 0.375, "
             "0.375], 'witness_b': ['1', '0.375', '0.375'], 'witness_b_double': [1, 0.375, 0.375], 'intersect': True}");
  check_json("check box.off --json",
             "{'file': 'box.off', 'kind': 'convex polyhedron', 'dimension': 3, 'vertices': 8, 'edges': 12, 'facets': 6, "
             "'facet_degrees': {'4': 6}, 'input_vertices': 8, 'input_faces': 6}");
  // 1/3 has no finite decimal: the exact string and its nearest double.
  dir_.write("third.off", "OFF\n4 4 0\n0 0 4/3\n1 0 4/3\n0 1 4/3\n0 0 7/3\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  dir_.write("unit.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
  check_json("distance unit.xyz third.off --json",
             "{'squared_distance': '1/9', 'squared_distance_double': 1/9, 'distance': 1/3, 'witness_a': ['0', '0', '1'], "
             "'witness_a_double': [0, 0, 1], 'witness_b': ['0', '0', '4/3'], 'witness_b_double': [0, 0, 4/3], "
             "'intersect': False}");
}

TEST_F(CliWorkflows, VersionNamesTheProjectGmpAndTheBuildType) {
  const cvms::test::CliOutcome o = run("--version");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(o.out.rfind("cvms ", 0), 0u) << o.out;
  EXPECT_NE(o.out.find("\nGMP "), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\nbuild type: "), std::string::npos) << o.out;
}

}  // namespace
