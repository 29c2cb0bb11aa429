// SPDX-License-Identifier: MIT
// Convex sets written in doubles (Coordinates::double_, double_outer) and
// exported as flat arrays (to_float_mesh), checked as a floating-point
// pipeline would read them: every coordinate token parsed as a double, the
// doubles taken exactly. The oracles are independent of the rounding code:
//  - validity: ConvexPolyhedron::from_soup accepts the doubles read back
//    with as many facets and vertices as written (none merged, none
//    dropped: maximal, exactly planar facets and only corners);
//  - nearest: the written vertices are exactly the extreme points among the
//    nearest doubles of the exact vertices (each a nearest double of some
//    exact vertex, every nearest double inside), each within half a gap
//    between doubles of its exact vertex, which with convexity gives the
//    documented Hausdorff bound;
//  - outer: every exact vertex lies in the written polyhedron (tested
//    against the planes of its written faces, exactly), and every written
//    vertex lies in the double box around some exact vertex;
//  - the same bytes on every write, and to_float_mesh equal to the file.
// Shapes: the paper's (cvms/shapes.hpp, rotated by rational quaternions, so
// their coordinates are not dyadic) and seeded random hulls scaled by 1/3.
#include "cvms/float_mesh.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/io.hpp"
#include "cvms/set_io.hpp"
#include "cvms/shapes.hpp"
#include "support/read_as_doubles.hpp"

namespace cvms {
namespace {

using test::inside;
using test::read_off_as_doubles;

constexpr double infinity = std::numeric_limits<double>::infinity();

Vec3 v3(const Rational& x, const Rational& y, const Rational& z) { return {x, y, z}; }

std::string written(const ConvexSet& set, Coordinates coordinates) {
  std::ostringstream out;
  write(out, set, FileFormat::off, "<test>", coordinates);
  return out.str();
}

double nearest_of(const Rational& c) { return to_double_nearest(c); }

// c lies within half the gap to the next double on its side of d (so d is a
// nearest double of c).
bool within_half_gap(const Rational& c, double d) {
  const Rational below = (Rational(d) + Rational(std::nextafter(d, -infinity))) / 2;
  const Rational above = (Rational(d) + Rational(std::nextafter(d, infinity))) / 2;
  return below <= c && c <= above;
}

// d is the largest double <= c or the smallest double >= c.
bool encloses(const Rational& c, double d) {
  const Rational exact(d);
  if (exact == c) return true;
  return exact < c ? Rational(std::nextafter(d, infinity)) > c : Rational(std::nextafter(d, -infinity)) < c;
}

void expect_nearest(const ConvexSet& set, const PolygonSoup& soup, const std::string& label) {
  const std::vector<Vec3> exact = set.vertices();
  for (const Vec3& q : soup.points) {
    bool found = false;
    for (const Vec3& v : exact)
      found = found || (q.x == Rational(nearest_of(v.x)) && q.y == Rational(nearest_of(v.y)) &&
                        q.z == Rational(nearest_of(v.z)));
    EXPECT_TRUE(found) << label << ": a written vertex is no exact vertex's nearest double";
    bool close = false;
    for (const Vec3& v : exact)
      close = close || (within_half_gap(v.x, to_double_nearest(q.x)) && within_half_gap(v.y, to_double_nearest(q.y)) &&
                        within_half_gap(v.z, to_double_nearest(q.z)));
    EXPECT_TRUE(close) << label << ": a written vertex is beyond half an ulp of every exact vertex";
  }
  for (const Vec3& v : exact) {
    const Vec3 r = v3(Rational(nearest_of(v.x)), Rational(nearest_of(v.y)), Rational(nearest_of(v.z)));
    EXPECT_TRUE(inside(soup, r)) << label << ": a rounded vertex is outside the written hull";
  }
}

void expect_outer(const ConvexSet& set, const PolygonSoup& soup, const std::string& label) {
  const std::vector<Vec3> exact = set.vertices();
  for (const Vec3& v : exact) EXPECT_TRUE(inside(soup, v)) << label << ": an exact vertex is outside";
  for (const Vec3& q : soup.points) {
    bool found = false;
    for (const Vec3& v : exact)
      found = found || (encloses(v.x, to_double_nearest(q.x)) && encloses(v.y, to_double_nearest(q.y)) &&
                        encloses(v.z, to_double_nearest(q.z)));
    EXPECT_TRUE(found) << label << ": a written vertex is no corner of an exact vertex's double box";
  }
}

// to_float_mesh holds what the file holds, in the same order.
void expect_mesh_matches(const FloatMesh& mesh, const PolygonSoup& soup, const std::string& label) {
  ASSERT_EQ(mesh.num_vertices(), soup.points.size()) << label;
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    EXPECT_EQ(Rational(mesh.positions[3 * i]), soup.points[i].x) << label;
    EXPECT_EQ(Rational(mesh.positions[3 * i + 1]), soup.points[i].y) << label;
    EXPECT_EQ(Rational(mesh.positions[3 * i + 2]), soup.points[i].z) << label;
  }
  EXPECT_EQ(mesh.face_offsets, soup.face_offsets) << label;
  EXPECT_EQ(mesh.face_indices, soup.face_indices) << label;
  std::vector<std::uint32_t> fans;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto face = soup.face(f);
    for (std::size_t i = 1; i + 1 < face.size(); ++i) fans.insert(fans.end(), {face[0], face[i], face[i + 1]});
  }
  EXPECT_EQ(mesh.triangles, fans) << label;
}

