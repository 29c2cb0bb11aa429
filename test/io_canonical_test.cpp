// SPDX-License-Identifier: MIT
// VertexOrder::canonical: the bytes depend on the set alone. A polyhedron
// and the same polyhedron renumbered (points shuffled with a fixed seed,
// each facet rotated) are written as the same bytes, a sum's packed
// vertices as the same bytes as its own soup rebuilt from Rationals; the
// points come out in exact lexicographic order (checked against Vec3's
// operator<, an independent comparison), including values whose doubles
// tie (1 and 1 + 2^-80), negative ones and long numerators.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cvms/io.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/shapes.hpp"

namespace cvms {
namespace {

using shapes::cube;
using shapes::geodesic_sphere;
using shapes::rotated_geodesic_sphere;

std::string written(const ConvexPolyhedron& p, FileFormat format,
                    Coordinates coordinates = Coordinates::exact) {
  std::ostringstream out;
  write(out, p, format, coordinates, VertexOrder::canonical);
  return out.str();
}

// p's soup with its points in a random order (fixed seed) and each facet
// starting at another corner: the same set, numbered otherwise.
ConvexPolyhedron renumbered(const ConvexPolyhedron& p, std::uint32_t seed) {
  const PolygonSoup soup = p.to_soup();
  std::vector<std::uint32_t> where(soup.points.size());
  std::iota(where.begin(), where.end(), std::uint32_t{0});
  std::mt19937 random(seed);
  std::shuffle(where.begin(), where.end(), random);
  PolygonSoup out;
  out.points.resize(soup.points.size());
  for (std::size_t i = 0; i < where.size(); ++i) out.points[where[i]] = soup.points[i];
  for (std::size_t f = soup.num_faces(); f-- > 0;) {
    std::vector<std::uint32_t> face;
    for (std::uint32_t v : soup.face(f)) face.push_back(where[v]);
    std::rotate(face.begin(), face.begin() + static_cast<std::ptrdiff_t>(f % face.size()), face.end());
    out.add_face(std::span<const std::uint32_t>(face));
  }
  return ConvexPolyhedron::from_soup(std::move(out));
}

ConvexPolyhedron tetrahedron(const Rational& s) {
  PolygonSoup soup;
  soup.points = {Vec3(0, 0, 0), Vec3(s, 0, 0), Vec3(0, s, 0), Vec3(0, 0, s)};
  soup.add_face({0, 2, 1});
  soup.add_face({0, 1, 3});
  soup.add_face({0, 3, 2});
  soup.add_face({1, 2, 3});
  return ConvexPolyhedron::from_soup(std::move(soup));
}

void expect_canonical(const ConvexPolyhedron& p, const std::string& what) {
  SCOPED_TRACE(what);
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const ConvexPolyhedron q = renumbered(p, seed);
    for (FileFormat format : {FileFormat::off, FileFormat::obj, FileFormat::stl})
      EXPECT_EQ(written(p, format), written(q, format));
    EXPECT_EQ(written(p, FileFormat::off, Coordinates::double_),
              written(q, FileFormat::off, Coordinates::double_));
    EXPECT_EQ(written(p, FileFormat::ply, Coordinates::double_),
              written(q, FileFormat::ply, Coordinates::double_));
  }
  std::istringstream in(written(p, FileFormat::off));
  const PolygonSoup back = read_off(in, "canonical");
  std::vector<Vec3> expected = p.to_soup().points;
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(back.points, expected);
  EXPECT_EQ(ConvexPolyhedron::from_soup(back).num_facets(), p.num_facets());
}

TEST(CanonicalOrder, RenumberedPolyhedraGiveTheSameBytes) {
  expect_canonical(cube(), "cube");
  expect_canonical(geodesic_sphere(2), "sphere 2");
  expect_canonical(tetrahedron(Rational(1, 3)), "tetrahedron 1/3");
}

TEST(CanonicalOrder, PackedSumsGiveTheBytesOfTheirRationals) {
  // 1 and 1 + 2^-80 have the same double; 2^-80 + 2^60 needs two limbs.
  const Rational tiny(mpz_class(1), mpz_class(1) << 80);
  const std::vector<std::pair<ConvexPolyhedron, ConvexPolyhedron>> pairs = {
      {cube(), cube()},
      {geodesic_sphere(2), rotated_geodesic_sphere(2)},
      {tetrahedron(1), tetrahedron(tiny)},
      {tetrahedron(Rational(mpz_class(1) << 60)), tetrahedron(tiny)},
      {cube(), tetrahedron(tiny)},
  };
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const ConvexPolyhedron sum = minkowski_sum(pairs[i].first, pairs[i].second).polyhedron;
    const ConvexPolyhedron swapped = minkowski_sum(pairs[i].second, pairs[i].first).polyhedron;
    const ConvexPolyhedron rebuilt = ConvexPolyhedron::from_soup(sum.to_soup());
    for (FileFormat format : {FileFormat::off, FileFormat::obj, FileFormat::ply}) {
      SCOPED_TRACE("pair " + std::to_string(i) + ", format " + std::to_string(static_cast<int>(format)));
      EXPECT_EQ(written(sum, format), written(rebuilt, format));
      EXPECT_EQ(written(sum, format), written(swapped, format));
      EXPECT_EQ(written(sum, format, Coordinates::double_), written(swapped, format, Coordinates::double_));
    }
    expect_canonical(sum, "sum " + std::to_string(i));
  }
}

}  // namespace
}  // namespace cvms
