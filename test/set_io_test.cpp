// SPDX-License-Identifier: MIT
// Convex sets in files: every dimension written and read back exactly (OFF,
// OBJ; STL for polygons), a flat OBJ as a modelling tool exports it (every
// z = 0, a few hundred vertices, fan-triangulated) read as the polygon,
// points-only files through the hull, and errors that name the file.
#include "cvms/set_io.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "cvms/error.hpp"
#include "cvms/io.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/set_sum.hpp"
#include "cvms/shapes.hpp"
#include "support/hand_solids.hpp"
#include "support/io_expect.hpp"
#include "support/set_oracle.hpp"

namespace cvms {
namespace {

using test::file_bytes;
using test::v3;

struct TempDir {
  std::filesystem::path path;
  TempDir() {
    path = std::filesystem::temp_directory_path() /
           ("cvms_set_io_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

void write_text(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

TEST(SetIo, EveryDimensionRoundTrips) {
  TempDir dir;
  const std::vector<ConvexSet> sets{
      ConvexSet(),
      ConvexSet::point({Rational(1, 3), 2, -5}),
      ConvexSet::segment(v3(0, 0, 0), {Rational(1, 10), 7, 1}),
      ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, 0), v3(2, 0, 1), v3(0, 1, 0)}),
      ConvexSet(shapes::truncated_cube()),
  };
  for (const ConvexSet& s : sets)
    for (const char* extension : {".off", ".obj"}) {
      if (s.empty() && extension == std::string(".obj")) continue;  // OBJ cannot hold it
      const auto path = dir.path / ("set" + std::to_string(s.dimension() + 1) + extension);
      write_file(path, s);
      EXPECT_EQ(test::describe_set(read_convex_set(path)), test::describe_set(s)) << path;
    }
  // STL: a polygon (fan-triangulated on output) comes back as the polygon.
  const ConvexSet square = ConvexSet::polygon(std::vector<Vec3>{v3(0, 0, 0), v3(4, 0, 0), v3(4, 4, 0), v3(0, 4, 0)});
  write_file(dir.path / "square.stl", square);
  EXPECT_EQ(test::describe_set(read_convex_set(dir.path / "square.stl")), test::describe_set(square));
  EXPECT_THROW(write_file(dir.path / "empty.obj", sets[0]), Error);
  try {
    write_file(dir.path / "point.stl", sets[1]);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
    EXPECT_NE(std::string(e.what()).find("point.stl: STL cannot hold a set of dimension 0"), std::string::npos);
  }
}

// A solid is written straight from its polyhedron (no copy of its
// coordinates into a soup first): the oracle is the soup writer on
// to_soup(), byte for byte, to files and streams, for every format and both
// coordinate modes, on a sum (values in an arena) and on rational,
// non-dyadic coordinates.
TEST(SetIo, SolidsAreWrittenAsTheirSoup) {
  TempDir dir;
  const ConvexPolyhedron sphere = shapes::geodesic_sphere(2);
  Mat3 skew = Mat3::identity();
  skew.m[0][1] = Rational(1, 3);
  skew.m[2][0] = Rational(-2, 7);
  const std::vector<ConvexSet> solids{
      ConvexSet(minkowski_sum(sphere, shapes::rotated_geodesic_sphere(2)).polyhedron),
      ConvexSet(sphere.transformed(skew, {Rational(1, 10), 0, 5}))};
  for (const ConvexSet& solid : solids) {
    ASSERT_EQ(solid.dimension(), 3);
    for (const char* ext : {".off", ".obj", ".stl"}) {
      for (Coordinates c : {Coordinates::exact, Coordinates::double_}) {
        SCOPED_TRACE(std::string(ext) + (c == Coordinates::exact ? " exact" : " double"));
        const auto direct = dir.path / (std::string("direct") + ext);
        const auto via_soup = dir.path / (std::string("soup") + ext);
        write_file(direct, solid, c);
        // In doubles, a text format holds the set rounded as a whole.
        const bool rounded = c != Coordinates::exact && std::string(ext) != ".stl";
        write_file(via_soup, (rounded ? round_to_doubles(solid, FloatMode::nearest) : solid).to_soup(), c);
        const std::string bytes = file_bytes(via_soup);
        EXPECT_GT(bytes.size(), 100u);
        EXPECT_EQ(file_bytes(direct), bytes);
        std::ostringstream streamed;
        write(streamed, solid, format_from_extension(direct), "solid", c);
        EXPECT_EQ(streamed.str(), bytes);
      }
    }
  }
}

// A 2D profile as exported with every z = 0: a 300-gon fanned from its
// centre, plus a solid, summed as the CLI does.
TEST(SetIo, FlatObjFromAModeller) {
  TempDir dir;
  const std::vector<Vec2> circle = shapes::circle_polygon(300);
  std::string obj = "# flat profile\no profile\nv 0 0 0\n";
  for (const Vec2& p : circle) obj += "v " + to_string(p.x) + " " + to_string(p.y) + " 0\n";
  for (std::size_t i = 0; i < circle.size(); ++i)
    obj += "f 1 " + std::to_string(i + 2) + " " + std::to_string((i + 1) % circle.size() + 2) + "\n";
  write_text(dir.path / "profile.obj", obj);
  const ConvexSet profile = read_convex_set(dir.path / "profile.obj");
  ASSERT_EQ(profile.dimension(), 2);
  EXPECT_EQ(profile.num_vertices(), 300u);
  EXPECT_EQ(profile.normal(), v3(0, 0, 1));
  const ConvexSet solid = ConvexSet(shapes::random_hull(7, 30, 5));
  const ConvexSet sum = minkowski_sum(profile, solid);
  EXPECT_EQ(test::describe_set(sum), test::sum_oracle(profile, solid));
}

TEST(SetIo, PointFilesGoThroughTheHull) {
  TempDir dir;
  write_text(dir.path / "line.xyz", "# three points on a line\n0 0 0\n1 1 1\n\n1/2 1/2 1/2\n");
  const ConvexSet line = read_convex_set(dir.path / "line.xyz");
  EXPECT_EQ(line.vertices(), (std::vector<Vec3>{v3(0, 0, 0), v3(1, 1, 1)}));
  write_text(dir.path / "flat.off", "OFF\n4 0 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n");
  EXPECT_EQ(read_convex_set(dir.path / "flat.off").dimension(), 2);
}

TEST(SetIo, ErrorsNameTheFile) {
  TempDir dir;
  write_text(dir.path / "bent.off", "OFF\n4 1 0\n0 0 0\n4 0 0\n1 1 0\n0 4 0\n4 0 1 2 3\n");
  try {
    (void)read_convex_set(dir.path / "bent.off");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::not_convex);
    EXPECT_NE(std::string(e.what()).find("bent.off: face 0: polygon: vertex 2 is a reflex corner"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW((void)read_convex_set(dir.path / "missing.xyz"), Error);
}

}  // namespace
}  // namespace cvms