void check_both_modes(const ConvexSet& set, const std::string& label) {
  for (const Coordinates coordinates : {Coordinates::double_, Coordinates::double_outer}) {
    const bool outer = coordinates == Coordinates::double_outer;
    const std::string what = label + (outer ? " outer" : " nearest");
    const std::string text = written(set, coordinates);
    EXPECT_EQ(written(set, coordinates), text) << what << ": bytes differ between two writes";
    const PolygonSoup soup = read_off_as_doubles(text);
    test::expect_valid_convex_set(soup, what);
    if (outer)
      expect_outer(set, soup, what);
    else
      expect_nearest(set, soup, what);
    expect_mesh_matches(to_float_mesh(set, outer ? FloatMode::outer : FloatMode::nearest), soup, what);
  }
}

ConvexPolyhedron rotated(const ConvexPolyhedron& p, std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d) {
  return p.transformed(shapes::rational_rotation(a, b, c, d), Vec3{});
}

TEST(FloatModes, PaperShapesRotatedByRationalQuaternions) {
  const std::vector<std::pair<std::string, ConvexPolyhedron>> shapes = {
      {"tetrahedron", shapes::tetrahedron()},       {"cube", shapes::cube()},
      {"octahedron", shapes::octahedron()},         {"truncated cube", shapes::truncated_cube()},
      {"Sphere_2", shapes::geodesic_sphere(2)},     {"rotated Sphere_2", shapes::rotated_geodesic_sphere(2)},
      {"prism 7", shapes::prism(7, Rational(2))}};
  for (const auto& [name, shape] : shapes) {
    check_both_modes(shape, name);
    check_both_modes(rotated(shape, 1, 2, 3, 4), name + " rotated (1,2,3,4)");
    check_both_modes(rotated(shape, 7, 1, 0, 5), name + " rotated (7,1,0,5)");
  }
}

TEST(FloatModes, RandomHullsWithNonDyadicCoordinates) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const ConvexPolyhedron hull = shapes::random_hull(seed, 40, 1000);
    const Rational third(1, 3);
    const ConvexPolyhedron scaled = hull.transformed(shapes::scaling(third, Rational(1, 7), Rational(10, 3)), Vec3{});
    check_both_modes(scaled, "random hull / 3");
    check_both_modes(rotated(scaled, 3, 1, 4, 1), "random hull rotated");
  }
}

// Rounding each vertex alone breaks the cube rotated by (1,2,3,4): the
// corners of a facet no longer lie in one plane. The hull does not.
TEST(FloatModes, RoundingEachVertexAloneIsNotValidButTheHullIs) {
  const ConvexPolyhedron p = rotated(shapes::cube(), 1, 2, 3, 4);
  std::ostringstream each;
  write(each, p.to_soup(), FileFormat::off, Coordinates::double_);
  const PolygonSoup naive = read_off_as_doubles(each.str());
  bool same = false;
  try {
    same = ConvexPolyhedron::from_soup(naive).num_facets() == naive.num_faces();
  } catch (const Error&) {
  }
  EXPECT_FALSE(same) << "the example no longer shows the problem: pick another rotation";
  check_both_modes(p, "rotated cube");
}

TEST(FloatModes, DoublesAreWrittenUnchanged) {
  const ConvexPolyhedron cube = shapes::box(v3(Rational(1, 2), 0, 0), v3(1, 2, Rational(3, 4)));
  const ConvexSet set(cube);
  EXPECT_EQ(written(set, Coordinates::double_), written(set, Coordinates::exact));
  EXPECT_EQ(written(set, Coordinates::double_outer), written(set, Coordinates::exact));
}

