// SPDX-License-Identifier: MIT
// Writers (exact bytes against hand-written text, exact round trips, float
// rounding and normals of binary STL, determinism), format dispatch, file
// errors, the polyhedron-level read_polyhedron and write_file (every error
// names the file), Error::message and read_points.
#include "cvms/io.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <locale>
#include <random>
#include <sstream>

#include "cvms/minkowski.hpp"
#include "cvms/shapes.hpp"
#include "support/io_expect.hpp"

namespace cvms {
namespace {

using test::data_path;
using test::file_bytes;
using test::faces_of;
using test::make_soup;
using test::throws_error;
using test::v3;
using Faces = std::vector<std::vector<std::uint32_t>>;

Rational pow2(int e) {
  mpz_class p;
  mpz_ui_pow_ui(p.get_mpz_t(), 2, static_cast<unsigned long>(e < 0 ? -e : e));
  return e < 0 ? Rational(mpz_class(1), p) : Rational(p);
}

std::string written(const PolygonSoup& soup, FileFormat format, Coordinates c = Coordinates::exact) {
  std::ostringstream out;
  write(out, soup, format, c);
  return out.str();
}

PolygonSoup reread(const std::string& bytes, FileFormat format) {
  std::istringstream in(bytes);
  return read(in, format, "roundtrip");
}

// A temporary directory removed at the end of the test.
struct TempDir {
  std::filesystem::path path;
  TempDir() {
    path = std::filesystem::temp_directory_path() /
           ("cvms_io_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

// ---- dispatch and files -----------------------------------------------------

TEST(Io, FormatFromExtension) {
  EXPECT_EQ(format_from_extension("a/b/cube.off"), FileFormat::off);
  EXPECT_EQ(format_from_extension("CUBE.OBJ"), FileFormat::obj);
  EXPECT_EQ(format_from_extension("x.Stl"), FileFormat::stl);
  EXPECT_TRUE(throws_error([] { format_from_extension("points.xyz"); }, ErrorCategory::invalid_argument,
                           {"points.xyz", ".off"}));
  EXPECT_TRUE(
      throws_error([] { format_from_extension("noext"); }, ErrorCategory::invalid_argument, {"noext"}));
}

TEST(Io, ReadFileErrors) {
  EXPECT_TRUE(throws_error([] { read_file(data_path("does_not_exist.off")); }, ErrorCategory::io,
                           {"does_not_exist.off"}));
  TempDir dir;
  std::filesystem::create_directory(dir.path / "folder.off");
  EXPECT_TRUE(throws_error([&] { read_file(dir.path / "folder.off"); }, ErrorCategory::io,
                           {"folder.off", "directory"}));
  EXPECT_TRUE(throws_error([] { read_file(data_path("points.xyz")); }, ErrorCategory::invalid_argument,
                           {"points.xyz"}));
}

TEST(Io, ReadDispatchesOnFormat) {
  std::ifstream in(data_path("cube.obj"), std::ios::binary);
  EXPECT_EQ(read(in, FileFormat::obj, "cube.obj").num_faces(), 6u);
  std::istringstream off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(faces_of(read(off, FileFormat::off, "x")), (Faces{{0, 1, 2}}));
}

TEST(Io, StreamsWithExceptionsEnabledAndAnUnlimitedByteCap) {
  std::istringstream in("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  in.exceptions(std::ios::failbit | std::ios::badbit | std::ios::eofbit);
  PolygonSoup soup = read_off(in, "x", ReadLimits{.max_bytes = std::numeric_limits<std::uint64_t>::max()});
  EXPECT_EQ(faces_of(soup), (Faces{{0, 1, 2}}));
}

TEST(Io, Utf8ByteOrderMarkIsSkipped) {
  std::istringstream off("\xEF\xBB\xBFOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(read_off(off, "bom.off").points.size(), 3u);
  std::istringstream obj("\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(read_obj(obj, "bom.obj").num_faces(), 1u);
  std::istringstream stl("\xEF\xBB\xBFsolid x\nendsolid x\n");
  EXPECT_EQ(read_stl(stl, "bom.stl").num_faces(), 0u);
}

// ---- writers: exact bytes ---------------------------------------------------

PolygonSoup small_soup() {
  return make_soup({v3(0, Rational(1, 3), Rational(-5, 2)), v3(Rational(1, 1000000), 12, Rational(7, 8)),
                    v3(0, 0, 1), v3(1, 1, 1)},
                   {{0, 1, 2}, {0, 2, 3, 1}});
}

TEST(WriteOff, ExactText) {
  EXPECT_EQ(written(small_soup(), FileFormat::off),
            "OFF\n4 2 0\n0 1/3 -2.5\n0.000001 12 0.875\n0 0 1\n1 1 1\n3 0 1 2\n4 0 2 3 1\n");
}

TEST(WriteOff, DoubleTextIsShortestRoundTrip) {
  mpz_class ten300;
  mpz_ui_pow_ui(ten300.get_mpz_t(), 10, 300);
  PolygonSoup soup = make_soup({v3(Rational(1, 10), Rational(1, 3), Rational(ten300)),
                                v3(-2, Rational(1, 1024), 0), v3(Rational(5e-324), 0, 1)},
                               {{0, 1, 2}});
  EXPECT_EQ(written(soup, FileFormat::off, Coordinates::double_),
            "OFF\n3 1 0\n0.1 0.3333333333333333 1e+300\n-2 0.0009765625 0\n5e-324 0 1\n3 0 1 2\n");
  // The text reads back exactly as the printed decimals, each of which has
  // the written double as its nearest double.
  PolygonSoup back = reread(written(soup, FileFormat::off, Coordinates::double_), FileFormat::off);
  EXPECT_EQ(back.points[0],
            v3(Rational(1, 10), Rational(3333333333333333, 10000000000000000), Rational(ten300)));
  EXPECT_EQ(back.points[1], soup.points[1]);
  EXPECT_EQ(back.points[2].x.get_d(), 5e-324);
}

TEST(WriteObj, ExactAndDoubleText) {
  EXPECT_EQ(written(small_soup(), FileFormat::obj),
            "v 0 1/3 -2.5\nv 0.000001 12 0.875\nv 0 0 1\nv 1 1 1\nf 1 2 3\nf 1 3 4 2\n");
  EXPECT_EQ(written(small_soup(), FileFormat::obj, Coordinates::double_),
            "v 0 0.3333333333333333 -2.5\nv 1e-06 12 0.875\nv 0 0 1\nv 1 1 1\nf 1 2 3\nf 1 3 4 2\n");
}

// ---- writers: exact round trips ---------------------------------------------

Rational random_rational(std::mt19937_64& rng) {
  switch (rng() % 5) {
    case 0:
      return Rational(static_cast<long>(rng() % 2001) - 1000);
    case 1: {  // a large p/q
      mpz_class p, q;
      mpz_ui_pow_ui(p.get_mpz_t(), 3, 50 + rng() % 100);
      mpz_ui_pow_ui(q.get_mpz_t(), 7, 1 + rng() % 80);
      Rational r(p + static_cast<unsigned long>(rng() % 1000), q);
      r.canonicalize();
      return rng() % 2 ? r : Rational(-r);
    }
    case 2: {  // a decimal with many digits and a big exponent
      mpz_class ten;
      mpz_ui_pow_ui(ten.get_mpz_t(), 10, rng() % 500);
      Rational r(mpz_class(static_cast<unsigned long>(rng() % 1000000007)), ten);
      r.canonicalize();
      return rng() % 2 ? r : Rational(r.get_num() * ten * ten);
    }
    case 3: {  // a random finite double
      std::uint64_t bits = (rng() & ~(std::uint64_t{0x7ff} << 52)) | (std::uint64_t{rng() % 2046 + 1} << 52);
      return rational_from_double(std::bit_cast<double>(bits));
    }
    default: {
      Rational r(static_cast<long>(rng() % 100) - 50, static_cast<long>(rng() % 99) + 1);
      r.canonicalize();
      return r;
    }
  }
}

PolygonSoup random_soup(std::mt19937_64& rng) {
  PolygonSoup soup;
  const std::size_t n = 3 + rng() % 40;
  for (std::size_t i = 0; i < n; ++i)
    soup.points.push_back({random_rational(rng), random_rational(rng), random_rational(rng)});
  const std::size_t faces = rng() % 30;
  for (std::size_t f = 0; f < faces; ++f) {
    std::vector<std::uint32_t> face(3 + rng() % 5);
    for (auto& i : face) i = static_cast<std::uint32_t>(rng() % n);
    soup.add_face(face);
  }
  return soup;
}

TEST(RoundTrip, ExactOffAndObjAreIdentical) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    PolygonSoup soup = random_soup(rng);
    for (FileFormat format : {FileFormat::off, FileFormat::obj}) {
      PolygonSoup back = reread(written(soup, format), format);
      EXPECT_EQ(back.points, soup.points);
      EXPECT_EQ(faces_of(back), faces_of(soup));
    }
  }
}

TEST(RoundTrip, DoubleOffAndObjKeepTheNearestDouble) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    PolygonSoup soup = random_soup(rng);
    for (Vec3& p : soup.points)  // keep within the double range
      for (int i = 0; i < 3; ++i)
        if (abs(p[i]) > Rational(1e300) || (p[i] != 0 && abs(p[i]) < Rational(1e-300))) p[i] = Rational(1, 3);
    for (FileFormat format : {FileFormat::off, FileFormat::obj}) {
      PolygonSoup back = reread(written(soup, format, Coordinates::double_), format);
      ASSERT_EQ(back.points.size(), soup.points.size());
      for (std::size_t v = 0; v < soup.points.size(); ++v)
        for (int i = 0; i < 3; ++i) {
          // The text read back is a short decimal; the double nearest to it must be
          // the double nearest to the original: no double lies strictly closer to
          // the original than it, checked against both neighbours exactly.
          const Rational& exact = soup.points[v][i];
          double d = to_double_nearest(back.points[v][i]);
          Rational err = abs(exact - Rational(d));
          EXPECT_LE(err, abs(exact - Rational(std::nextafter(d, INFINITY))));
          EXPECT_LE(err, abs(exact - Rational(std::nextafter(d, -INFINITY))));
        }
      EXPECT_EQ(faces_of(back), faces_of(soup));
    }
  }
}

// ---- binary STL writer ------------------------------------------------------

float float_at(const std::string& bytes, std::size_t at) {
  std::uint32_t bits = 0;
  for (int i = 3; i >= 0; --i)
    bits = (bits << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
  return std::bit_cast<float>(bits);
}

TEST(WriteStl, LayoutFanTriangulationAndExactFloats) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<float> coordinate(-1000.0f, 1000.0f);
  std::vector<Vec3> points;
  for (int i = 0; i < 12; ++i)
    points.push_back({rational_from_float(coordinate(rng)), rational_from_float(coordinate(rng)),
                      rational_from_float(coordinate(rng))});
  PolygonSoup soup = make_soup(points, {{0, 1, 2}, {3, 4, 5, 6}, {7, 8, 9, 10, 11}, {0, 5, 11}});
  const std::string bytes = written(soup, FileFormat::stl);
  const std::size_t triangles = 1 + 2 + 3 + 1;
  ASSERT_EQ(bytes.size(), 84 + 50 * triangles);
  EXPECT_NE(bytes.substr(0, 5), "solid");
  EXPECT_EQ(static_cast<unsigned char>(bytes[80]), triangles);
  // The fan of each face, by position (vertex numbering may change on reading).
  std::vector<std::array<Vec3, 3>> expected;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto face = soup.face(f);
    for (std::size_t k = 1; k + 1 < face.size(); ++k)
      expected.push_back({points[face[0]], points[face[k]], points[face[k + 1]]});
  }
  PolygonSoup back = reread(bytes, FileFormat::stl);
  ASSERT_EQ(back.num_faces(), triangles);
  EXPECT_EQ(back.points.size(), 12u);  // shared corners merged again
  for (std::size_t t = 0; t < triangles; ++t) {
    auto face = back.face(t);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(back.points[face[k]], expected[t][k]) << "triangle " << t;
  }
}

TEST(WriteStl, NormalsAreUnitAndSurviveExtremeScales) {
  PolygonSoup soup =
      make_soup({v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 1), v3(1, -1, 0), v3(Rational(1e30), 0, 0),
                 v3(0, Rational(1e30), 0), v3(Rational(1e-30), 0, 0), v3(0, Rational(1e-30), 0), v3(2, 0, 0)},
                {{0, 1, 2}, {0, 3, 4}, {0, 5, 6}, {0, 7, 8}, {0, 1, 9}});
  const std::string bytes = written(soup, FileFormat::stl);
  auto normal = [&bytes](std::size_t t) {
    std::size_t at = 84 + 50 * t;
    return std::array<float, 3>{float_at(bytes, at), float_at(bytes, at + 4), float_at(bytes, at + 8)};
  };
  const float h = std::sqrt(0.5f);
  EXPECT_EQ(normal(0), (std::array<float, 3>{0.0f, 0.0f, 1.0f}));
  EXPECT_EQ(normal(1), (std::array<float, 3>{h, h, 0.0f}));
  EXPECT_EQ(normal(2), (std::array<float, 3>{0.0f, 0.0f, 1.0f}));  // the exact cross product is 1e60
  EXPECT_EQ(normal(3), (std::array<float, 3>{0.0f, 0.0f, 1.0f}));  // and 1e-60 here
  EXPECT_EQ(normal(4), (std::array<float, 3>{0.0f, 0.0f, 0.0f}));  // degenerate
  // Attribute bytes are zero.
  EXPECT_EQ(bytes[84 + 48], '\0');
  EXPECT_EQ(bytes[84 + 49], '\0');
}

TEST(WriteStl, CoordinatesRoundToNearestFloatWithoutDoubleRounding) {
  // 1 + 2^-24 + 2^-60 rounds to the double 1 + 2^-24, a float tie that would
  // go to 1; the exact value is above the tie, so the nearest float is 1 + 2^-23.
  const Rational above_tie = 1 + pow2(-24) + pow2(-60);
  const Rational tie_down = 1 + pow2(-24);                  // tie: even is 1
  const Rational tie_up = 1 + 3 * pow2(-24);                // tie: even is 1 + 2^-22
  const Rational near_max = Rational(FLT_MAX) + pow2(102);  // below FLT_MAX + ulp/2
  PolygonSoup soup =
      make_soup({v3(above_tie, tie_down, tie_up), v3(near_max, 0, 0), v3(0, 0, Rational(1, 3))}, {{0, 1, 2}});
  PolygonSoup back = reread(written(soup, FileFormat::stl), FileFormat::stl);
  EXPECT_EQ(back.points[0], v3(1 + pow2(-23), 1, 1 + pow2(-22)));
  EXPECT_EQ(back.points[1], v3(Rational(FLT_MAX), 0, 0));
  EXPECT_EQ(back.points[2], v3(0, 0, Rational(11184811) * pow2(-25)));
}

// ---- writer preconditions and failures --------------------------------------

TEST(Write, RejectsInvalidSoupsAndUnrepresentableValues) {
  PolygonSoup out_of_range = make_soup({v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0)}, {{0, 1, 3}});
  PolygonSoup two_gon = make_soup({v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0)}, {{0, 1}});
  PolygonSoup broken_offsets = make_soup({v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0)}, {{0, 1, 2}});
  broken_offsets.face_offsets.back() = 7;
  // Offsets that rise past the indices and come back to their count: the
  // first face would read beyond them (ASan checks that nothing is read).
  PolygonSoup overshooting = make_soup({v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0)}, {{0, 1, 2}, {0, 2, 1}});
  overshooting.face_offsets = {0, 10, 6};
  for (FileFormat format : {FileFormat::off, FileFormat::obj, FileFormat::stl}) {
    EXPECT_TRUE(
        throws_error([&] { written(overshooting, format); }, ErrorCategory::invalid_argument, {"offsets"}));
    EXPECT_TRUE(throws_error([&] { written(out_of_range, format); }, ErrorCategory::invalid_argument,
                             {"face 0 has index 3 but there are 3 vertices"}));
    EXPECT_TRUE(
        throws_error([&] { written(two_gon, format); }, ErrorCategory::invalid_argument, {"face 0 has 2"}));
    EXPECT_TRUE(
        throws_error([&] { written(broken_offsets, format); }, ErrorCategory::invalid_argument, {"offsets"}));
  }
  mpz_class ten400;
  mpz_ui_pow_ui(ten400.get_mpz_t(), 10, 400);
  PolygonSoup huge = make_soup({v3(Rational(ten400), 0, 0), v3(1, 0, 0), v3(0, 1, 0)}, {{0, 1, 2}});
  EXPECT_NO_THROW(written(huge, FileFormat::off));
  EXPECT_TRUE(throws_error([&] { written(huge, FileFormat::off, Coordinates::double_); },
                           ErrorCategory::invalid_argument, {"range of double"}));
  PolygonSoup too_big_for_float =
      make_soup({v3(Rational(1e39), 0, 0), v3(1, 0, 0), v3(0, 1, 0)}, {{0, 1, 2}});
  EXPECT_TRUE(throws_error([&] { written(too_big_for_float, FileFormat::stl); },
                           ErrorCategory::invalid_argument, {"range of float"}));
}

