// SPDX-License-Identifier: MIT
// PLY reader and writer: ASCII and binary bodies of both byte orders built
// byte by byte here (independent of the writer), every numeric type for the
// coordinates, extra properties and elements skipped, exact values checked
// against hand-computed rationals (0.1f is 13421773 / 2^27), round trips
// through the writer, every hostile input with its located error, and the
// bad corpus (test/data/bad/*.ply).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <tuple>

#include "cvms/convex_hull.hpp"
#include "cvms/io.hpp"
#include "cvms/set_io.hpp"
#include "support/io_expect.hpp"

namespace cvms {
namespace {

using test::data_path;
using test::faces_of;
using test::throws_error;
using test::v3;
using Faces = std::vector<std::vector<std::uint32_t>>;

Rational over_pow2(long numerator, int exponent) {
  mpz_class p;
  mpz_ui_pow_ui(p.get_mpz_t(), 2, static_cast<unsigned long>(exponent));
  Rational r(mpz_class(numerator), p);
  r.canonicalize();
  return r;
}

// A PLY body built value by value in a chosen byte order.
class Bytes {
 public:
  explicit Bytes(bool big_endian) : big_(big_endian) {}
  Bytes& text(std::string_view s) {
    out_.append(s);
    return *this;
  }
  Bytes& u(std::uint64_t bits, int size) {
    for (int i = 0; i < size; ++i) {
      const int shift = 8 * (big_ ? size - 1 - i : i);
      out_.push_back(static_cast<char>((bits >> shift) & 0xffu));
    }
    return *this;
  }
  Bytes& i8(std::int8_t v) { return u(static_cast<std::uint8_t>(v), 1); }
  Bytes& u8(std::uint8_t v) { return u(v, 1); }
  Bytes& i16(std::int16_t v) { return u(static_cast<std::uint16_t>(v), 2); }
  Bytes& u16(std::uint16_t v) { return u(v, 2); }
  Bytes& i32(std::int32_t v) { return u(static_cast<std::uint32_t>(v), 4); }
  Bytes& u32(std::uint32_t v) { return u(v, 4); }
  Bytes& f32(float v) { return u(std::bit_cast<std::uint32_t>(v), 4); }
  Bytes& f64(double v) { return u(std::bit_cast<std::uint64_t>(v), 8); }
  [[nodiscard]] const std::string& str() const { return out_; }

