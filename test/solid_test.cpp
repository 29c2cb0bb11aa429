// SPDX-License-Identifier: MIT
// Solid (cvms/solid.hpp) on small non-convex solids of test/data/solids and
// on a real mesh. Oracles: volumes, genus, shells and reflex edges counted
// by hand from the fixtures' comments; locate against a membership function
// written for each box-made fixture (see local_location).
#include "cvms/solid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/error.hpp"
#include "cvms/io.hpp"
#include "support/hand_solids.hpp"

namespace {

using cvms::ErrorCategory;
using cvms::Location;
using cvms::Rational;
using cvms::Solid;
using cvms::Vec3;

std::filesystem::path data(const std::string& name) {
  return std::filesystem::path(CVMS_TEST_DATA_DIR) / "solids" / name;
}

struct Expected {
  const char* file;
  Rational volume;
  std::uint32_t shells, cavities, genus, reflex_edges, facets;
  bool convex;
};

TEST(Solid, ValidFixturesHaveTheirHandCountedProperties) {
  const std::vector<Expected> cases = {
      {"l_block.off", 3, 1, 0, 0, 1, 8, false},
      {"star_prism.off", 32, 1, 0, 0, 4, 10, false},
      {"split_top_cube.off", 8, 1, 0, 0, 0, 6, true},
      {"box_with_hole.off", 8, 1, 0, 1, 4, 10, false},
      {"two_cubes.off", 2, 2, 0, 0, 0, 12, false},
      {"cavity_cube.off", 26, 2, 1, 0, 12, 12, false},
      {"collinear_cube.off", 8, 1, 0, 0, 0, 6, true},
      {"decimal_box.off", Rational(7, 320), 1, 0, 0, 0, 6, true},
      {"nested_shells.off", 99, 3, 1, 0, 12, 18, false},
  };
  for (const Expected& e : cases) {
    SCOPED_TRACE(e.file);
    const Solid s = cvms::read_solid(data(e.file));
    EXPECT_EQ(s.volume(), e.volume);
    EXPECT_EQ(s.num_shells(), e.shells);
    EXPECT_EQ(s.num_cavities(), e.cavities);
    EXPECT_EQ(s.genus(), e.genus);
    EXPECT_EQ(s.num_reflex_edges(), e.reflex_edges);
    EXPECT_EQ(s.num_facets(), e.facets);
    EXPECT_EQ(s.is_convex(), e.convex);
    // Every facet plane holds its triangles' corners, and its normal points
    // away from the solid: the triangles turn counterclockwise around it.
    for (std::size_t t = 0; t < s.triangles().size(); ++t) {
      const auto& tri = s.triangles()[t];
      const std::uint32_t f = s.triangle_facets()[t];
      const Vec3& n = s.facet_normal(f);
      for (std::uint32_t v : tri) EXPECT_EQ(cvms::dot(n, s.vertices()[v]), s.facet_offset(f));
      const Vec3 area = cvms::cross(s.vertices()[tri[1]] - s.vertices()[tri[0]],
                                    s.vertices()[tri[2]] - s.vertices()[tri[0]]);
      EXPECT_GT(cvms::dot(area, n), 0);
    }
  }
}

TEST(Solid, CoplanarFacesAndCollinearVerticesKeepTheirVertices) {
  const Solid top = cvms::read_solid(data("split_top_cube.off"));
  EXPECT_EQ(top.vertices().size(), 8u);
  EXPECT_EQ(top.triangles().size(), 12u);
  const Solid collinear = cvms::read_solid(data("collinear_cube.off"));
  EXPECT_EQ(collinear.vertices().size(), 9u);  // the midpoint stays, as a corner of triangles
  EXPECT_EQ(collinear.triangles().size(), 14u);
}

// Two unit cubes sharing an edge or a corner by index: two shells, the
// shared points held once per shell (8 vertices each), volume 2 by hand.
TEST(Solid, CubesSharingAnEdgeOrACornerAreTwoShellsThatTouch) {
  for (const char* file : {"cubes_sharing_edge.off", "cubes_sharing_corner.off"}) {
    SCOPED_TRACE(file);
    const Solid s = cvms::read_solid(data(file));
    EXPECT_EQ(s.num_shells(), 2u);
    EXPECT_EQ(s.num_cavities(), 0u);
    EXPECT_EQ(s.volume(), 2);
    EXPECT_EQ(s.vertices().size(), 16u);
    EXPECT_EQ(s.num_facets(), 12u);
    EXPECT_EQ(s.locate(Vec3{1, 1, Rational(1, 2)}), cvms::Location::boundary);
    EXPECT_EQ(s.locate(Vec3{Rational(3, 2), Rational(1, 2), Rational(1, 2)}), cvms::Location::outside);
    EXPECT_EQ(s.locate(Vec3{Rational(3, 2), Rational(3, 2), Rational(3, 2)}),
              std::string(file) == "cubes_sharing_corner.off" ? cvms::Location::inside : cvms::Location::outside);
  }
}

struct Invalid {
  const char* file;
  ErrorCategory category;
  std::vector<std::string> parts;  // substrings of the message
};

TEST(Solid, InvalidFixturesGiveLocatedErrors) {
  const std::vector<Invalid> cases = {
      {"open_box.off", ErrorCategory::topology, {"open surface", "boundary edge"}},
      {"fold.off", ErrorCategory::topology, {"intersect"}},
      {"inverted_cube.off", ErrorCategory::topology, {"inverted orientation", "shell of face 0"}},
      {"cavity_outward.off", ErrorCategory::topology, {"inconsistent orientation", "shell of face 6"}},
      {"bowtie_face.off", ErrorCategory::degenerate, {"face 1 is not simple"}},
      {"nonplanar_face.off", ErrorCategory::degenerate, {"face 1 is not planar", "vertex 7"}},
  };
  for (const Invalid& c : cases) {
    SCOPED_TRACE(c.file);
    try {
      (void)cvms::read_solid(data(c.file));
      ADD_FAILURE() << "accepted";
    } catch (const cvms::Error& e) {
      EXPECT_EQ(e.category(), c.category) << e.what();
      const std::string message = e.message();
      EXPECT_EQ(message.rfind(data(c.file).string() + ": ", 0), 0u) << message;
      for (const std::string& part : c.parts) EXPECT_NE(message.find(part), std::string::npos) << message;
    }
  }
}

// The closed axis-aligned box spanned by a face's corners (the fixture's
// faces are axis-aligned rectangles, so this is the face itself).
struct Rect {
  Vec3 lo, hi;
};
Rect face_rect(const cvms::PolygonSoup& soup, std::size_t f) {
  Rect r{soup.points[soup.face(f)[0]], soup.points[soup.face(f)[0]]};
  for (std::uint32_t v : soup.face(f))
    for (int k = 0; k < 3; ++k) {
      if (soup.points[v][k] < r.lo[k]) r.lo[k] = soup.points[v][k];
      if (soup.points[v][k] > r.hi[k]) r.hi[k] = soup.points[v][k];
    }
  return r;
}

TEST(Solid, OverlappingCubesNameTwoFacesThatReallyMeet) {
  const cvms::PolygonSoup soup = cvms::read_file(data("overlapping_cubes.off"));
  try {
    (void)Solid::from_soup(soup);
    FAIL() << "accepted";
  } catch (const cvms::Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::topology);
    unsigned a = 0, b = 0;
    ASSERT_EQ(std::sscanf(e.message(), "faces %u and %u intersect", &a, &b), 2) << e.what();
    EXPECT_LT(a, b);
    EXPECT_LT(a, 6u);  // one face of each cube
    EXPECT_GE(b, 6u);
    ASSERT_LT(b, 12u);
    const Rect ra = face_rect(soup, a);
    const Rect rb = face_rect(soup, b);
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(ra.lo[k] <= rb.hi[k] && rb.lo[k] <= ra.hi[k]) << e.what();
  }
}