TEST(Write, FailingStreamIsAnIoError) {
  std::ostringstream out;
  out.setstate(std::ios::badbit);
  EXPECT_TRUE(throws_error([&] { write_off(out, small_soup()); }, ErrorCategory::io, {"writing"}));
  std::ostringstream throwing;
  throwing.exceptions(std::ios::badbit | std::ios::failbit);
  EXPECT_THROW(throwing.setstate(std::ios::badbit), std::ios_base::failure);
  EXPECT_TRUE(throws_error([&] { write_obj(throwing, small_soup()); }, ErrorCategory::io, {"writing"}));
  EXPECT_TRUE(throws_error([] { write_file("/nonexistent_dir_cvms/x.off", small_soup()); }, ErrorCategory::io,
                           {"/nonexistent_dir_cvms/x.off"}));
  EXPECT_TRUE(
      throws_error([] { write_file("x.ply", small_soup()); }, ErrorCategory::invalid_argument, {"x.ply"}));
}

// A locale that groups digits ("1,234"): stream formatting would pick it up.
struct Grouping : std::numpunct<char> {
  char do_thousands_sep() const override { return ','; }
  std::string do_grouping() const override { return "\3"; }
  char do_decimal_point() const override { return '@'; }
};

TEST(Write, OutputIsDeterministicAndLocaleIndependent) {
  PolygonSoup soup;
  for (int i = 0; i < 1500; ++i) soup.points.push_back({Rational(i, 7), Rational(i * 1000), Rational(i) / 4});
  for (std::uint32_t i = 0; i + 2 < 1500; i += 3) soup.add_face({i, i + 1, i + 2});
  for (FileFormat format : {FileFormat::off, FileFormat::obj, FileFormat::stl})
    for (Coordinates c : {Coordinates::exact, Coordinates::double_}) {
      std::string first = written(soup, format, c);
      EXPECT_EQ(first, written(soup, format, c));
      std::ostringstream grouped;
      grouped.imbue(std::locale(std::locale::classic(), new Grouping));
      write(grouped, soup, format, c);
      EXPECT_EQ(grouped.str(), first);
      EXPECT_EQ(first.find("1,"), std::string::npos);
    }
}

