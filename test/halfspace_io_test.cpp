// SPDX-License-Identifier: MIT
// cdd H- and V-representation files and the plain half-space form: the
// classic cdd examples (a cube given with redundant rows, a cross-polytope)
// against hand-checked sets, exact round trips, and hostile input (errors
// naming the line; a lying header count allocates nothing).
#include <gtest/gtest.h>

#include <array>
#include <ostream>
#include <sstream>
#include <streambuf>
#include <string>

#include "cvms/error.hpp"
#include "cvms/halfspace_io.hpp"
#include "cvms/shapes.hpp"
#include "support/hand_solids.hpp"
#include "support/random_sets.hpp"
#include "support/set_oracle.hpp"

namespace cvms {
namespace {

using test::describe_set;
using test::v3;

HalfspaceSystem parse(const std::string& text, HalfspaceFormat format = HalfspaceFormat::cdd) {
  std::istringstream in(text);
  return read_halfspaces(in, format, "test.ine");
}

void expect_error(const std::string& text, ErrorCategory category, const std::string& fragment,
                  HalfspaceFormat format = HalfspaceFormat::cdd) {
  try {
    (void)parse(text, format);
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), category) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(CddFormat, CubeWithRedundantRows) {
  // cdd's convention: each row b c means b + c·x >= 0.
  const std::string text =
      "* the unit cube [-1,1]^3 and two redundant rows\n"
      "H-representation\n"
      "begin\n"
      " 8 4 rational\n"
      " 1 -1 0 0\n 1 1 0 0\n 1 0 -1 0\n 1 0 1 0\n 1 0 0 -1\n 1 0 0 1\n"
      " 3 -1 -1 -1\n 10/3 0 0 -2\n"
      "end\n"
      "minimize\n 0 1 1 1\n";
  EXPECT_EQ(describe_set(from_halfspaces(parse(text))), describe_set(ConvexSet(shapes::box(v3(-1, -1, -1), v3(1, 1, 1)))));
}

TEST(CddFormat, CrossPolytopeAndLinearity) {
  std::string text = "H-representation\nbegin\n8 4 integer\n";
  for (int s = 0; s < 8; ++s) {
    text += "1 " + std::to_string((s & 1) ? 1 : -1) + " " + std::to_string((s & 2) ? 1 : -1) + " " +
            std::to_string((s & 4) ? 1 : -1) + "\n";
  }
  text += "end\n";
  EXPECT_EQ(describe_set(from_halfspaces(parse(text))), describe_set(ConvexSet(shapes::octahedron())));
  // z == 0 as a linearity row: the cross-polytope's square section.
  const std::string flat = "H-representation\nlinearity 1 9\nbegin\n9 4 real\n" + text.substr(text.find("8 4 integer\n") + 12, text.find("end") - text.find("8 4 integer\n") - 12) + "0.0 0 0 1\nend\n";
  const ConvexSet s = from_halfspaces(parse(flat));
  EXPECT_EQ(describe_set(s), describe_set(ConvexSet::polygon(std::vector<Vec3>{v3(1, 0, 0), v3(0, 1, 0), v3(-1, 0, 0), v3(0, -1, 0)})));
}

TEST(CddFormat, RoundTripsAreExact) {
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    std::mt19937_64 rng(seed);
    const ConvexSet set = test::random_set(rng, static_cast<int>(seed % 4), Vec3{Rational(1, 3), 0, Rational(7, 5)});
    const HalfspaceSystem rows = to_halfspaces(set);
    for (const HalfspaceFormat format : {HalfspaceFormat::cdd, HalfspaceFormat::plain}) {
      std::ostringstream out;
      write_halfspaces(out, rows, format);
      std::istringstream in(out.str());
      EXPECT_EQ(describe_set(from_halfspaces(read_halfspaces(in, format))), describe_set(set)) << "seed " << seed;
    }
    std::ostringstream ext;
    write_cdd_points(ext, set);
    std::istringstream in(ext.str());
    const std::vector<Vec3> points = read_cdd_points(in);
    EXPECT_EQ(test::hull_oracle(points), describe_set(set)) << "seed " << seed;
  }
  const HalfspaceSystem rational{{}, {{Vec3{Rational(1, 3), 0, 0}, Rational(2, 7)}}};
  std::ostringstream out;
  write_halfspaces(out, rational, HalfspaceFormat::cdd);
  EXPECT_NE(out.str().find("1 4 rational\n2/7 -1/3 0 0\n"), std::string::npos) << out.str();
  std::istringstream in(out.str());
  EXPECT_EQ(read_halfspaces(in, HalfspaceFormat::cdd).inequalities, rational.inequalities);
}

// More rows than any reservation made before reading them (4,096), with
// rational and negative entries and equalities among them: every row comes
// back exactly, in order, in both formats (the readers parse rows in place
// and move them into the system once).
TEST(CddFormat, ManyRowsComeBackExactlyInOrder) {
  std::mt19937_64 rng(2026);
  HalfspaceSystem rows;
  const auto number = [&] {
    Rational q(static_cast<long>(rng() % 2001) - 1000, static_cast<long>(1 + rng() % 9));
    q.canonicalize();
    return q;
  };
  for (int i = 0; i < 5000; ++i) {
    HalfspaceRow row{Vec3{number(), number(), number()}, number()};
    (i % 997 == 3 ? rows.equalities : rows.inequalities).push_back(row);
  }
  std::ostringstream cdd;
  write_halfspaces(cdd, rows, HalfspaceFormat::cdd);
  std::istringstream cdd_in(cdd.str());
  const HalfspaceSystem from_cdd = read_halfspaces(cdd_in, HalfspaceFormat::cdd);
  EXPECT_EQ(from_cdd.inequalities, rows.inequalities);
  EXPECT_EQ(from_cdd.equalities, rows.equalities);
  const HalfspaceSystem inequalities{{}, rows.inequalities};
  std::ostringstream plain;
  write_halfspaces(plain, inequalities, HalfspaceFormat::plain);
  std::istringstream plain_in(plain.str());
  EXPECT_EQ(read_halfspaces(plain_in, HalfspaceFormat::plain).inequalities, rows.inequalities);
}

TEST(CddFormat, HostileInputNamesTheLine) {
  expect_error("begin\n1 4 integer\n1 0 0 0\n", ErrorCategory::parse, "test.ine:3: no 'end' line");
  expect_error("H-representation\n1 4 integer\n", ErrorCategory::parse, "no 'begin' line");
  expect_error("", ErrorCategory::parse, "test.ine: empty input (no 'begin' line)");
  expect_error("", ErrorCategory::parse, "test.ine: empty input (no rows)", HalfspaceFormat::plain);
  expect_error("# only a comment\n", ErrorCategory::parse, "test.ine:1: no rows, only comments and blank lines",
               HalfspaceFormat::plain);
  expect_error("begin\n2 5 integer\nend\n", ErrorCategory::parse,
               "test.ine:2: expected 'm 4 integer|rational|real' (3-D: 4 columns; 2-D: 3), got '2 5 integer'");
  expect_error("linearity 18446744073709551616 1\nbegin\n", ErrorCategory::parse,
               "test.ine:1: linearity: expected 18446744073709551616 row indices");
  expect_error("linearity 1 99999999999999999999\nbegin\n", ErrorCategory::parse,
               "test.ine:1: linearity index 99999999999999999999 is not a row");
  expect_error("begin\n2 4 integer\n1 0 0 0\nend\n", ErrorCategory::parse, "test.ine:4: 1 rows before 'end', the header says 2");
  expect_error("begin\n1 4 integer\n1 0 0 0\n1 0 0 0\nend\n", ErrorCategory::parse, "test.ine:4: more rows");
  expect_error("begin\n1 4 integer\n1 0 x 0\nend\n", ErrorCategory::parse, "test.ine:3:");
  expect_error("begin\n1 4 integer\n1 0 0\nend\n", ErrorCategory::parse, "test.ine:3: row 1 has fewer than 4 numbers");
  expect_error("begin\n1 4 integer\n1 0 0 0 0\nend\n", ErrorCategory::parse, "more than 4 numbers");
  expect_error("begin\n1 5 integer\n1 0 0 0 0\nend\n", ErrorCategory::parse, "test.ine:2: expected 'm 4");
  expect_error("begin\n1 3 integer\n1 0 0 0\nend\n", ErrorCategory::parse, "test.ine:3: row 1 has more than 3 numbers");
  expect_error("begin\n1 4 float\n1 0 0 0\nend\n", ErrorCategory::parse, "expected 'm 4");
  expect_error("linearity 1 2\nbegin\n1 4 integer\n1 0 0 0\nend\n", ErrorCategory::parse, "linearity index 2 is not a row");
  expect_error("linearity 2 1\nbegin\n", ErrorCategory::parse, "test.ine:1: linearity");
  expect_error("V-representation\nbegin\n1 4 integer\n1 0 0 0\nend\n", ErrorCategory::parse, "this is a V-representation");
  expect_error("begin\n1 4 integer\n1 0 nan 0\nend\n", ErrorCategory::parse, "test.ine:3:");
  // A header that lies about its size: refused at the end, nothing reserved for it.
  expect_error("begin\n18446744073709551615 4 integer\n1 0 0 0\nend\n", ErrorCategory::limit, "test.ine:2:");
  expect_error("begin\n99999999 4 integer\n1 0 0 0\nend\n", ErrorCategory::parse, "the header says 99999999");
  expect_error("1 0\n", ErrorCategory::parse, "test.ine:1: row 1 has fewer than 3 numbers", HalfspaceFormat::plain);
  expect_error("1 0 1\n1 0 0 1\n", ErrorCategory::parse, "test.ine:2: row 2 has 4 numbers, row 1 has 3",
               HalfspaceFormat::plain);
  expect_error("# ok\n1 0 0 1\n1 0 0 1 2\n", ErrorCategory::parse, "test.ine:3:", HalfspaceFormat::plain);
}

// Files of the plane: rows a b c (cdd: m 3) are the polygon in z = 0, and
// written back with dimension 2 they are the same rows (hand-checked).
TEST(CddFormat, RowsAndPointsOfThePlane) {
  std::istringstream plain("# the square |x| <= 1, 0 <= y <= 2\n1 0 1\n-1 0 1\n0 1 2\n0 -1 0\n");
  const HalfspaceFile file = read_halfspaces_of_any_dimension(plain, HalfspaceFormat::plain);
  EXPECT_EQ(file.dimension, 2);
  ASSERT_EQ(file.system.equalities.size(), 1u);
  EXPECT_EQ(file.system.equalities[0], (HalfspaceRow{{0, 0, 1}, 0}));
  ASSERT_EQ(file.system.inequalities.size(), 4u);
  EXPECT_EQ(file.system.inequalities[2], (HalfspaceRow{{0, 1, 0}, 2}));
  const ConvexSet square = from_halfspaces(file.system);
  ASSERT_EQ(square.dimension(), 2);
  std::ostringstream cdd;
  write_halfspaces(cdd, to_halfspaces(square), HalfspaceFormat::cdd, 2);
  EXPECT_EQ(cdd.str(), "H-representation\nbegin\n4 3 integer\n0 0 1\n1 -1 0\n2 0 -1\n1 1 0\nend\n");
  std::istringstream cdd_in(cdd.str());
  const HalfspaceFile back = read_halfspaces_of_any_dimension(cdd_in, HalfspaceFormat::cdd);
  EXPECT_EQ(back.dimension, 2);
  EXPECT_EQ(describe_set(from_halfspaces(back.system)), describe_set(square));
  std::ostringstream points;
  write_plain_points(points, square, 2);
  EXPECT_EQ(points.str(), "-1 0\n1 0\n1 2\n-1 2\n");
  std::istringstream points_in(points.str());
  const PointFile read_back = read_plain_points(points_in);
  EXPECT_EQ(read_back.dimension, 2);
  EXPECT_EQ(read_back.points, square.vertices());
  // A vertex off the plane cannot go into a file of the plane.
  std::ostringstream ignored;
  EXPECT_THROW(write_cdd_points(ignored, ConvexSet::point({0, 0, 1}), 2), Error);
}

TEST(CddFormat, VRepresentationRefusesRaysAndLines) {
  const auto points = [](const std::string& text) {
    std::istringstream in(text);
    return read_cdd_points(in, "p.ext");
  };
  EXPECT_EQ(points("V-representation\nbegin\n2 4 rational\n1 1/2 0 0\n1 0 0 1\nend\n").size(), 2u);
  EXPECT_THROW((void)points("V-representation\nbegin\n1 4 integer\n0 1 0 0\nend\n"), Error);
  EXPECT_THROW((void)points("linearity 1 1\nV-representation\nbegin\n1 4 integer\n1 1 0 0\nend\n"), Error);
  EXPECT_THROW((void)points("H-representation\nbegin\n1 4 integer\n1 1 0 0\nend\n"), Error);
}

TEST(PlainFormat, RowsAreAxPlusByPlusCzAtMostD) {
  const HalfspaceSystem s = parse("# the cube\n1 0 0 1\n-1 0 0 1  # x >= -1\n0 1 0 1\n0 -1 0 1\n0 0 1 1\n0 0 -1 1\n\n",
                                  HalfspaceFormat::plain);
  EXPECT_EQ(s.inequalities.size(), 6u);
  EXPECT_EQ(describe_set(from_halfspaces(s)), describe_set(ConvexSet(shapes::box(v3(-1, -1, -1), v3(1, 1, 1)))));
}

// A stream buffer that takes no byte, as a full disk or a string that
// cannot grow: the stream swallows the failure into its badbit.
class RefusingBuffer : public std::streambuf {
 protected:
  int_type overflow(int_type /*c*/) override { return traits_type::eof(); }
};

// Regression: the row and point writers returned normally on a stream that
// had failed, so that lost output (a buffer that could not grow in memory)
// looked written.
TEST(Writers, LostOutputIsAnIoError) {
  const ConvexSet cube = shapes::box(v3(-1, -1, -1), v3(1, 1, 1));
  const HalfspaceSystem rows = to_halfspaces(cube);
  const auto expect_io_error = [](const auto& write) {
    RefusingBuffer refusing;
    std::ostream out(&refusing);
    try {
      write(out);
      ADD_FAILURE() << "no error for lost output";
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::io) << e.what();
      EXPECT_NE(std::string(e.what()).find("writing the output failed"), std::string::npos) << e.what();
    }
  };
  expect_io_error([&](std::ostream& out) { write_halfspaces(out, rows, HalfspaceFormat::cdd); });
  expect_io_error([&](std::ostream& out) { write_halfspaces(out, rows, HalfspaceFormat::plain); });
  const std::array<Vec3, 3> triangle{v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0)};
  const HalfspaceSystem plane_rows = to_halfspaces(ConvexSet::polygon(triangle));
  expect_io_error([&](std::ostream& out) { write_halfspaces(out, plane_rows, HalfspaceFormat::cdd, 2); });
  expect_io_error([&](std::ostream& out) { write_cdd_points(out, cube); });
  expect_io_error([&](std::ostream& out) { write_plain_points(out, cube); });
}

}  // namespace
}  // namespace cvms