cvms::PolygonSoup unit_cube_soup() {
  cvms::PolygonSoup soup;
  soup.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (auto f : {std::vector<std::uint32_t>{0, 3, 2, 1},
                 {4, 5, 6, 7},
                 {0, 1, 5, 4},
                 {1, 2, 6, 5},
                 {2, 3, 7, 6},
                 {3, 0, 4, 7}})
    soup.add_face(f);
  return soup;
}

void expect_error(cvms::PolygonSoup soup, ErrorCategory category, const std::string& part) {
  try {
    (void)Solid::from_soup(std::move(soup));
    ADD_FAILURE() << "accepted, expected " << part;
  } catch (const cvms::Error& e) {
    EXPECT_EQ(e.category(), category) << e.what();
    EXPECT_NE(std::string(e.message()).find(part), std::string::npos) << e.what();
  }
}

TEST(Solid, SoupLevelDefects) {
  {
    // Each face with its own copies of its corners: merged into 8 vertices.
    cvms::PolygonSoup cube = unit_cube_soup();
    cvms::PolygonSoup copies;
    for (std::size_t f = 0; f < cube.num_faces(); ++f) {
      std::vector<std::uint32_t> face;
      for (std::uint32_t v : cube.face(f)) {
        face.push_back(static_cast<std::uint32_t>(copies.points.size()));
        copies.points.push_back(cube.points[v]);
      }
      copies.add_face(face);
    }
    copies.points.push_back({5, 5, 5});  // used by no face: ignored
    const Solid s = Solid::from_soup(copies);
    EXPECT_EQ(s.vertices().size(), 8u);
    EXPECT_EQ(s.volume(), 1);
    EXPECT_TRUE(s.is_convex());
  }
  {
    cvms::PolygonSoup soup = unit_cube_soup();
    soup.points[7] = {0, 0, 1};  // equal to point 4: face 1 repeats a vertex
    expect_error(soup, ErrorCategory::degenerate, "face 1 uses vertex 4 more than once");
  }
  {
    cvms::PolygonSoup soup;
    soup.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 1}};
    soup.add_face({0, 1, 2});
    soup.add_face({0, 2, 3});
    expect_error(soup, ErrorCategory::degenerate, "face 0 has zero area");
  }
  {
    cvms::PolygonSoup soup = unit_cube_soup();
    soup.face_indices[0] = 9;
    expect_error(soup, ErrorCategory::topology, "face 0: vertex index 9 out of range");
  }
  {
    cvms::PolygonSoup soup = unit_cube_soup();
    std::swap(soup.face_indices[4], soup.face_indices[5]);  // face 1 reversed in part: a bow tie
    expect_error(soup, ErrorCategory::degenerate, "face 1 is not simple");
  }
  {
    // Face 1 reversed: its edges run as their neighbours' do.
    cvms::PolygonSoup soup = unit_cube_soup();
    std::reverse(soup.face_indices.begin() + 4, soup.face_indices.begin() + 8);
    expect_error(soup, ErrorCategory::topology, "in the same direction (inconsistent orientation)");
  }
  expect_error(cvms::PolygonSoup{}, ErrorCategory::topology, "empty solid");
  {
    // A prism over a polygon of 4097 corners: refused before its quadratic checks.
    cvms::PolygonSoup soup;
    const std::uint32_t n = 4097;
    for (std::uint32_t i = 0; i < n; ++i) soup.points.push_back({i, static_cast<long>(i) * i, 0});
    std::vector<std::uint32_t> cap(n);
    for (std::uint32_t i = 0; i < n; ++i) cap[i] = i;
    soup.add_face(cap);
    expect_error(soup, ErrorCategory::limit, "face 0 has 4097 vertices; at most 4096");
  }
}

