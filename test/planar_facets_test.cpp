// SPDX-License-Identifier: MIT
// The self-intersection search, which skips pairs of triangles that
// certified planar facets prove apart (planar_facets.hpp), against a brute
// force written here: every pair of triangles decided by the exact pair test
// (triangle_intersection.hpp). Soups are triangulated planar grids, in a
// tilted plane so no coordinate is constant, damaged at random: a vertex
// moved within the plane (folds, overlaps, T-junctions) or off it, triangles
// crossing the grid or touching it at a vertex, an edge or a chord from
// below, a triangle repeated the other way round. The two must agree on
// every soup, and the pair reported must be the first intersecting one in
// the hierarchy's order, as when every pair is tested. Seeds are fixed and
// printed on failure. Hand-checked cases: which facets are certified, and a
// comb prism of thin triangles accepted whole and refused when damaged.
#include "planar_facets.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/solid.hpp"
#include "self_intersection.hpp"
#include "support/hand_solids.hpp"
#include "triangle_intersection.hpp"
#include "triangle_tree.hpp"

namespace {

using cvms::Rational;
using cvms::Vec3;
using Triangle = std::array<std::uint32_t, 3>;

struct Soup {
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
};

// The point of the tilted plane z = x + 2y over (x, y), lifted by `off`.
Vec3 on_plane(int x, int y, int off = 0) { return {Rational(x), Rational(y), Rational(x + 2 * y + off)}; }

// An n x n grid of unit squares, each cut by a random diagonal, all
// triangles counterclockwise seen from above.
Soup grid(int n, std::mt19937& rng) {
  Soup soup;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) soup.points.push_back(on_plane(x, y));
  auto id = [n](int x, int y) { return static_cast<std::uint32_t>(y * (n + 1) + x); };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const std::uint32_t a = id(x, y), b = id(x + 1, y), c = id(x + 1, y + 1), d = id(x, y + 1);
      if (rng() % 2 == 0) {
        soup.triangles.push_back({a, b, c});
        soup.triangles.push_back({a, c, d});
      } else {
        soup.triangles.push_back({a, b, d});
        soup.triangles.push_back({b, c, d});
      }
    }
  return soup;
}

bool brute_force_intersects(const Soup& soup) {
  for (std::size_t i = 0; i < soup.triangles.size(); ++i)
    for (std::size_t j = i + 1; j < soup.triangles.size(); ++j)
      if (cvms::detail::triangles_overlap(soup.points, soup.triangles[i], soup.triangles[j])) return true;
  return false;
}

// Positive areas and distinct points: the search's preconditions.
bool valid(const Soup& soup) {
  for (const Triangle& t : soup.triangles)
    if (cross(soup.points[t[1]] - soup.points[t[0]], soup.points[t[2]] - soup.points[t[0]]) == Vec3{})
      return false;
  const std::set<std::array<Rational, 3>> distinct = [&] {
    std::set<std::array<Rational, 3>> s;
    for (const Vec3& p : soup.points) s.insert({p.x, p.y, p.z});
    return s;
  }();
  return distinct.size() == soup.points.size();
}

std::uint32_t add_point(Soup& soup, const Vec3& p) {
  soup.points.push_back(p);
  return static_cast<std::uint32_t>(soup.points.size() - 1);
}

// One random damage of the grid (n squares a side).
void damage(Soup& soup, int n, std::mt19937& rng) {
  auto coordinate = [&](int lo, int hi) {
    return lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1));
  };
  auto vertex = [&] { return static_cast<std::uint32_t>(rng() % soup.points.size()); };
  switch (rng() % 7) {
    case 0:  // moved within the plane
      soup.points[vertex()] = on_plane(coordinate(-1, n + 1), coordinate(-1, n + 1));
      break;
    case 1:  // moved off the plane
      soup.points[vertex()] = on_plane(coordinate(0, n), coordinate(0, n), coordinate(-2, 2));
      break;
    case 2: {  // a triangle crossing the plane, or not
      const std::uint32_t a =
          add_point(soup, on_plane(coordinate(0, n), coordinate(0, n), coordinate(-3, 3)));
      const std::uint32_t b =
          add_point(soup, on_plane(coordinate(0, n), coordinate(0, n), coordinate(-3, 3)));
      const std::uint32_t c =
          add_point(soup, on_plane(coordinate(0, n), coordinate(0, n), coordinate(-3, 3)));
      soup.triangles.push_back({a, b, c});
      break;
    }
    case 3: {  // touching from below at a grid vertex
      const std::uint32_t b = add_point(soup, on_plane(coordinate(0, n), coordinate(0, n), -1));
      const std::uint32_t c = add_point(soup, on_plane(coordinate(0, n), coordinate(0, n), -2));
      soup.triangles.push_back({vertex(), b, c});
      break;
    }
    case 4: {  // touching from below along a grid edge
      const Triangle& t = soup.triangles[rng() % soup.triangles.size()];
      const std::uint32_t c = add_point(soup, on_plane(coordinate(0, n), coordinate(0, n), -1));
      soup.triangles.push_back({t[1], t[0], c});
      break;
    }
    case 5: {  // touching from below along a chord between any two vertices
      const std::uint32_t c = add_point(soup, on_plane(coordinate(0, n), coordinate(0, n), -1));
      soup.triangles.push_back({vertex(), vertex(), c});
      break;
    }
    default: {  // a triangle repeated the other way round
      const Triangle t = soup.triangles[rng() % soup.triangles.size()];
      soup.triangles.push_back({t[0], t[2], t[1]});
      break;
    }
  }
}