 private:
  bool big_;
  std::string out_;
};

PolygonSoup ply_from(const std::string& bytes, const ReadLimits& limits = {}) {
  std::istringstream in(bytes);
  return read_ply(in, "mem.ply", limits);
}

::testing::AssertionResult fails(const std::string& bytes, ErrorCategory category,
                                 std::initializer_list<std::string_view> needles, const ReadLimits& limits = {}) {
  return throws_error([&] { ply_from(bytes, limits); }, category, needles);
}

const std::string tetra_faces_ascii = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
const Faces tetra_faces{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

std::string binary_header(const char* format, const std::string& vertex_properties, std::size_t vertices,
                          const std::string& face_list, std::size_t faces) {
  return std::string("ply\nformat ") + format + " 1.0\nelement vertex " + std::to_string(vertices) + "\n" +
         vertex_properties + "element face " + std::to_string(faces) + "\nproperty " + face_list +
         " vertex_indices\nend_header\n";
}

// ---- ASCII ----

TEST(ReadPly, AsciiExactValuesCommentsAndObjInfo) {
  const std::string text =
      "ply\nformat ascii 1.0\ncomment made by hand\nobj_info anything at all\n"
      "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
      "0.1 0 0\n1 0 0\n0 1e2 0\n0 0 -2.5e-3\n" +
      tetra_faces_ascii;
  const PolygonSoup soup = ply_from(text);
  EXPECT_EQ(soup.points, (std::vector<Vec3>{{Rational(1, 10), 0, 0}, v3(1, 0, 0), v3(0, 100, 0),
                                            {0, 0, Rational(-1, 400)}}));
  EXPECT_EQ(faces_of(soup), tetra_faces);
}

TEST(ReadPly, AsciiCrLfHeaderAndValuesAcrossLines) {
  const std::string text =
      "ply\r\nformat ascii 1.0\r\nelement vertex 4\r\nproperty double x\r\nproperty double y\r\n"
      "property double z\r\nelement face 4\r\nproperty list uchar uint vertex_index\r\nend_header\r\n"
      "0 0\r\n0 1 0 0 0 1 0\r\n0 0 1\r\n" +
      tetra_faces_ascii;
  const PolygonSoup soup = ply_from(text);
  EXPECT_EQ(soup.points, (std::vector<Vec3>{v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 1)}));
  EXPECT_EQ(faces_of(soup), tetra_faces);
}

TEST(ReadPly, AsciiSkipsExtraPropertiesListsAndElements) {
  const std::string text =
      "ply\nformat ascii 1.0\n"
      "element material 1\nproperty uchar red\nproperty list int float weights\n"
      "element vertex 4\nproperty float nx\nproperty float x\nproperty list uchar float extra\n"
      "property float y\nproperty uchar red\nproperty float z\nproperty float confidence\n"
      "element nothing 1000000000000000\n"
      "element face 4\nproperty uchar flags\nproperty list uchar int vertex_indices\n"
      "property list uchar float texcoord\n"
      "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
      "255 3 0.5 1e3 -2\n"
      "nan 0 2 7 8 0 255 0 nan\n"
      "-inf 1 0 0 0 0 0\n"
      "1 0 1 1 1 255 0 0\n"
      "1 0 3 1 2 3 0 0 1 0.25\n"
      "9 3 0 2 1 0\n9 3 0 1 3 6 0 0 1 0 0 1\n9 3 0 3 2 0\n9 3 1 2 3 0\n"
      "0 1\n";
  const PolygonSoup soup = ply_from(text);
  EXPECT_EQ(soup.points, (std::vector<Vec3>{v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 1)}));
  EXPECT_EQ(faces_of(soup), tetra_faces);
}

TEST(ReadPly, AsciiIntegerTypedCoordinatesAndFacesBeforeVertices) {
  const std::string text =
      "ply\nformat ascii 1.0\n"
      "element face 4\nproperty list int8 uint16 vertex_indices\n"
      "element vertex 4\nproperty char x\nproperty ushort y\nproperty int32 z\nend_header\n" +
      tetra_faces_ascii + "-128 0 0\n127 0 0\n0 65535 0\n0 0 -2147483648\n";
  const PolygonSoup soup = ply_from(text);
  EXPECT_EQ(soup.points, (std::vector<Vec3>{v3(-128, 0, 0), v3(127, 0, 0), v3(0, 65535, 0),
                                            {0, 0, Rational(std::numeric_limits<std::int32_t>::min())}}));
  EXPECT_EQ(faces_of(soup), tetra_faces);
}

TEST(ReadPly, PointCloudWithoutFacesAndEmptyVertexElement) {
  PolygonSoup soup = ply_from(
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
      "end_header\n1 2 3\n4 5 6\n");
  EXPECT_EQ(soup.points, (std::vector<Vec3>{v3(1, 2, 3), v3(4, 5, 6)}));
  EXPECT_EQ(soup.num_faces(), 0u);
  soup = ply_from("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                  "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n");
  EXPECT_TRUE(soup.points.empty());
  EXPECT_EQ(soup.num_faces(), 0u);
}

// ---- binary ----

// A tetrahedron in binary, float coordinates between normals and colours,
// in the given byte order.
std::string binary_tetra_float(bool big_endian) {
  Bytes b(big_endian);
  b.text(binary_header(big_endian ? "binary_big_endian" : "binary_little_endian",
                       "property float x\nproperty float nx\nproperty float y\nproperty uchar red\n"
                       "property float z\nproperty list uchar short extra\n",
                       4, "list uchar int", 4));
  const float xyz[4][3] = {{0.1f, 0, 0}, {1, 0, 0}, {0, -3.5f, 0}, {0, 0, 1e-40f}};
  for (const auto& p : xyz) {
    b.f32(p[0]).f32(std::numeric_limits<float>::quiet_NaN()).f32(p[1]).u8(200).f32(p[2]);
    b.u8(2).i16(-1).i16(7);
  }
  for (const auto& f : tetra_faces) {
    b.u8(3);
    for (std::uint32_t i : f) b.i32(static_cast<std::int32_t>(i));
  }
  return b.str();
}

TEST(ReadPly, BinaryFloatBothByteOrdersAreExactDyadics) {
  // 0.1f = 0x3dcccccd = 13421773 / 2^27; 1e-40f is the subnormal 71362 / 2^149.
  const std::vector<Vec3> expected{{over_pow2(13421773, 27), 0, 0},
                                   v3(1, 0, 0),
                                   {0, Rational(-7, 2), 0},
                                   {0, 0, over_pow2(71362, 149)}};
  for (bool big : {false, true}) {
    SCOPED_TRACE(big ? "big endian" : "little endian");
    const PolygonSoup soup = ply_from(binary_tetra_float(big));
    EXPECT_EQ(soup.points, expected);
    EXPECT_EQ(faces_of(soup), tetra_faces);
  }
}

TEST(ReadPly, BinaryDoubleWithUintCountsAndVertexIndexName) {
  for (bool big : {false, true}) {
    SCOPED_TRACE(big ? "big endian" : "little endian");
    Bytes b(big);
    b.text("ply\nformat " + std::string(big ? "binary_big_endian" : "binary_little_endian") +
           " 1.0\nelement vertex 4\nproperty float64 x\nproperty float64 y\nproperty float64 z\n"
           "element face 4\nproperty list uint32 uint32 vertex_index\nproperty double quality\nend_header\n");
    // 0.1 = 0x3fb999999999999a = 3602879701896397 / 2^55.
    b.f64(0.1).f64(0).f64(0).f64(1).f64(0).f64(0).f64(0).f64(-0.0).f64(-1e300).f64(0).f64(0).f64(1);
    for (const auto& f : tetra_faces) {
      b.u32(3);
      for (std::uint32_t i : f) b.u32(i);
      b.f64(std::numeric_limits<double>::infinity());  // skipped, not checked
    }
    const PolygonSoup soup = ply_from(b.str());
    mpz_class e300;
    mpz_ui_pow_ui(e300.get_mpz_t(), 10, 300);
    EXPECT_EQ(soup.points[0], (Vec3{over_pow2(3602879701896397, 55), 0, 0}));
    EXPECT_EQ(soup.points[1], v3(1, 0, 0));
    EXPECT_EQ(soup.points[2].x, 0);
    EXPECT_EQ(soup.points[2].y, 0);
    // -1e300 is a double near -10^300, not -10^300: check it is the double.
    EXPECT_NE(soup.points[2].z, Rational(-e300));
    EXPECT_EQ(soup.points[2].z, rational_from_double(-1e300));
    EXPECT_EQ(soup.points[3], v3(0, 0, 1));
    EXPECT_EQ(faces_of(soup), tetra_faces);
  }
}

TEST(ReadPly, BinaryEveryIntegerTypeAsCoordinate) {
  const char* types[] = {"char", "uchar", "short", "ushort", "int", "uint", "int8", "uint8", "int16", "uint16",
                         "int32", "uint32"};
  const int sizes[] = {1, 1, 2, 2, 4, 4, 1, 1, 2, 2, 4, 4};
  const bool is_signed[] = {true, false, true, false, true, false, true, false, true, false, true, false};
  for (bool big : {false, true}) {
    for (std::size_t t = 0; t < std::size(types); ++t) {
      SCOPED_TRACE(std::string(types[t]) + (big ? " big endian" : " little endian"));
      const std::string type = types[t];
      Bytes b(big);
      b.text("ply\nformat " + std::string(big ? "binary_big_endian" : "binary_little_endian") +
             " 1.0\nelement vertex 2\nproperty " + type + " x\nproperty " + type + " y\nproperty " + type +
             " z\nend_header\n");
      const std::uint64_t all_ones = sizes[t] == 4 ? 0xffffffffu : (std::uint64_t{1} << (8 * sizes[t])) - 1;
      b.u(1, sizes[t]).u(all_ones, sizes[t]).u(all_ones >> 1, sizes[t]);
      b.u(0, sizes[t]).u(0, sizes[t]).u(0, sizes[t]);
      const PolygonSoup soup = ply_from(b.str());
      const Rational max_value(static_cast<long>(all_ones));
      const Rational top = is_signed[t] ? Rational(-1) : max_value;
      EXPECT_EQ(soup.points[0], (Vec3{1, top, Rational(static_cast<long>(all_ones >> 1))}));
      EXPECT_EQ(soup.points[1], v3(0, 0, 0));
    }
  }
}

// ---- writing and round trips ----

PolygonSoup decimal_tetra() {
  PolygonSoup soup;
  mpz_class big;
  mpz_ui_pow_ui(big.get_mpz_t(), 10, 30);
  soup.points = {{Rational(1, 10), 0, 0}, {Rational(big), 0, Rational(-1, 4)}, v3(0, 1, 0), {0, 0, Rational(3, 1250)}};
  soup.face_offsets = {0, 3, 6, 9, 12};
  soup.face_indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  return soup;
}

TEST(WritePly, ExactIsAsciiAndReadsBackExactly) {
  const PolygonSoup soup = decimal_tetra();
  std::ostringstream out;
  write_ply(out, soup);
  EXPECT_EQ(out.str().substr(0, out.str().find("end_header")),
            "ply\nformat ascii 1.0\ncomment cvms: exact decimal coordinates\nelement vertex 4\n"
            "property double x\nproperty double y\nproperty double z\nelement face 4\n"
            "property list uchar int vertex_indices\n");
  EXPECT_NE(out.str().find("\n0.1 0 0\n"), std::string::npos);
  const PolygonSoup back = ply_from(out.str());
  EXPECT_EQ(back.points, soup.points);
  EXPECT_EQ(faces_of(back), faces_of(soup));
}

TEST(WritePly, ExactRefusesACoordinateWithoutFiniteDecimal) {
  PolygonSoup soup = decimal_tetra();
  soup.points[2].y = Rational(1, 3);
  std::ostringstream out;
  EXPECT_TRUE(throws_error([&] { write_ply(out, soup); }, ErrorCategory::invalid_argument,
                           {"vertex 2", "1/3", "no finite decimal expansion"}));
  EXPECT_TRUE(out.str().empty());  // refused before a byte is written
}

TEST(WritePly, DoubleIsBinaryAndReadsBackAsTheDoubles) {
  PolygonSoup soup = decimal_tetra();
  soup.points[2].y = Rational(1, 3);
  std::ostringstream out;
  write_ply(out, soup, Coordinates::double_);
  const std::string& bytes = out.str();
  const std::string header =
      "ply\nformat binary_little_endian 1.0\ncomment cvms: coordinates rounded to the nearest doubles\n"
      "element vertex 4\nproperty double x\nproperty double y\nproperty double z\nelement face 4\n"
      "property list uchar int vertex_indices\nend_header\n";
  ASSERT_EQ(bytes.substr(0, header.size()), header);
  EXPECT_EQ(bytes.size(), header.size() + 4 * 24 + 4 * (1 + 12));
  // 1/3 rounds to 0x3fd5555555555555 = 6004799503160661 / 2^54; 0.1 to
  // 3602879701896397 / 2^55; 10^30 to the double 1e30; 3/1250 to 0.0024.
  std::uint64_t y2 = 0;
  std::memcpy(&y2, bytes.data() + header.size() + 2 * 24 + 8, 8);
  EXPECT_EQ(y2, 0x3fd5555555555555u);
  const PolygonSoup back = ply_from(bytes);
  EXPECT_EQ(back.points[2].y, over_pow2(6004799503160661, 54));
  EXPECT_EQ(back.points[0].x, over_pow2(3602879701896397, 55));
  EXPECT_EQ(back.points[1].x, rational_from_double(1e30));
  EXPECT_EQ(back.points[3].z, rational_from_double(0.0024));
  EXPECT_EQ(faces_of(back), faces_of(soup));
  // Written again, the doubles stay the same bytes.
  std::ostringstream again;
  write_ply(again, back, Coordinates::double_);
  EXPECT_EQ(again.str(), bytes);
}

TEST(WritePly, FacesBeyond255VerticesGetUintCounts) {
  PolygonSoup soup;
  constexpr std::uint32_t n = 300;
  for (std::uint32_t i = 0; i < n; ++i) soup.points.push_back(v3(i, i * i, 0));
  soup.face_offsets = {0, n};
  for (std::uint32_t i = 0; i < n; ++i) soup.face_indices.push_back(i);
  for (Coordinates c : {Coordinates::exact, Coordinates::double_}) {
    std::ostringstream out;
    write_ply(out, soup, c);
    EXPECT_NE(out.str().find("property list uint int vertex_indices\n"), std::string::npos);
    const PolygonSoup back = ply_from(out.str());
    EXPECT_EQ(back.points, soup.points);
    EXPECT_EQ(faces_of(back), faces_of(soup));
  }
}

TEST(WritePly, PolyhedronFilesRoundTripAndDispatchByExtension) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "cvms_io_ply_test";
  std::filesystem::create_directories(dir);
  const ConvexPolyhedron cube = read_polyhedron(data_path("cube.off"));
  EXPECT_EQ(format_from_extension("A.PLY"), FileFormat::ply);
  for (Coordinates c : {Coordinates::exact, Coordinates::double_}) {
    const std::filesystem::path path = dir / (c == Coordinates::exact ? "cube.ply" : "cube_double.ply");
    write_file(path, cube, c);
    const ConvexPolyhedron back = read_polyhedron(path);
    EXPECT_EQ(back.num_vertices(), cube.num_vertices());
    EXPECT_EQ(back.num_facets(), cube.num_facets());
    const auto lexicographic = [](const Vec3& p, const Vec3& q) {
      return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
    };
    std::vector<Vec3> a(cube.mesh().positions().begin(), cube.mesh().positions().end());
    std::vector<Vec3> b(back.mesh().positions().begin(), back.mesh().positions().end());
    std::sort(a.begin(), a.end(), lexicographic);
    std::sort(b.begin(), b.end(), lexicographic);
    EXPECT_EQ(a, b);
    // The same file through the readers of sets and of points.
    EXPECT_EQ(read_convex_set(path).dimension(), 3);
    std::ifstream in(path, std::ios::binary);
    EXPECT_EQ(read_points(in, path.string()).size(), cube.num_vertices());
  }
  // Sets below dimension 3 and the empty set come back as they went.
  for (const ConvexSet& set : {ConvexSet(), convex_hull_set(std::vector<Vec3>{v3(1, 2, 3), v3(4, 5, 6)})}) {
    write_file(dir / "set.ply", set);
    EXPECT_EQ(read_convex_set(dir / "set.ply").dimension(), set.dimension());
  }
  std::filesystem::remove_all(dir);
}

// ---- hostile inputs ----

const std::string xyz_float = "property float x\nproperty float y\nproperty float z\n";

TEST(ReadPlyHostile, HugeCountsAreRefusedOnTheirHeaderLine) {
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(fails("ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n" + xyz_float + "end_header\n",
                    ErrorCategory::limit, {"mem.ply:3:", "1000000000000 vertices exceed the limit"}));
  EXPECT_TRUE(fails("ply\nformat ascii 1.0\nelement vertex 3\n" + xyz_float +
                        "element face 1000000000000\nproperty list uchar int vertex_indices\nend_header\n",
                    ErrorCategory::limit, {"mem.ply:7:", "1000000000000 faces exceed the limit"}));
  EXPECT_TRUE(fails("ply\nformat ascii 1.0\nelement vertex 99999999999999999999999\n", ErrorCategory::limit,
                    {"mem.ply:3:", "beyond 2^64-1"}));
  ReadLimits limits;
  limits.max_vertices = 3;
  EXPECT_TRUE(fails("ply\nformat ascii 1.0\nelement vertex 4\n", ErrorCategory::limit,
                    {"mem.ply:3:", "4 vertices exceed the limit of 3"}, limits));
  // A counted element without properties takes no byte: skipped at once.
  const PolygonSoup soup = ply_from("ply\nformat binary_big_endian 1.0\nelement vertex 0\n" + xyz_float +
                                    "element nothing 18446744073709551614\nend_header\n");
  EXPECT_TRUE(soup.points.empty());
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

// Duplicate names are looked up in trees: a header of 10^5 elements and
// 10^5 properties is read in well under a second, not in 10^10 comparisons.
TEST(ReadPlyHostile, ManyElementsAndPropertiesStayFast) {
  std::string text = "ply\nformat binary_little_endian 1.0\n";
  for (int e = 0; e < 100000; ++e) text += "element e" + std::to_string(e) + " 0\n";
  text += "element vertex 1\n" + xyz_float;
  for (int p = 0; p < 100000; ++p) text += "property uchar p" + std::to_string(p) + "\n";
  text += "end_header\n";
  Bytes body(false);
  body.f32(1).f32(2).f32(3);
  const auto start = std::chrono::steady_clock::now();
  const PolygonSoup soup = ply_from(text + body.str() + std::string(100000, '\x7f'));
  EXPECT_EQ(soup.points, std::vector<Vec3>{v3(1, 2, 3)});
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::duration<double>(2.0 * test::slow_factor));
}

TEST(ReadPlyHostile, TruncatedBodies) {
  std::string bytes = binary_tetra_float(false);
  const std::size_t header = bytes.find("end_header\n") + 11;
  // Cut in the middle of vertex 2's y coordinate (each vertex: 4 floats, a
  // uchar, a uchar count and two shorts = 22 bytes).
  EXPECT_TRUE(fails(bytes.substr(0, header + 2 * 22 + 9), ErrorCategory::parse,
                    {"mem.ply: byte " + std::to_string(header + 2 * 22 + 8) + ":",
                     "unexpected end of input in y coordinate of vertex 2"}));
  EXPECT_TRUE(fails(bytes.substr(0, bytes.size() - 1), ErrorCategory::parse,
                    {"unexpected end of input in index of face 3"}));
  EXPECT_TRUE(fails("ply\nformat ascii 1.0\nelement vertex 2\n" + xyz_float + "end_header\n1 2 3\n4 5\n",
                    ErrorCategory::parse, {"mem.ply:9:", "missing z coordinate of vertex 1"}));
  EXPECT_TRUE(fails("ply\nformat ascii 1.0\nelement vertex 1\n", ErrorCategory::parse,
                    {"mem.ply:3:", "no 'end_header'"}));
}

TEST(ReadPlyHostile, ListCountsBeyondLimitsAndTypes) {
  Bytes b(false);
  b.text(binary_header("binary_little_endian", xyz_float, 3, "list uint int", 1));
  for (int i = 0; i < 9; ++i) b.f32(0);
  b.u32(0xffffffffu);
  EXPECT_TRUE(fails(b.str(), ErrorCategory::parse,
                    {"byte " + std::to_string(b.str().size() - 4) + ":",
                     "face 0 lists 4294967295 vertices, more than the 3 vertices"}));
  // A skipped list announcing 2^32-1 floats ends at the end of the input, at once.
  Bytes skip(true);
  skip.text("ply\nformat binary_big_endian 1.0\nelement vertex 0\n" + xyz_float +
            "element junk 1\nproperty list uint double values\nend_header\n");
  skip.u32(0xffffffffu).f64(1);
  EXPECT_TRUE(fails(skip.str(), ErrorCategory::parse, {"unexpected end of input in values of junk 0"}));
  EXPECT_TRUE(fails("ply\nformat ascii 1.0\nelement vertex 3\n" + xyz_float +
                        "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
                        "300 0 1 2\n",
                    ErrorCategory::parse, {"mem.ply:13:", "'300' is not an integer from 0 to 255"}));
  Bytes negative(false);
  negative.text(binary_header("binary_little_endian", xyz_float, 3, "list char int", 1));
  for (int i = 0; i < 9; ++i) negative.f32(0);
  negative.i8(-3);
  EXPECT_TRUE(fails(negative.str(), ErrorCategory::parse, {"count of index list of face 0 is negative (-3)"}));
}

TEST(ReadPlyHostile, FacesTooSmallAndIndicesOutOfRange) {
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz_float +
                           "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_TRUE(fails(head + "2 0 1\n", ErrorCategory::parse, {"mem.ply:13:", "face 0 has 2 vertices, at least 3"}));
  EXPECT_TRUE(fails(head + "3 0 1 3\n", ErrorCategory::parse, {"mem.ply:13:", "face 0 has index 3 but there are 3"}));
  EXPECT_TRUE(fails(head + "3 0 -1 2\n", ErrorCategory::parse, {"face 0 has index -1"}));
  EXPECT_TRUE(fails(head + "3 0 1 x\n", ErrorCategory::parse, {"index of face 0 'x' is not an integer"}));
  Bytes b(true);
  b.text(binary_header("binary_big_endian", xyz_float, 3, "list uchar uint", 1));
  for (int i = 0; i < 9; ++i) b.f32(0);
  b.u8(3).u32(0).u32(1).u32(7);
  const std::size_t at = b.str().size() - 4;
  EXPECT_TRUE(fails(b.str(), ErrorCategory::parse,
                    {"mem.ply: byte " + std::to_string(at) + ":", "face 0 has index 7 but there are 3 vertices"}));
}

TEST(ReadPlyHostile, NonFiniteCoordinates) {
  for (bool big : {false, true}) {
    for (double bad : {std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()}) {
      Bytes b(big);
      b.text(binary_header(big ? "binary_big_endian" : "binary_little_endian",
                           "property double x\nproperty float y\nproperty double z\n", 1, "list uchar int", 0));
      Bytes f = b;
      b.f64(0).f32(0).f64(bad);
      const std::size_t at = b.str().size() - 8;
      EXPECT_TRUE(fails(b.str(), ErrorCategory::parse,
                        {"byte " + std::to_string(at) + ":", "z coordinate of vertex 0 is not finite",
                         std::isnan(bad) ? "(nan)" : "(inf)"}));
      f.f64(0).f32(static_cast<float>(bad)).f64(0);
      EXPECT_TRUE(fails(f.str(), ErrorCategory::parse, {"y coordinate of vertex 0 is not finite"}));
    }
  }
  EXPECT_TRUE(fails("ply\nformat ascii 1.0\nelement vertex 1\n" + xyz_float + "end_header\n0 nan 0\n",
                    ErrorCategory::parse, {"mem.ply:8:", "y coordinate of vertex 0 is not finite"}));
  EXPECT_TRUE(fails("ply\nformat ascii 1.0\nelement vertex 1\nproperty int x\nproperty int y\nproperty int z\n"
                    "end_header\n0 1.5 0\n",
                    ErrorCategory::parse, {"mem.ply:8:", "y coordinate of vertex 0 '1.5' is not an integer"}));
}

TEST(ReadPlyHostile, MalformedHeaders) {
  struct Case {
    std::string text;
    std::vector<std::string> needles;
  };
  const std::string v = "element vertex 1\n" + xyz_float;
  const Case cases[] = {
      {"", {"mem.ply: empty input"}},
      {"plx\n", {"mem.ply:1:", "expected 'ply'"}},
      {"ply extra\n", {"mem.ply:1:", "expected 'ply'"}},
      {std::string("\0\0\0\0", 4), {"mem.ply:1:", "a NUL byte in the header (at byte 0)"}},
      {"ply\nformat ascii 2.0\n", {"mem.ply:2:", "unsupported PLY version '2.0'"}},
      {"ply\nformat binary_middle_endian 1.0\n", {"mem.ply:2:", "unknown PLY format"}},
      {"ply\nformat ascii 1.0\nformat ascii 1.0\n", {"mem.ply:3:", "a second 'format'"}},
      {"ply\nelement vertex 1\n", {"mem.ply:2:", "before the 'format' line"}},
      {"ply\nformat ascii 1.0\nproperty float x\n", {"mem.ply:3:", "before any 'element'"}},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\n", {"mem.ply:4:", "unknown PLY property type 'float128'"}},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty list float int x\n", {"mem.ply:4:", "count type of a list"}},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty double x\n",
       {"mem.ply:5:", "a second property 'x'"}},
      {"ply\nformat ascii 1.0\n" + v + v, {"mem.ply:7:", "a second element 'vertex'"}},
      {"ply\nformat ascii 1.0\nelement vertex -1\n", {"mem.ply:3:", "'-1' is not a non-negative integer"}},
      {"ply\nformat ascii 1.0\nmaterial foo\n", {"mem.ply:3:", "unknown PLY header keyword 'material'"}},
      {"ply\nformat ascii 1.0\nend_header\n", {"mem.ply:3:", "no 'vertex' element"}},
      {"ply\nend_header\n", {"mem.ply:2:", "'end_header' before the 'format' line"}},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float z\nend_header\n",
       {"mem.ply:3:", "element 'vertex' has no property 'y'"}},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty list uchar float x\nproperty float y\n"
       "property float z\nend_header\n",
       {"mem.ply:3:", "property 'x' of element 'vertex' is a list"}},
      {"ply\nformat ascii 1.0\n" + v + "element face 1\nproperty list uchar int indices\nend_header\n",
       {"mem.ply:7:", "no list property 'vertex_indices'"}},
      {"ply\nformat ascii 1.0\n" + v + "element face 1\nproperty int vertex_indices\nend_header\n",
       {"mem.ply:7:", "'vertex_indices' of element 'face' is not a list"}},
      {"ply\nformat ascii 1.0\n" + v + "element face 1\nproperty list uchar float vertex_indices\nend_header\n",
       {"mem.ply:7:", "must be of an integer type, not 'float'"}},
      {"ply\nformat ascii 1.0\n" + v + "element face 1\nproperty list uchar int vertex_indices\n"
       "property list uchar int vertex_index\nend_header\n",
       {"mem.ply:7:", "both 'vertex_indices' and 'vertex_index'"}},
      {std::string("ply\nformat ascii 1.0\ncomment a NUL \0 here\n", 36), {"mem.ply:3:", "a NUL byte in the header"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    try {
      ply_from(c.text);
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::parse) << e.what();
      for (const std::string& needle : c.needles) EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  }
}