TEST(Write, FilesRoundTripThroughEveryFormat) {
  TempDir dir;
  PolygonSoup soup = make_soup({v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 1)},
                               {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});  // first use in index order
  for (const char* name : {"t.off", "t.obj", "t.stl", "T.OFF"}) {
    SCOPED_TRACE(name);
    write_file(dir.path / name, soup);
    PolygonSoup back = read_file(dir.path / name);
    EXPECT_EQ(back.points, soup.points);
    EXPECT_EQ(faces_of(back), faces_of(soup));
  }
}

// ---- polyhedra: read_polyhedron, write_file, to_polyhedron, Error::message ---

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// An octahedron whose top vertex is pushed below the equator: reflex edges.
const char* const dented_octahedron =
    "OFF\n6 8 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n0 0 -1/2\n0 0 -1\n"
    "3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n3 1 0 5\n3 2 1 5\n3 3 2 5\n3 0 3 5\n";
// A cube without its top: an open surface.
const char* const open_cube =
    "OFF\n8 5 0\n-1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n"
    "4 0 3 2 1\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

void expect_same_polyhedron(const ConvexPolyhedron& got, const ConvexPolyhedron& expected) {
  const PolygonSoup a = got.to_soup();
  const PolygonSoup b = expected.to_soup();
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(faces_of(a), faces_of(b));
}