TEST(PlanarFacets, SearchAgreesWithBruteForceOnDamagedGrids) {
  int checked = 0, refused = 0;
  for (std::uint32_t seed = 1; seed <= 600; ++seed) {
    std::mt19937 rng(seed);
    const int n = 2 + static_cast<int>(seed % 4);
    Soup soup = grid(n, rng);
    const int damages = static_cast<int>(rng() % 3);
    for (int k = 0; k < damages; ++k) damage(soup, n, rng);
    if (!valid(soup)) continue;
    std::vector<std::uint32_t> face_of(soup.triangles.size());
    for (std::uint32_t t = 0; t < face_of.size(); ++t) face_of[t] = t;
    const cvms::detail::TriangleTree tree(soup.points, soup.triangles);
    const auto found = cvms::detail::find_self_intersection(tree, soup.points, soup.triangles, face_of);
    const bool expected = brute_force_intersects(soup);
    ASSERT_EQ(found.faces.has_value(), expected) << "seed " << seed;
    // The located message names the first intersecting pair in the
    // hierarchy's order: every pair tested in that order must name the same.
    std::optional<std::pair<std::uint32_t, std::uint32_t>> first;
    tree.for_each_overlapping_pair([&](std::uint32_t s, std::uint32_t t) {
      if (!cvms::detail::triangles_overlap(soup.points, soup.triangles[s], soup.triangles[t])) return false;
      first = std::pair{s, t};
      return true;
    });
    ASSERT_EQ(found.faces, first) << "seed " << seed;
    ++checked;
    refused += expected ? 1 : 0;
  }
  // Both outcomes must be well represented for the agreement to mean much.
  EXPECT_GT(checked, 400);
  EXPECT_GT(refused, 80);
  EXPECT_GT(checked - refused, 80);
}

// Hand-checked facets: an undamaged grid is one certified facet; a grid
// with a hole punched out has two boundary loops and is not certified; a
// grid with an interior vertex moved beyond its far corner folds, and the
// overlap is found.
TEST(PlanarFacets, CertifiesOnlySimpleBoundaries) {
  std::mt19937 rng(7);
  const Soup soup = grid(3, rng);
  const cvms::detail::PlanarFacets facets(soup.points, soup.triangles);
  for (std::uint32_t t = 0; t < soup.triangles.size(); ++t) EXPECT_EQ(facets.of(t), 0U);
  EXPECT_TRUE(facets.certified(0));
  EXPECT_EQ(facets.size(0), soup.triangles.size());

  Soup holed = soup;
  // The middle square's two triangles are 8 and 9 (row 1, column 1).
  holed.triangles.erase(holed.triangles.begin() + 8, holed.triangles.begin() + 10);
  const cvms::detail::PlanarFacets holed_facets(holed.points, holed.triangles);
  EXPECT_FALSE(holed_facets.certified(holed_facets.of(0)));

  Soup folded = soup;
  folded.points[5] = on_plane(4, 4);  // vertex (1, 1) moved beyond the far corner
  const cvms::detail::PlanarFacets folded_facets(folded.points, folded.triangles);
  const cvms::detail::TriangleTree tree(folded.points, folded.triangles);
  std::vector<std::uint32_t> face_of(folded.triangles.size());
  for (std::uint32_t t = 0; t < face_of.size(); ++t) face_of[t] = t;
  EXPECT_TRUE(cvms::detail::find_self_intersection(tree, folded.points, folded.triangles, face_of).faces);
}

}  // namespace

namespace {

// The prism over a comb of 16 teeth (z in [0, 1]), as polygons: its top and
// bottom faces triangulate into long thin triangles.
cvms::PolygonSoup comb_prism() { return cvms::test::prism_over(cvms::test::comb_polygon(16), 0, 1); }

// Written as triangles, each its own face, the comb is still accepted; with
// one top corner of a tooth moved below the comb's base, within the top's
// plane, it crosses itself and is refused with the located message.
TEST(PlanarFacets, ThinTrianglesOfAValidSolidAreAcceptedAndADamagedOneRefused) {
  const cvms::PolygonSoup triangles = cvms::Solid::from_soup(comb_prism()).to_soup();
  for (std::size_t f = 0; f < triangles.num_faces(); ++f) ASSERT_EQ(triangles.face(f).size(), 3U);
  EXPECT_NO_THROW((void)cvms::Solid::from_soup(triangles));
  cvms::PolygonSoup damaged = triangles;
  const auto corner =
      std::find(damaged.points.begin(), damaged.points.end(), Vec3{Rational(30), Rational(4), Rational(1)});
  ASSERT_NE(corner, damaged.points.end());
  *corner = Vec3{Rational(30), Rational(-1), Rational(1)};
  try {
    (void)cvms::Solid::from_soup(damaged);
    FAIL() << "a self-crossing comb was accepted";
  } catch (const cvms::Error& e) {
    EXPECT_NE(std::string(e.what()).find("intersect (self-intersecting surface)"), std::string::npos)
        << e.what();
  }
}

}  // namespace