// Random soups on a small grid: every one is a valid solid or a cvms::Error,
// and a valid one has positive volume and its vertices on its boundary.
TEST(Solid, RandomSoupsAreSolidsOrErrors) {
  const unsigned seed = 77;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coordinate(0, 2);
  int valid = 0;
  for (int round = 0; round < 300; ++round) {
    SCOPED_TRACE("seed " + std::to_string(seed) + ", round " + std::to_string(round));
    // A unit cube's faces with one or two vertices moved on the grid, or
    // random triangles on the cube's points.
    cvms::PolygonSoup soup = unit_cube_soup();
    if (round % 3 == 2) {
      soup.face_offsets = {0};
      soup.face_indices.clear();
      std::uniform_int_distribution<std::uint32_t> corner(0, 7);
      for (int f = 0; f < 8; ++f) soup.add_face({corner(rng), corner(rng), corner(rng)});
    } else {
      for (int moved = 0; moved <= round % 3; ++moved)
        soup.points[static_cast<std::size_t>(coordinate(rng) * 3 + coordinate(rng)) % 8] = {
            coordinate(rng), coordinate(rng), coordinate(rng)};
    }
    try {
      const Solid s = Solid::from_soup(soup);
      ++valid;
      EXPECT_GT(s.volume(), 0);
      for (const Vec3& v : s.vertices()) EXPECT_EQ(s.locate(v), Location::boundary);
    } catch (const cvms::Error&) {
    }
  }
  EXPECT_GT(valid, 0);
}

