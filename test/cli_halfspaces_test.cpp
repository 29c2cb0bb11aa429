// SPDX-License-Identifier: MIT
// `cvms diff`, `cvms halfspaces` and `cvms hull --from-halfspaces`
// run as a program on real files: hand-checked results (the cube [0,2]^3
// minus the unit cube is the unit cube at the origin; a cube minus itself is
// {0}), the cdd file round trip and the exit codes of bad input and usage
// errors.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "support/cli_runner.hpp"

namespace {

std::string cube_off(int lo, int hi) {
  std::ostringstream s;
  s << "OFF\n8 6 0\n";
  for (int i = 0; i < 8; ++i) s << ((i & 1) ? hi : lo) << ' ' << ((i & 2) ? hi : lo) << ' ' << ((i & 4) ? hi : lo) << '\n';
  s << "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";
  return s.str();
}

class CliHalfspaces : public cvms::test::CliTest {
 protected:
  CliHalfspaces() : CliTest("cli_halfspaces_") {}
  void SetUp() override {
#ifndef CVMS_CLI_PATH
    GTEST_SKIP() << "the cvms tool is not built (CVMS_BUILD_TOOLS=OFF)";
#endif
    dir_.write("big.off", cube_off(0, 2));
    dir_.write("unit.off", cube_off(0, 1));
    dir_.write("open.txt", "1 0 0 1\n");
    dir_.write("bad.ine", "begin\n2 4 integer\n1 0 0 0\nend\n");
  }
  [[nodiscard]] std::string read(const std::string& name) const {
    std::ifstream in(dir_.path() / name);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
};

TEST_F(CliHalfspaces, DiffPrintsTheDimensionAndCounts) {
  cvms::test::CliOutcome o = run("diff big.off unit.off -o d.off");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(o.out, "difference: convex polyhedron\ndimension 3, V 8 E 12 F 6\n");
  o = run("check d.off");
  ASSERT_EQ(o.code, 0) << o.err;
  o = run("diff unit.off unit.off -o p.off");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(o.out, "difference: point\ndimension 0, V 1\n");
  o = run("diff unit.off big.off -o e.off");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(o.out, "difference: empty set\ndimension -1, V 0\n");
}

TEST_F(CliHalfspaces, HalfspacesAndBackThroughCdd) {
  cvms::test::CliOutcome o = run("halfspaces big.off -o big.ine");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(read("big.ine").find("begin\n6 4 integer\n"), std::string::npos) << read("big.ine");
  o = run("hull --from-halfspaces big.ine -o back.off");
  ASSERT_EQ(o.code, 0) << o.err;
  o = run("check back.off");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.out.find("V 8 E 12 F 6"), std::string::npos) << o.out;
  o = run("halfspaces big.off -o big.ext");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(read("big.ext").find("V-representation\nbegin\n8 4 integer\n1 0 0 0\n"), std::string::npos) << read("big.ext");
  o = run("halfspaces unit.off -o -");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(o.out.rfind("H-representation\n", 0), 0u) << o.out;
}

TEST_F(CliHalfspaces, BadInputAndUsage) {
  cvms::test::CliOutcome o = run("hull --from-halfspaces open.txt -o o.off");
  EXPECT_EQ(o.code, 1);
  EXPECT_NE(o.err.find("open.txt: the half-spaces do not bound"), std::string::npos) << o.err;
  o = run("hull --from-halfspaces bad.ine -o o.off");
  EXPECT_EQ(o.code, 1);
  EXPECT_NE(o.err.find("bad.ine:4:"), std::string::npos) << o.err;
  o = run("hull -o o.off");
  EXPECT_EQ(o.code, 2) << o.err;
  o = run("hull unit.off --from-halfspaces big.ine -o o.off");
  EXPECT_EQ(o.code, 2) << o.err;
  o = run("diff - - -o o.off");
  EXPECT_EQ(o.code, 2) << o.err;
}

// Each message names the file once, quotes the input as written, and says
// what is wrong with an empty input rather than a line 0 or a whole space.
TEST_F(CliHalfspaces, MessagesNameTheFileOnceAndQuoteTheInputAsWritten) {
  const auto expect_error = [&](const std::string& args, const std::string& message) {
    SCOPED_TRACE("cvms " + args);
    const cvms::test::CliOutcome o = run(args);
    EXPECT_EQ(o.code, 1);
    EXPECT_EQ(o.err, "cvms: " + message + "\n");
  };
  dir_.write("empty.off", "OFF\n0 0 0\n");
  expect_error("diff unit.off empty.off -o d.off",
               "invalid_argument: empty.off: B is empty (the difference A - B would be all of space)");
  dir_.write("header.ine", "H-representation\nbegin\n2 5 integer\nend\n");
  expect_error("hull --from-halfspaces header.ine",
               "parse: header.ine:3: expected 'm 4 integer|rational|real' (3-D: 4 columns; 2-D: 3), got '2 5 integer'");
  dir_.write("empty.ine", "");
  expect_error("hull --from-halfspaces empty.ine", "parse: empty.ine: empty input (no 'begin' line)");
  expect_error("hull --from-halfspaces - < empty.ine", "parse: <stdin>: empty input (no 'begin' line)");
  dir_.write("count.ine", "linearity 18446744073709551616 1\nbegin\n1 4 integer\n1 0 0 0\nend\n");
  expect_error("hull --from-halfspaces count.ine",
               "parse: count.ine:1: linearity: expected 18446744073709551616 row indices");
  dir_.write("index.ine", "linearity 1 18446744073709551616\nbegin\n1 4 integer\n1 0 0 0\nend\n");
  expect_error("hull --from-halfspaces index.ine",
               "parse: index.ine:1: linearity index 18446744073709551616 is not a row");
  std::filesystem::create_directory(dir_.path() / "rows.ine");
  expect_error("hull --from-halfspaces rows.ine", "io: cannot read 'rows.ine': it is a directory");
  expect_error("hull --from-halfspaces - < /", "io: cannot read standard input: it is a directory");
  dir_.write("empty.txt", "");
  expect_error("hull --from-halfspaces empty.txt", "parse: empty.txt: empty input (no rows)");
  dir_.write("comments.txt", "# nothing\n\n");
  expect_error("hull --from-halfspaces comments.txt", "parse: comments.txt:2: no rows, only comments and blank lines");
  // 3y - 4.5z <= 0 and 0 <= 1: unbounded along (0, -3, -2) at any scaling.
  dir_.write("open2.txt", "0 3 -4.5 0\n0 0 0 1\n");
  expect_error("hull --from-halfspaces open2.txt",
               "invalid_argument: open2.txt: the half-spaces do not bound their intersection: it is unbounded in "
               "direction (0, -3, -2)");
}

}  // namespace