TEST(ReadPlyHostile, TrailingDataLongHeadersAndSizeLimits) {
  const std::string ascii = "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz_float + "end_header\n1 2 3\n";
  EXPECT_NO_THROW(ply_from(ascii + "\n  \n"));
  EXPECT_TRUE(fails(ascii + "4\n", ErrorCategory::parse, {"mem.ply:9:", "unexpected '4' after the last element"}));
  Bytes b(false);
  b.text("ply\nformat binary_little_endian 1.0\nelement vertex 1\n" + xyz_float + "end_header\n");
  b.f32(1).f32(2).f32(3);
  EXPECT_NO_THROW(ply_from(b.str()));
  const std::size_t end = b.str().size();
  EXPECT_TRUE(fails(b.str() + "\n", ErrorCategory::parse,
                    {"mem.ply: byte " + std::to_string(end) + ":", "bytes after the last element"}));
  ReadLimits limits;
  limits.max_line_bytes = 100;
  EXPECT_TRUE(fails("ply\nformat ascii 1.0\ncomment " + std::string(200, 'c') + "\n", ErrorCategory::limit,
                    {"mem.ply:3:", "header is longer than the limit of 100 bytes"}, limits));
  limits = {};
  limits.max_bytes = b.str().size() - 1;
  EXPECT_TRUE(fails(b.str(), ErrorCategory::limit, {"larger than the limit"}, limits));
  limits.max_bytes = ascii.size() - 2;
  EXPECT_TRUE(fails(ascii, ErrorCategory::limit, {"larger than the limit"}, limits));
}

