// SPDX-License-Identifier: MIT
// `--float[=nearest|outer]` of the commands that write, run as a program on
// real files. Every output is read back as a floating-point pipeline reads it
// (support/read_as_doubles.hpp) and must be a valid convex set; an outer
// output must contain the exact result, whose oracle is the exact hull of
// the operands' pairwise vertex sums (sum) or of the points (hull).
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/set_io.hpp"
#include "support/cli_runner.hpp"
#include "support/read_as_doubles.hpp"

namespace cvms {
namespace {

// A tetrahedron and a skewed box with thirds and sevenths for coordinates:
// none of their sums' coordinates is a double.
constexpr const char* tetra_off =
    "OFF\n4 4 0\n0 0 0\n1/3 0 0\n0 2/7 0\n1/7 1/9 5/3\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
constexpr const char* points_xyz = "0 0 0\n1/3 0 0\n0 1/3 0\n0 0 1/3\n1/3 1/3 1/3\n2/7 1/11 0.1\n";

class CliFloat : public test::CliTest {
 protected:
  CliFloat() : CliTest("cli_float_") {}
  void SetUp() override {
#ifndef CVMS_CLI_PATH
    GTEST_SKIP() << "the cvms tool is not built (CVMS_BUILD_TOOLS=OFF)";
#endif
    dir_.write("t.off", tetra_off);
    dir_.write("p.xyz", points_xyz);
    ASSERT_EQ(run("gen rotated-sphere --subdivisions 1 -o s.off").code, 0);
  }
  [[nodiscard]] std::string text(const std::string& name) const {
    std::ifstream in(dir_.path() / name, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
  }
  [[nodiscard]] std::vector<Vec3> vertices(const std::string& name) const {
    return read_convex_set(dir_.path() / name).vertices();
  }
  // The exact sum of the files' sets: the hull of all pairwise vertex sums.
  [[nodiscard]] std::vector<Vec3> sum_oracle(const std::vector<std::string>& names) const {
    std::vector<Vec3> sums{Vec3{}};
    for (const std::string& name : names) {
      std::vector<Vec3> next;
      for (const Vec3& s : sums)
        for (const Vec3& v : vertices(name)) next.push_back(s + v);
      sums = convex_hull_set(next).vertices();
    }
    return sums;
  }
  // Runs a command writing `out` and checks the doubles it holds: valid, and
  // with `outer`, containing every point of `exact`.
  void expect_float_output(const std::string& command, const std::string& out, const std::vector<Vec3>& exact,
                           bool outer) {
    const test::CliOutcome o = run(command);
    ASSERT_EQ(o.code, 0) << command << ": " << o.err;
    const PolygonSoup soup = test::read_off_as_doubles(text(out));
    test::expect_valid_convex_set(soup, command);
    if (!outer) return;
    for (const Vec3& v : exact) EXPECT_TRUE(test::inside(soup, v)) << command << ": an exact vertex is outside";
  }
};

TEST_F(CliFloat, SumOfTwoAndOfThreeInEveryMode) {
  const std::vector<Vec3> two = sum_oracle({"t.off", "s.off"});
  const std::vector<Vec3> three = sum_oracle({"t.off", "s.off", "t.off"});
  expect_float_output("sum t.off s.off --float -o n.off", "n.off", two, false);
  expect_float_output("sum t.off s.off --float=nearest -o n2.off", "n2.off", two, false);
  EXPECT_EQ(text("n.off"), text("n2.off"));
  expect_float_output("sum t.off s.off --float=outer -o o.off", "o.off", two, true);
  expect_float_output("sum t.off s.off t.off --float=outer -o o3.off", "o3.off", three, true);
  expect_float_output("sum t.off s.off t.off --float -o n3.off", "n3.off", three, false);
  // The operands' order changes neither the set nor the bytes.
  ASSERT_EQ(run("sum t.off t.off s.off --float=outer -o o3b.off").code, 0);
  EXPECT_EQ(text("o3.off"), text("o3b.off"));
}

TEST_F(CliFloat, HullGenAndDiff) {
  expect_float_output("hull p.xyz --float=outer -o h.off", "h.off", vertices("p.xyz"), true);
  expect_float_output("hull p.xyz --float -o hn.off", "hn.off", {}, false);
  ASSERT_EQ(run("gen rotated-sphere --subdivisions 2 -o g_exact.off").code, 0);
  expect_float_output("gen rotated-sphere --subdivisions 2 --float=outer -o g2.off", "g2.off", vertices("g_exact.off"),
                      true);
  ASSERT_EQ(run("sum t.off s.off -o big.off").code, 0);
  ASSERT_EQ(run("diff big.off t.off -o d_exact.off").code, 0);
  expect_float_output("diff big.off t.off --float=outer -o d.off", "d.off", vertices("d_exact.off"), true);
}

TEST_F(CliFloat, BadModesAndFormatsAreRefusedAndLeaveTheOutput) {
  dir_.write("keep.stl", "keep");
  dir_.write("keep.off", "keep");
  test::CliOutcome o = run("sum t.off s.off --float=inner -o keep.off");
  EXPECT_EQ(o.code, 2) << o.err;
  EXPECT_NE(o.err.find("inner"), std::string::npos) << o.err;
  // STL holds float32: the outer rounding in doubles cannot be written there.
  o = run("sum t.off s.off --float=outer -o keep.stl");
  EXPECT_EQ(o.code, 1);
  EXPECT_NE(o.err.find("keep.stl: STL holds float32"), std::string::npos) << o.err;
  EXPECT_EQ(text("keep.stl"), "keep");
  // Rows are written exactly: no --float for them.
  o = run("diff s.off t.off --float=outer -o d.ine");
  EXPECT_EQ(o.code, 2) << o.err;
  EXPECT_EQ(text("keep.off"), "keep");
}

}  // namespace
}  // namespace cvms