// The location of p in a closed union of boxes with integer corners, for p
// on the quarter grid: near such a p the set is a union of closed octants
// at p (every boundary plane within 1/16 of p passes through p), so p is
// interior iff the 8 points p + (+-1/16, +-1/16, +-1/16) are all in it.
Location local_location(const std::function<bool(const Vec3&)>& in_closed_set, const Vec3& p) {
  if (!in_closed_set(p)) return Location::outside;
  const Rational d(1, 16);
  for (int mask = 0; mask < 8; ++mask) {
    const Vec3 q{p.x + ((mask & 1) != 0 ? d : -d), p.y + ((mask & 2) != 0 ? d : -d),
                 p.z + ((mask & 4) != 0 ? d : -d)};
    if (!in_closed_set(q)) return Location::boundary;
  }
  return Location::inside;
}

bool in_box(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  return lo.x <= p.x && p.x <= hi.x && lo.y <= p.y && p.y <= hi.y && lo.z <= p.z && p.z <= hi.z;
}
bool in_open_box(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  return lo.x < p.x && p.x < hi.x && lo.y < p.y && p.y < hi.y && lo.z < p.z && p.z < hi.z;
}

TEST(Solid, LocateAgreesWithMembershipOfBoxes) {
  struct Case {
    const char* file;
    std::function<bool(const Vec3&)> in;
  };
  const std::vector<Case> cases = {
      {"l_block.off",
       [](const Vec3& p) {
         return in_box(p, {0, 0, 0}, {2, 1, 1}) || in_box(p, {0, 0, 0}, {1, 2, 1});
       }},
      {"box_with_hole.off",
       [](const Vec3& p) {
         return in_box(p, {0, 0, 0}, {3, 1, 1}) || in_box(p, {0, 2, 0}, {3, 3, 1}) ||
                in_box(p, {0, 0, 0}, {1, 3, 1}) || in_box(p, {2, 0, 0}, {3, 3, 1});
       }},
      {"two_cubes.off",
       [](const Vec3& p) {
         return in_box(p, {0, 0, 0}, {1, 1, 1}) || in_box(p, {2, 2, 2}, {3, 3, 3});
       }},
      {"cavity_cube.off",
       [](const Vec3& p) {
         return in_box(p, {0, 0, 0}, {3, 3, 3}) && !in_open_box(p, {1, 1, 1}, {2, 2, 2});
       }},
      {"split_top_cube.off",
       [](const Vec3& p) {
         return in_box(p, {0, 0, 0}, {2, 2, 2});
       }},
      {"collinear_cube.off",
       [](const Vec3& p) {
         return in_box(p, {0, 0, 0}, {2, 2, 2});
       }},
  };
  const unsigned seed = 4049;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> quarter(-2, 22);  // -1/2 .. 11/2
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.file) + ", seed " + std::to_string(seed));
    const Solid s = cvms::read_solid(data(c.file));
    int counts[3] = {0, 0, 0};
    for (int i = 0; i < 600; ++i) {
      const Vec3 p{Rational(quarter(rng), 4), Rational(quarter(rng), 4), Rational(quarter(rng), 4)};
      const Location expected = local_location(c.in, p);
      ++counts[static_cast<int>(expected)];
      ASSERT_EQ(s.locate(p), expected) << "p = (" << p.x << ", " << p.y << ", " << p.z << ")";
    }
    // The grid reaches all three answers.
    EXPECT_GT(counts[0], 0);
    EXPECT_GT(counts[1], 0);
    EXPECT_GT(counts[2], 0);
  }
}

// The prism z in [0, 1] over a comb of k teeth: a base [0, 3k - 2] x [0, 1]
// and teeth [3i, 3i + 1] x [1, 4]. Its caps are polygons of 4k corners
// whose triangulations hold long thin triangles spanning the base, the case
// where the ray search must keep its boxes apart.
Solid comb_prism(int k) {
  return Solid::from_soup(cvms::test::prism_over(cvms::test::comb_polygon(k), 0, 1));
}