// ---- the bad corpus ----

::testing::AssertionResult bad(std::string_view name, ErrorCategory category,
                               std::initializer_list<std::string_view> needles) {
  const std::string file = "bad/" + std::string(name);
  auto result = throws_error([&] { read_file(data_path(file)); }, category, needles);
  if (!result) return result;
  return throws_error([&] { read_file(data_path(file)); }, category, {name});
}

TEST(ReadPlyBad, Corpus) {
  EXPECT_TRUE(bad("ply_lying_vertex_count.ply", ErrorCategory::limit, {":3:", "vertices exceed the limit"}));
  EXPECT_TRUE(bad("ply_truncated_ascii.ply", ErrorCategory::parse, {":11:", "index of face 0"}));
  EXPECT_TRUE(bad("ply_index_out_of_range.ply", ErrorCategory::parse, {":15:", "face 0 has index 4"}));
  EXPECT_TRUE(bad("ply_no_end_header.ply", ErrorCategory::parse, {"no 'end_header'"}));
  EXPECT_TRUE(bad("ply_binary_truncated.ply", ErrorCategory::parse, {"byte 201:", "z coordinate of vertex 2"}));
  EXPECT_TRUE(bad("ply_binary_nan.ply", ErrorCategory::parse, {"byte 181:", "x coordinate of vertex 1 is not finite"}));
}

}  // namespace
}  // namespace cvms
