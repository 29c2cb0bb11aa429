// SPDX-License-Identifier: MIT
// `cvms distance` and `cvms penetration` run as a program on real files: the
// line format, the exact numbers (hand-checked: unit cubes 1/3 apart, cubes
// overlapping by 1/10) and the exit codes of bad input and usage errors.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "support/cli_runner.hpp"

namespace {

// The cube [x0, x0 + 1] x [0, 1] x [0, 1] as OFF text (x0 exact text).
std::string cube_off(const std::string& x0, const std::string& x1) {
  std::ostringstream s;
  s << "OFF\n8 6 0\n";
  for (int i = 0; i < 8; ++i) s << ((i & 1) ? x1 : x0) << ' ' << ((i & 2) ? 1 : 0) << ' ' << ((i & 4) ? 1 : 0) << '\n';
  s << "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";
  return s.str();
}

class CliProximity : public cvms::test::CliTest {
 protected:
  CliProximity() : CliTest("cli_proximity_") {}
  void SetUp() override {
#ifndef CVMS_CLI_PATH
    GTEST_SKIP() << "the cvms tool is not built (CVMS_BUILD_TOOLS=OFF)";
#endif
    dir_.write("a.off", cube_off("0", "1"));
    dir_.write("apart.off", cube_off("4/3", "7/3"));
    dir_.write("over.off", cube_off("0.9", "1.9"));
  }
  // Runs the command and checks that it succeeds, prints `head` first and
  // says whether the operands intersect.
  void expect_run(const std::string& command, const std::string& head, bool intersect) {
    const cvms::test::CliOutcome o = run(command);
    ASSERT_EQ(o.code, 0) << command << ": " << o.err;
    EXPECT_EQ(o.out.rfind(head, 0), 0u) << command << ": " << o.out;
    EXPECT_NE(o.out.find(intersect ? "intersect yes\n" : "intersect no\n"), std::string::npos) << command << ": " << o.out;
  }
};

TEST_F(CliProximity, DistanceOfCubesOneThirdApart) {
  const cvms::test::CliOutcome o = run("distance a.off apart.off");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(o.out,
            "squared_distance 1/9\n"
            "distance 0.3333333333333333\n"
            "witness_a 1 0 0\n"
            "witness_b 4/3 0 0\n"
            "intersect no\n");
}

TEST_F(CliProximity, PenetrationOfCubesOverlappingByOneTenth) {
  const cvms::test::CliOutcome o = run("penetration a.off over.off");
  ASSERT_EQ(o.code, 0) << o.err;
  const std::string head =
      "squared_depth 0.01\n"
      "depth 0.1\n"
      "direction 1 0 0\n";
  EXPECT_EQ(o.out.substr(0, head.size()), head) << o.out;
  EXPECT_NE(o.out.find("\nwitness_a 1 "), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\nwitness_b 0.9 "), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\nintersect yes\n"), std::string::npos) << o.out;
}

TEST_F(CliProximity, PenetrationOfSeparatedAndDistanceOfOverlapping) {
  expect_run("penetration a.off apart.off", "squared_depth 0\ndepth 0\ndirection 0 0 0\n", false);
  expect_run("distance a.off over.off", "squared_distance 0\ndistance 0\n", true);
}

TEST_F(CliProximity, BadInputAndUsage) {
  cvms::test::CliOutcome o = run("distance a.off missing.off");
  EXPECT_EQ(o.code, 1);
  EXPECT_NE(o.err.find("missing.off"), std::string::npos) << o.err;
  o = run("penetration - -");
  EXPECT_EQ(o.code, 2);
  o = run("distance a.off");
  EXPECT_EQ(o.code, 2);
  o = run("distance a.off b.txt");
  EXPECT_EQ(o.code, 2);
}

// A flat operand (an OBJ with one face: the square [0,1]^2 at height 4/3)
// and a segment (an OBJ with only `v` lines) against the unit cube.
TEST_F(CliProximity, FlatObjOperands) {
  dir_.write("square.obj", "v 0 0 4/3\nv 1 0 4/3\nv 1 1 4/3\nv 0 1 4/3\nf 1 2 3 4\n");
  dir_.write("segment.obj", "v 0.5 0.5 -1\nv 0.5 0.5 2\n");
  dir_.write("empty.off", "OFF\n0 0 0\n");
  expect_run("distance a.off square.obj", "squared_distance 1/9\ndistance 0.3333333333333333\n", false);
  // The segment pierces the cube: A + (-B) = [-1/2, 1/2]^2 x [-2, 2].
  expect_run("penetration a.off segment.obj", "squared_depth 0.25\ndepth 0.5\ndirection -1 0 0\n", true);
  // Two flat operands in one plane: A + (-B) has no interior, depth 0.
  expect_run("penetration square.obj square.obj", "squared_depth 0\ndepth 0\ndirection 0 0 1\n", true);
  const cvms::test::CliOutcome o = run("distance empty.off a.off");
  EXPECT_EQ(o.code, 1);
  EXPECT_NE(o.err.find("empty.off"), std::string::npos) << o.err;
}

}  // namespace