TEST(Solid, LocateInACombPrismAgreesWithItsTeeth) {
  constexpr int k = 24;
  const Solid comb = comb_prism(k);
  const auto in = [](const Vec3& p) {
    if (!in_box(p, {0, 0, 0}, {3 * k - 2, 1, 1})) {
      if (p.x < 0 || p.x > 3 * k - 2) return false;
      const Rational tooth = p.x / 3;  // in a tooth iff x - 3 floor(x / 3) <= 1 (or x = 3i)
      const Rational base(tooth.get_num() / tooth.get_den());
      return in_box(p, {3 * base, 1, 0}, {3 * base + 1, 4, 1});
    }
    return true;
  };
  const unsigned seed = 5011;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> x_quarter(-2, 4 * (3 * k - 1)), y_quarter(-2, 18), z_quarter(-2, 6);
  int counts[3] = {0, 0, 0};
  for (int i = 0; i < 1500; ++i) {
    const Vec3 p{Rational(x_quarter(rng), 4), Rational(y_quarter(rng), 4), Rational(z_quarter(rng), 4)};
    const Location expected = local_location(in, p);
    ++counts[static_cast<int>(expected)];
    ASSERT_EQ(comb.locate(p), expected) << "seed " << seed << ", p = (" << p.x << ", " << p.y << ", " << p.z << ")";
  }
  EXPECT_GT(counts[0], 0);
  EXPECT_GT(counts[1], 0);
  EXPECT_GT(counts[2], 0);
}

TEST(Solid, LocateOnTheStarPrismAndDecimalBox) {
  const Solid star = cvms::read_solid(data("star_prism.off"));
  EXPECT_EQ(star.locate({0, 0, 1}), Location::inside);
  EXPECT_EQ(star.locate({3, 0, 1}), Location::inside);                              // in a point of the star
  EXPECT_EQ(star.locate({2, 2, 1}), Location::outside);                             // between two points
  EXPECT_EQ(star.locate({Rational(5, 2), Rational(1, 2), 1}), Location::boundary);  // on the edge (4,0)-(1,1)
  EXPECT_EQ(star.locate({1, 1, 1}), Location::boundary);                            // on a reflex edge
  EXPECT_EQ(star.locate({0, 0, 2}), Location::boundary);                            // on the top cap
  EXPECT_EQ(star.locate({0, 0, 3}), Location::outside);
  const Solid box = cvms::read_solid(data("decimal_box.off"));
  EXPECT_EQ(box.locate({Rational(1, 5), 0, Rational(6, 5)}), Location::inside);
  EXPECT_EQ(box.locate({Rational(1, 10), 0, Rational(6, 5)}), Location::boundary);
  EXPECT_EQ(box.locate({Rational(1, 10), Rational(-1, 5), Rational(21, 20)}),
            Location::boundary);  // a corner
  EXPECT_EQ(box.locate({Rational(9, 100), 0, Rational(6, 5)}), Location::outside);
}

TEST(Solid, ConversionsAndEmpty) {
  const Solid empty;
  EXPECT_EQ(empty.num_shells(), 0u);
  EXPECT_EQ(empty.volume(), 0);
  EXPECT_EQ(empty.locate({0, 0, 0}), Location::outside);
  EXPECT_EQ(empty.to_soup().num_faces(), 0u);

  const Solid cube = Solid::from_polyhedron(cvms::ConvexPolyhedron::from_soup(unit_cube_soup()));
  EXPECT_EQ(cube.volume(), 1);
  EXPECT_TRUE(cube.is_convex());
  EXPECT_EQ(cube.num_facets(), 6u);
  EXPECT_EQ(cube.locate({Rational(1, 2), Rational(1, 2), Rational(1, 2)}), Location::inside);
  EXPECT_EQ(cube.locate({1, 1, 1}), Location::boundary);

  const Solid hole = cvms::read_solid(data("box_with_hole.off"));
  const Solid again = Solid::from_soup(hole.to_soup());
  EXPECT_EQ(again.volume(), hole.volume());
  EXPECT_EQ(again.genus(), 1u);
  EXPECT_EQ(again.num_facets(), hole.num_facets());
}