TEST(FloatModes, FlatSetsOfEveryDimension) {
  const Rational t(1, 3);
  // A point not on the double grid becomes its box (outer) or its nearest double.
  const ConvexSet point = ConvexSet::point(v3(t, t, t));
  EXPECT_EQ(round_to_doubles(point, FloatMode::nearest).dimension(), 0);
  EXPECT_EQ(round_to_doubles(point, FloatMode::outer).dimension(), 3);
  EXPECT_EQ(round_to_doubles(point, FloatMode::outer).num_vertices(), 8u);
  EXPECT_EQ(round_to_doubles(ConvexSet::point(v3(t, 0, 0)), FloatMode::outer).dimension(), 1);
  check_both_modes(point, "point");
  const ConvexSet segment = ConvexSet::segment(v3(0, 0, 0), v3(1, t, 2));
  EXPECT_EQ(round_to_doubles(segment, FloatMode::nearest).dimension(), 1);
  check_both_modes(segment, "segment");
  // A triangle in the plane x + y + z = 1, rotated: the nearest doubles need
  // not be coplanar any more, the outer hull is solid.
  const std::vector<Vec3> triangle = {v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 1)};
  const Mat3 r = shapes::rational_rotation(1, 2, 3, 4);
  std::vector<Vec3> turned;
  for (const Vec3& v : triangle) turned.push_back(r * v);
  const ConvexSet polygon = ConvexSet::polygon(turned);
  check_both_modes(polygon, "rotated triangle");
  EXPECT_EQ(round_to_doubles(polygon, FloatMode::outer).dimension(), 3);
  EXPECT_TRUE(round_to_doubles(ConvexSet(), FloatMode::outer).empty());
}

TEST(FloatModes, ATinyPolyhedronMayFlattenInNearestButNotInOuter) {
  const Rational tiny = Rational(1, 3) * Rational(1, 1000000) * Rational(1, 1000000) * Rational(1, 1000000);
  const ConvexPolyhedron p = shapes::box(v3(1, 1, 1), v3(1 + tiny, 1 + tiny, 1 + tiny));
  EXPECT_EQ(round_to_doubles(p, FloatMode::nearest).dimension(), 0);
  EXPECT_EQ(round_to_doubles(p, FloatMode::outer).dimension(), 3);
  check_both_modes(p, "tiny box");
}

TEST(FloatModes, ErrorsNameWhatCannotBeRounded) {
  const Rational huge = Rational(std::numeric_limits<double>::max()) * 2;
  const ConvexPolyhedron p = shapes::box(v3(0, 0, 0), v3(huge, 1, Rational(1, 3)));
  for (const FloatMode mode : {FloatMode::nearest, FloatMode::outer}) {
    try {
      (void)round_to_doubles(p, mode);
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
      EXPECT_NE(std::string(e.message()).find("coordinate x is beyond the range of double"), std::string::npos) << e.message();
      EXPECT_NE(std::string(e.message()).find("vertex "), std::string::npos) << e.message();
    }
  }
  // DBL_MAX is a double; just above it rounds to DBL_MAX, but its outer
  // bound above is infinite.
  const Rational above_max = Rational(std::numeric_limits<double>::max()) + 1;
  const ConvexSet edge = ConvexSet::point(v3(above_max, 0, 0));
  EXPECT_NO_THROW((void)round_to_doubles(edge, FloatMode::nearest));
  EXPECT_THROW((void)round_to_doubles(edge, FloatMode::outer), Error);

  std::ostringstream out;
  EXPECT_THROW(write(out, shapes::cube().to_soup(), FileFormat::off, Coordinates::double_outer), Error);
  EXPECT_THROW(write(out, shapes::cube(), FileFormat::stl, Coordinates::double_outer), Error);
  EXPECT_TRUE(out.str().empty());
}

TEST(FloatModes, AFailedWriteLeavesTheFileUntouched) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("cvms_float_modes_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / "out.off";
  { std::ofstream(path) << "keep"; }
  const Rational huge = Rational(std::numeric_limits<double>::max()) * 2;
  const ConvexPolyhedron p = shapes::box(v3(0, 0, 0), v3(huge, 1, 1));
  try {
    write_file(path, p, Coordinates::double_outer);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
    EXPECT_EQ(std::string(e.message()).rfind(path.string() + ": ", 0), 0u) << e.message();
  }
  std::ifstream in(path);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "keep");
  // The file form equals the stream form.
  const ConvexPolyhedron q = rotated(shapes::octahedron(), 1, 2, 3, 4);
  write_file(path, q, Coordinates::double_outer);
  std::ifstream again(path);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(again), {}), written(q, Coordinates::double_outer));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cvms