TEST(ErrorMessage, IsWhatWithoutTheCategoryPrefix) {
  const Error e(ErrorCategory::not_convex, "cube.off: reflex edge (0, 4)");
  EXPECT_STREQ(e.what(), "not_convex: cube.off: reflex edge (0, 4)");
  EXPECT_STREQ(e.message(), "cube.off: reflex edge (0, 4)");
  EXPECT_STREQ(Error(ErrorCategory::invalid_argument, "").message(), "");
}

// The soup a polyhedron is written as: its own, or in doubles (text formats)
// that of the set rounded as a whole (float_modes_test checks the rounding).
PolygonSoup soup_written_for(const ConvexPolyhedron& p, FileFormat format, Coordinates c) {
  if (c == Coordinates::exact || format == FileFormat::stl) return p.to_soup();
  return round_to_doubles(p, FloatMode::nearest).to_soup();
}

// write_file of a polyhedron writes from its mesh without copying it into a
// soup; the oracle is the soup writer on to_soup() (in doubles, on the
// rounded set's), byte for byte, for every format and both coordinate
// modes, on a sum (whose values live in an arena) and on a polyhedron with
// rational, non-dyadic coordinates; so does the stream writer.
TEST(Write, PolyhedronIsWrittenAsItsSoup) {
  TempDir dir;
  const ConvexPolyhedron sphere = shapes::geodesic_sphere(2);
  const ConvexPolyhedron sum = minkowski_sum(sphere, shapes::rotated_geodesic_sphere(2)).polyhedron;
  Mat3 skew = Mat3::identity();
  skew.m[0][1] = Rational(1, 3);
  skew.m[2][0] = Rational(-2, 7);
  const ConvexPolyhedron rational = sphere.transformed(skew, {Rational(1, 10), 0, 5});
  for (const ConvexPolyhedron* p : {&sum, &rational}) {
    for (const char* ext : {".off", ".obj", ".stl"}) {
      for (Coordinates c : {Coordinates::exact, Coordinates::double_}) {
        SCOPED_TRACE(std::string(ext) + (c == Coordinates::exact ? " exact" : " double"));
        const auto direct = dir.path / (std::string("direct") + ext);
        const auto via_soup = dir.path / (std::string("soup") + ext);
        const FileFormat format = format_from_extension(direct);
        const PolygonSoup soup = soup_written_for(*p, format, c);
        write_file(direct, *p, c);
        write_file(via_soup, soup, c);
        const std::string bytes = file_bytes(direct);
        EXPECT_GT(bytes.size(), 100u);
        EXPECT_EQ(bytes, file_bytes(via_soup));
        // The stream writer.
        std::ostringstream streamed, soup_streamed;
        write(streamed, *p, format, c);
        write(soup_streamed, soup, format, c);
        EXPECT_EQ(streamed.str(), bytes);
        EXPECT_EQ(soup_streamed.str(), bytes);
      }
    }
  }
}