TEST(Solid, CopiesLocateConcurrently) {
  // The cavity cube's hierarchy exists after validation; the polyhedron's is
  // built by whichever thread asks first.
  const Solid validated = cvms::read_solid(data("cavity_cube.off"));
  const Solid lazy = Solid::from_polyhedron(cvms::ConvexPolyhedron::from_soup(unit_cube_soup()));
  std::vector<std::thread> threads;
  std::vector<int> wrong(4, 0);
  for (int i = 0; i < 4; ++i)
    threads.emplace_back([copy = validated, lazy_copy = lazy, &wrong, i] {  // each its own copies
      for (int k = 0; k < 50; ++k) {
        const Rational t(k + 1, 52);
        if (lazy_copy.locate({t, t, t}) != Location::inside) ++wrong[i];
        if (copy.locate({Rational(3, 2), Rational(3, 2), Rational(3, 2)}) != Location::outside) ++wrong[i];
        if (copy.locate({Rational(1, 2), t, Rational(1, 2)}) != Location::inside) ++wrong[i];
      }
    });
  for (auto& t : threads) t.join();
  for (int w : wrong) EXPECT_EQ(w, 0);
}

TEST(Solid, RealMeshValidates) {
  const auto start = std::chrono::steady_clock::now();
  cvms::PolygonSoup soup = cvms::read_file(data("spot.obj"));
  const auto read = std::chrono::steady_clock::now();
  const Solid spot = Solid::from_soup(std::move(soup));
  const auto done = std::chrono::steady_clock::now();
  std::printf("spot.obj: read in %.3f s, validated in %.3f s (%zu vertices, %zu triangles)\n",
              std::chrono::duration<double>(read - start).count(),
              std::chrono::duration<double>(done - read).count(), spot.vertices().size(),
              spot.triangles().size());
  EXPECT_EQ(spot.num_shells(), 1u);
  EXPECT_EQ(spot.num_cavities(), 0u);
  EXPECT_EQ(spot.genus(), 0u);
  EXPECT_GT(spot.volume(), 0);
  EXPECT_GT(spot.num_reflex_edges(), 0u);
  EXPECT_FALSE(spot.is_convex());
  // Every vertex is on the boundary; points beyond the bounding box are outside.
  for (std::size_t v = 0; v < spot.vertices().size(); v += 7)
    ASSERT_EQ(spot.locate(spot.vertices()[v]), Location::boundary) << "vertex " << v;
  Vec3 lo = spot.vertices()[0], hi = lo;
  for (const Vec3& p : spot.vertices())
    for (int k = 0; k < 3; ++k) {
      if (p[k] < lo[k]) lo[k] = p[k];
      if (p[k] > hi[k]) hi[k] = p[k];
    }
  const auto located = std::chrono::steady_clock::now();
  for (int i = 0; i < 100; ++i) {
    const Rational t(i, 100);
    ASSERT_EQ(spot.locate({hi.x + t, lo.y + t, lo.z}), Location::outside) << i;
    ASSERT_EQ(spot.locate({lo.x - t, hi.y - t, hi.z}), Location::outside) << i;
  }
  std::printf("spot.obj: 200 outside points located in %.3f s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - located).count());
}

TEST(Solid, ManyDisjointPartsValidate) {
  // 6 x 6 x 6 unit cubes two apart, with a cube-shaped cavity in the last one.
  cvms::PolygonSoup soup;
  const cvms::PolygonSoup cube = unit_cube_soup();
  auto add_cube = [&](const Vec3& at, const Rational& scale, bool inward) {
    const auto base = static_cast<std::uint32_t>(soup.points.size());
    for (const Vec3& p : cube.points) soup.points.push_back(at + scale * p);
    for (std::size_t f = 0; f < cube.num_faces(); ++f) {
      std::vector<std::uint32_t> face;
      for (std::uint32_t v : cube.face(f)) face.push_back(base + v);
      if (inward) std::reverse(face.begin(), face.end());
      soup.add_face(face);
    }
  };
  for (int x = 0; x < 6; ++x)
    for (int y = 0; y < 6; ++y)
      for (int z = 0; z < 6; ++z) add_cube({2 * x, 2 * y, 2 * z}, 1, false);
  add_cube({Rational(41, 4), Rational(41, 4), Rational(41, 4)}, Rational(1, 2), true);
  const Solid s = Solid::from_soup(soup);
  EXPECT_EQ(s.num_shells(), 217u);
  EXPECT_EQ(s.num_cavities(), 1u);
  EXPECT_EQ(s.volume(), 216 - Rational(1, 8));
  EXPECT_EQ(s.locate({Rational(21, 2), Rational(21, 2), Rational(21, 2)}),
            Location::outside);  // in the cavity
  EXPECT_EQ(s.locate({Rational(101, 10), Rational(101, 10), Rational(101, 10)}), Location::inside);
  EXPECT_EQ(s.locate({Rational(3, 2), Rational(1, 2), Rational(1, 2)}), Location::outside);  // between cubes
}

// Inside or outside by brute force, independently of the library's ray
// test: the crossings of the ray from p along +x with every triangle, in
// plain rational arithmetic (the triangle projected on the yz-plane contains
// (p.y, p.z), and the triangle's plane lies ahead there). Nothing when the
// ray meets an edge or a vertex (a degenerate sample).
std::optional<bool> inside_by_x_ray(const Solid& s, const Vec3& p) {
  bool odd = false;
  for (const auto& t : s.triangles()) {
    const Vec3& a = s.vertices()[t[0]];
    const Vec3& b = s.vertices()[t[1]];
    const Vec3& c = s.vertices()[t[2]];
    if ((p.y < a.y && p.y < b.y && p.y < c.y) || (p.y > a.y && p.y > b.y && p.y > c.y)) continue;
    if ((p.z < a.z && p.z < b.z && p.z < c.z) || (p.z > a.z && p.z > b.z && p.z > c.z)) continue;
    auto side = [&](const Vec3& u, const Vec3& v) {
      const Rational value = (v.y - u.y) * (p.z - u.z) - (v.z - u.z) * (p.y - u.y);
      return sgn(value);
    };
    const int s1 = side(a, b), s2 = side(b, c), s3 = side(c, a);
    if ((s1 > 0 || s2 > 0 || s3 > 0) && (s1 < 0 || s2 < 0 || s3 < 0)) continue;
    const Vec3 n = cvms::cross(b - a, c - a);
    if (sgn(n.x) == 0) continue;  // the plane is parallel to the ray
    if (s1 == 0 || s2 == 0 || s3 == 0) return std::nullopt;
    // The plane's x above (p.y, p.z): n.x (x - a.x) + n.y (p.y - a.y) + n.z (p.z - a.z) = 0.
    const Rational x = a.x - (n.y * (p.y - a.y) + n.z * (p.z - a.z)) / n.x;
    if (x == p.x) return std::nullopt;
    if (x > p.x) odd = !odd;
  }
  return odd;
}

TEST(Solid, LocateInTheRealMeshAgreesWithBruteForce) {
  const Solid spot = cvms::read_solid(data("spot.obj"));
  const unsigned seed = 2930;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coordinate(-1000, 1000);
  int inside = 0, compared = 0;
  for (int i = 0; i < 60; ++i) {
    const Vec3 p{Rational(coordinate(rng), 1700), Rational(coordinate(rng), 1100),
                 Rational(coordinate(rng), 1000)};
    const std::optional<bool> expected = inside_by_x_ray(spot, p);
    if (!expected) continue;
    ++compared;
    inside += *expected ? 1 : 0;
    EXPECT_EQ(spot.locate(p), *expected ? Location::inside : Location::outside)
        << "seed " << seed << ", p = (" << p.x << ", " << p.y << ", " << p.z << ")";
  }
  EXPECT_GT(compared, 50);
  EXPECT_GT(inside, 0);
}

TEST(Solid, PlantedIntersectionInTheRealMeshIsFound) {
  cvms::PolygonSoup soup = cvms::read_file(data("spot.obj"));
  // Vertex 0 mirrored through the centroid of the points: its triangles now
  // reach across the model and pass through the surface.
  Vec3 centroid{0, 0, 0};
  for (const Vec3& p : soup.points) centroid += p;
  centroid = centroid * Rational(1, static_cast<long>(soup.points.size()));
  soup.points[0] = centroid * Rational(2) - soup.points[0];
  try {
    (void)Solid::from_soup(soup);
    FAIL() << "accepted";
  } catch (const cvms::Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::topology) << e.what();
    unsigned a = 0, b = 0;
    ASSERT_EQ(std::sscanf(e.message(), "faces %u and %u intersect", &a, &b), 2) << e.what();
    // Only triangles at vertex 0 moved, so one of the two is one of them.
    auto uses_vertex_0 = [&](unsigned f) {
      for (std::uint32_t v : soup.face(f))
        if (v == 0) return true;
      return false;
    };
    EXPECT_TRUE(uses_vertex_0(a) || uses_vertex_0(b)) << e.what();
  }
}

}  // namespace
