// SPDX-License-Identifier: MIT
#include "support/read_as_doubles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/rational.hpp"

namespace cvms::test {
namespace {

Rational parse_double(const std::string& token) {
  char* end = nullptr;
  const double d = std::strtod(token.c_str(), &end);
  EXPECT_EQ(*end, '\0') << token;
  char shortest[32];
  const auto printed = std::to_chars(shortest, shortest + sizeof shortest, d);
  EXPECT_EQ(std::string(shortest, printed.ptr), token) << "not the shortest text of its double";
  return rational_from_double(d);
}

bool lexicographic_less(const Vec3& a, const Vec3& b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

std::vector<Vec3> sorted(std::vector<Vec3> points) {
  std::sort(points.begin(), points.end(), lexicographic_less);
  return points;
}

}  // namespace

PolygonSoup read_off_as_doubles(const std::string& text) {
  std::istringstream in(text);
  std::string keyword;
  std::size_t points = 0, faces = 0, edges = 0;
  in >> keyword >> points >> faces >> edges;
  EXPECT_EQ(keyword, "OFF");
  PolygonSoup soup;
  for (std::size_t i = 0; i < points && in; ++i) {
    std::string x, y, z;
    in >> x >> y >> z;
    soup.points.push_back(Vec3{parse_double(x), parse_double(y), parse_double(z)});
  }
  for (std::size_t f = 0; f < faces && in; ++f) {
    std::size_t n = 0;
    in >> n;
    std::vector<std::uint32_t> face(n);
    for (std::uint32_t& i : face) in >> i;
    soup.add_face(face);
  }
  EXPECT_FALSE(in.fail()) << "not an OFF text as cvms writes it";
  return soup;
}

void expect_valid_convex_set(const PolygonSoup& soup, const std::string& label) {
  try {
    const ConvexSet back = convex_set_from_soup(soup);
    EXPECT_EQ(back.num_vertices(), soup.points.size()) << label << ": a written vertex is not a corner";
    if (back.dimension() == 3) {
      EXPECT_EQ(back.polyhedron().num_facets(), soup.num_faces()) << label << ": facets merged on reading (not maximal)";
    }
  } catch (const Error& e) {
    ADD_FAILURE() << label << ": the doubles written are not a convex set: " << e.what();
  }
}

bool inside(const PolygonSoup& soup, const Vec3& p) {
  if (soup.num_faces() <= 1) {
    std::vector<Vec3> with_p = soup.points;
    with_p.push_back(p);
    return sorted(convex_hull_set(with_p).vertices()) == sorted(soup.points);
  }
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto face = soup.face(f);
    const Vec3& a = soup.points[face[0]];
    const Vec3 normal = cross(soup.points[face[1]] - a, soup.points[face[2]] - a);
    if (sgn(dot(normal, p - a)) > 0) return false;
  }
  return true;
}

}  // namespace cvms::test