TEST(ReadPolyhedron, IsReadFileThenFromSoup) {
  for (const char* name : {"cube.off", "cube.obj", "tetra_ascii.stl", "tetra_exact.off"}) {
    SCOPED_TRACE(name);
    expect_same_polyhedron(read_polyhedron(data_path(name)),
                           ConvexPolyhedron::from_soup(read_file(data_path(name))));
  }
  const ConvexPolyhedron cube = read_polyhedron(data_path("cube.off"));
  EXPECT_EQ(cube.num_vertices(), 8u);
  EXPECT_EQ(cube.num_edges(), 12u);
  EXPECT_EQ(cube.num_facets(), 6u);
  EXPECT_TRUE(throws_error([] { read_polyhedron(data_path("cube.off"), ReadLimits{.max_vertices = 7}); },
                           ErrorCategory::limit, {"cube.off"}));
}

TEST(ReadPolyhedron, EveryErrorNamesTheFileOnce) {
  TempDir dir;
  const std::filesystem::path dented = dir.path / "dented.off";
  const std::filesystem::path open = dir.path / "open.off";
  write_text(dented, dented_octahedron);
  write_text(open, open_cube);
  // from_soup's errors get the file name in front, the category first.
  EXPECT_TRUE(throws_error([&] { read_polyhedron(dented); }, ErrorCategory::not_convex,
                           {"not_convex: " + dented.string() + ": reflex edge"}));
  EXPECT_TRUE(throws_error([&] { read_polyhedron(open); }, ErrorCategory::topology,
                           {"topology: " + open.string() + ": ", "boundary edge"}));
  // The reader's and read_file's errors already name it: not a second time.
  const std::filesystem::path truncated = data_path("bad/truncated_faces.off");
  const std::filesystem::path missing = dir.path / "missing.off";
  struct Case {
    std::filesystem::path path;
    ErrorCategory category;
  };
  for (const Case& c : {Case{truncated, ErrorCategory::parse}, Case{missing, ErrorCategory::io},
                        Case{dir.path, ErrorCategory::invalid_argument}}) {
    SCOPED_TRACE(c.path.string());
    EXPECT_TRUE(throws_error([&] { read_polyhedron(c.path); }, c.category, {c.path.string()}));
    try {
      read_polyhedron(c.path);
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.find(c.path.string()), what.rfind(c.path.string())) << what;
    }
  }
  EXPECT_TRUE(
      throws_error([&] { read_polyhedron(truncated); }, ErrorCategory::parse, {truncated.string() + ":"}));
}

TEST(ToPolyhedron, NamesTheSource) {
  std::istringstream in(dented_octahedron);
  PolygonSoup soup = read_off(in, "<stdin>");
  EXPECT_TRUE(throws_error([&] { to_polyhedron(std::move(soup), "<stdin>"); }, ErrorCategory::not_convex,
                           {"not_convex: <stdin>: reflex edge"}));
  EXPECT_EQ(to_polyhedron(read_file(data_path("cube.off")), "cube").num_facets(), 6u);
}

TEST(WriteFilePolyhedron, ExactOffAndObjReadBackAsTheSamePolyhedron) {
  TempDir dir;
  // 1/3 has no finite decimal, 1e400 no double: both must survive exactly.
  const ConvexPolyhedron cube = read_polyhedron(data_path("cube.off")).translated(v3(Rational(1, 3), 0, 0));
  const ConvexPolyhedron tetra = read_polyhedron(data_path("tetra_exact.off"));
  for (const ConvexPolyhedron* p : {&cube, &tetra})
    for (const char* name : {"p.off", "p.obj", "P.OFF"}) {
      SCOPED_TRACE(name);
      write_file(dir.path / name, *p);
      expect_same_polyhedron(read_polyhedron(dir.path / name), *p);
    }
  // Rounded coordinates: the hull of the nearest doubles, here a box again.
  for (const char* name : {"d.off", "d.obj"}) {
    SCOPED_TRACE(name);
    write_file(dir.path / name, cube, Coordinates::double_);
    const ConvexPolyhedron back = read_polyhedron(dir.path / name);
    EXPECT_EQ(back.num_vertices(), 8u);
    EXPECT_EQ(back.num_facets(), 6u);
    const auto points = back.to_soup().points;
    EXPECT_TRUE(std::any_of(points.begin(), points.end(),
                            [](const Vec3& v) { return to_double_nearest(v.x) == 1.0 / 3.0; }));
  }
  // STL: float32, fan-triangulated; read back, coplanar triangles merge again.
  write_file(dir.path / "d.stl", cube);
  const ConvexPolyhedron back = read_polyhedron(dir.path / "d.stl");
  EXPECT_EQ(back.num_vertices(), 8u);
  EXPECT_EQ(back.num_facets(), 6u);
}

TEST(WriteFilePolyhedron, ErrorsNameTheFile) {
  const ConvexPolyhedron cube = read_polyhedron(data_path("cube.off"));
  EXPECT_TRUE(throws_error([&] { write_file("/nonexistent_dir_cvms/p.off", cube); }, ErrorCategory::io,
                           {"/nonexistent_dir_cvms/p.off"}));
  EXPECT_TRUE(throws_error([&] { write_file("p.wrl", cube); }, ErrorCategory::invalid_argument, {"p.wrl"}));
  TempDir dir;
  const std::filesystem::path off = dir.path / "huge.off";
  const std::filesystem::path stl = dir.path / "huge.stl";
  const ConvexPolyhedron beyond_double = cube.translated(v3(pow2(1100), 0, 0));
  const ConvexPolyhedron beyond_float = cube.translated(v3(pow2(200), 0, 0));
  EXPECT_TRUE(throws_error([&] { write_file(off, beyond_double, Coordinates::double_); },
                           ErrorCategory::invalid_argument,
                           {"invalid_argument: " + off.string() + ": ", "range of double"}));
  EXPECT_TRUE(throws_error([&] { write_file(stl, beyond_float); }, ErrorCategory::invalid_argument,
                           {"invalid_argument: " + stl.string() + ": ", "range of float"}));
  // Exact output has no range: the same polyhedron is written and read back.
  write_file(off, beyond_double);
  expect_same_polyhedron(read_polyhedron(off), beyond_double);
}

// ---- read_points ------------------------------------------------------------

std::vector<Vec3> points_from(const std::string& text, const ReadLimits& limits = {}) {
  std::istringstream in(text);
  return read_points(in, "pts", limits);
}

TEST(ReadPoints, XyzLinesWithComments) {
  std::ifstream in(data_path("points.xyz"), std::ios::binary);
  EXPECT_EQ(read_points(in, "points.xyz"),
            (std::vector<Vec3>{v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, Rational(1, 3)),
                               v3(Rational(1, 4), Rational(1, 4), Rational(1, 4))}));
}

TEST(ReadPoints, OffAndObjVertices) {
  EXPECT_EQ(points_from("# comment first\nOFF\n2 0 0\n1 2 3\n4 5 6\n"),
            (std::vector<Vec3>{v3(1, 2, 3), v3(4, 5, 6)}));
  EXPECT_EQ(points_from("\nv 1 2 3\nv 4 5 6\n"), (std::vector<Vec3>{v3(1, 2, 3), v3(4, 5, 6)}));
  std::ifstream in(data_path("cube.off"), std::ios::binary);
  EXPECT_EQ(read_points(in, "cube.off").size(), 8u);
}

TEST(ReadPoints, BadLines) {
  EXPECT_TRUE(throws_error([] { points_from("0 0 0\n1 1\n"); }, ErrorCategory::parse,
                           {"pts:2:", "missing z coordinate of point 1"}));
  EXPECT_TRUE(throws_error([] { points_from("0 0 0\n1 1 1 1\n"); }, ErrorCategory::parse,
                           {"pts:2:", "point 1 has more than 3 values"}));
  EXPECT_TRUE(
      throws_error([] { points_from("#\n\n0 inf 0\n"); }, ErrorCategory::parse, {"pts:3:", "not finite"}));
  EXPECT_TRUE(throws_error([] { points_from(""); }, ErrorCategory::parse, {"pts: empty input"}));
  EXPECT_TRUE(throws_error([] { points_from("# only\n\n"); }, ErrorCategory::parse, {"pts:2:", "no points"}));
  EXPECT_TRUE(throws_error([] { points_from("0 0 0\n1 1 1\n", ReadLimits{.max_vertices = 1}); },
                           ErrorCategory::limit, {"pts:2:"}));
  EXPECT_TRUE(throws_error([] { points_from("OFF\n2 0 0\n1 2 3\n"); }, ErrorCategory::parse,
                           {"pts:3:", "2 vertices but only 1"}));
}

// A '#' inside "1.#INF" must not start a comment: an OFF with z = 1.#INF
// would pass as a tetrahedron with z = 1.
TEST(Io, MsvcInfinitiesAreRefusedInEveryReader) {
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  for (std::string token : {"1.#INF", "-1.#INF", "1.#IND", "-1.#IND", "1.#QNAN", "1.#SNAN", "1.#inf",
                            "-1.#ind00", "1.#QNaN0", "+1.#INF00", "12.#INF"}) {
    SCOPED_TRACE(token);
    std::istringstream off("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 " + token + "\n" + faces);
    EXPECT_TRUE(throws_error([&] { read_off(off, "t.off"); }, ErrorCategory::parse,
                             {"t.off:6:", "z coordinate of vertex 3 is not finite: '" + token + "'"}));
    std::istringstream obj("v 0 0 " + token + " # comment\n");
    EXPECT_TRUE(throws_error([&] { read_obj(obj, "t.obj"); }, ErrorCategory::parse,
                             {"t.obj:1:", "z coordinate of vertex 1 is not finite"}));
    EXPECT_TRUE(throws_error([&] { points_from("0 0 0\n" + token + " 1 1\n"); }, ErrorCategory::parse,
                             {"pts:2:", "x coordinate of point 1 is not finite"}));
    std::istringstream stl("solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex " + token +
                           " 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n");
    EXPECT_TRUE(throws_error([&] { read_stl(stl, "t.stl"); }, ErrorCategory::parse,
                             {"t.stl:5:", "x coordinate of vertex 1 of facet 0 is not finite"}));
  }
  // Comments right after a number, and '#' words that are no MSVC spelling, stay comments.
  EXPECT_EQ(points_from("1 2 3#info\n1 2 3.#comment\n1 2 3.# INF\n"),
            (std::vector<Vec3>{v3(1, 2, 3), v3(1, 2, 3), v3(1, 2, 3)}));
}

}  // namespace
}  // namespace cvms

namespace cvms {
namespace {

// What writing p gives in `format` and `mode`.
std::string written(const ConvexPolyhedron& p, FileFormat format, Coordinates mode) {
  std::ostringstream out;
  write(out, p, format, mode);
  return out.str();
}

// A sum keeps its vertices packed and is written straight from them
// (lib/io/soup_view.hpp), without a Rational per coordinate: the text must be
// what writing its soup gives (Vec3s, the Rational printer), in every format
// and mode, also for coordinates whose numerators take several limbs and
// whose denominators are past 2^64 (the packing's long path).
TEST(Write, ASumIsWrittenAsItsSoupIs) {
  const ConvexPolyhedron a = shapes::geodesic_sphere(2);
  const Rational tiny(mpq_class(1, 1) / mpq_class(mpz_class(1) << 100));
  const Rational huge(mpz_class(1) << 90);
  for (const Vec3& shift : {Vec3{0, 0, 0}, Vec3{tiny, -tiny, 3 * tiny}, Vec3{huge, tiny, -huge}}) {
    const ConvexPolyhedron b = shapes::rotated_geodesic_sphere(2).translated(shift);
    for (const unsigned threads : {1u, 2u}) {
      Options options;
      options.threads = threads;
      const ConvexPolyhedron sum = minkowski_sum(a, b, options).polyhedron;
      for (const FileFormat format : {FileFormat::off, FileFormat::obj, FileFormat::stl}) {
        for (const Coordinates mode : {Coordinates::exact, Coordinates::double_}) {
          if (format == FileFormat::stl && mode == Coordinates::exact) continue;  // STL is float32 only
          const std::string direct = written(sum, format, mode);
          EXPECT_EQ(direct, written(soup_written_for(sum, format, mode), format, mode))
              << "shift " << shift.x << ", " << shift.y << ", " << shift.z << "; " << threads << " threads; format "
              << static_cast<int>(format) << ", mode " << static_cast<int>(mode);
        }
      }
    }
  }
}

}  // namespace
}  // namespace cvms
