// SPDX-License-Identifier: MIT
// Tests of the half-edge mesh: construction, navigation, circulators, round
// trip to a soup, and every topology error of Mesh::from_soup.
#include "cvms/mesh.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <string>
#include <vector>

#include "cvms/error.hpp"
#include "support/hand_solids.hpp"

namespace cvms {
namespace {

using test::make_soup;
using test::v3;

// Expects from_soup to throw Error(category) whose message contains every
// string of `parts`.
void expect_error(const PolygonSoup& soup, ErrorCategory category, std::initializer_list<std::string> parts) {
  try {
    (void)Mesh::from_soup(soup);
    ADD_FAILURE() << "no error thrown";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), category) << e.what();
    for (const std::string& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(Mesh, TetrahedronCountsAndNavigation) {
  PolygonSoup soup = test::tetrahedron();
  Mesh m = Mesh::from_soup(soup);
  EXPECT_EQ(m.num_vertices(), 4u);
  EXPECT_EQ(m.num_edges(), 6u);
  EXPECT_EQ(m.num_halfedges(), 12u);
  EXPECT_EQ(m.num_faces(), 4u);
  EXPECT_NO_THROW(m.validate());
  for (HalfedgeId h : m.halfedges()) {
    EXPECT_EQ(Mesh::twin(Mesh::twin(h)), h);
    EXPECT_EQ(Mesh::edge(h), Mesh::edge(Mesh::twin(h)));
    EXPECT_EQ(m.from(h), m.to(Mesh::twin(h)));
    EXPECT_EQ(m.next(m.prev(h)), h);
    EXPECT_EQ(m.face(m.next(h)), m.face(h));
    EXPECT_NE(m.face(h), m.face(Mesh::twin(h)));
  }
  // Halfedge 2e runs from the smaller to the larger vertex index.
  for (EdgeId e : m.edges()) {
    HalfedgeId h = Mesh::halfedge(e);
    EXPECT_LT(m.from(h).index(), m.to(h).index());
    EXPECT_EQ(Mesh::edge(h), e);
  }
  for (VertexId v : m.vertices()) EXPECT_EQ(m.from(m.halfedge(v)), v);
}

TEST(Mesh, FaceCirculatorFollowsInputOrder) {
  PolygonSoup soup = test::cube_quads();
  Mesh m = Mesh::from_soup(soup);
  ASSERT_EQ(m.num_faces(), 6u);
  for (FaceId f : m.faces()) {
    std::vector<std::uint32_t> got;
    for (HalfedgeId h : m.face_halfedges(f)) got.push_back(m.from(h).index());
    auto want = soup.face(f.index());
    EXPECT_EQ(got, std::vector<std::uint32_t>(want.begin(), want.end()));
    EXPECT_EQ(m.degree(f), 4u);
  }
}

TEST(Mesh, VertexCirculatorIsCounterclockwiseFromOutside) {
  // Cube centred at (1/2, 1/2, 1/2): the outward direction at v is v - centre.
  for (const PolygonSoup& soup : {test::cube_quads(), test::cube_triangles(), test::octahedron()}) {
    Mesh m = Mesh::from_soup(soup);
    Vec3 centre{0, 0, 0};
    for (const Vec3& p : soup.points) centre += p;
    centre = Rational(1, static_cast<long>(soup.points.size())) * centre;
    for (VertexId v : m.vertices()) {
      std::vector<HalfedgeId> out;
      for (HalfedgeId h : m.outgoing_halfedges(v)) {
        EXPECT_EQ(m.from(h), v);
        out.push_back(h);
        ASSERT_LE(out.size(), m.num_halfedges());
      }
      std::set<HalfedgeId> unique(out.begin(), out.end());
      EXPECT_EQ(unique.size(), out.size());
      const Vec3 up = m.position(v) - centre;
      for (std::size_t i = 0; i < out.size(); ++i) {
        HalfedgeId h = out[i], g = out[(i + 1) % out.size()];
        EXPECT_EQ(g, Mesh::twin(m.prev(h)));
        Vec3 a = m.position(m.to(h)) - m.position(v), b = m.position(m.to(g)) - m.position(v);
        EXPECT_GT(dot(cross(a, b), up), 0) << "vertex " << v.index() << " step " << i;
      }
    }
  }
}

TEST(Mesh, EveryHalfedgeAppearsOnceInFacesAndFans) {
  Mesh m = Mesh::from_soup(test::subdivided(test::prism(), 1));
  std::vector<int> in_face(m.num_halfedges(), 0), in_fan(m.num_halfedges(), 0);
  for (FaceId f : m.faces())
    for (HalfedgeId h : m.face_halfedges(f)) {
      ++in_face[h.index()];
      EXPECT_EQ(m.face(h), f);
    }
  for (VertexId v : m.vertices())
    for (HalfedgeId h : m.outgoing_halfedges(v)) ++in_fan[h.index()];
  for (HalfedgeId h : m.halfedges()) {
    EXPECT_EQ(in_face[h.index()], 1);
    EXPECT_EQ(in_fan[h.index()], 1);
  }
  EXPECT_EQ(static_cast<int>(m.num_vertices()) - static_cast<int>(m.num_edges()) + static_cast<int>(m.num_faces()), 2);
}

// A circulator may start at any halfedge of its cycle: it visits the whole
// cycle once, in the order of the one from the stored halfedge, rotated.
TEST(Mesh, CirculatorsStartAnywhereInTheirCycle) {
  Mesh m = Mesh::from_soup(test::subdivided(test::prism(), 1));
  // Each rotation of `stored`, the cycle from its stored halfedge, from a
  // circulator started at its k-th halfedge.
  const auto expect_rotations = [&](const std::vector<HalfedgeId>& stored, HalfedgeCirculator::Kind kind,
                                    const std::string& cycle) {
    for (std::size_t k = 0; k < stored.size(); ++k) {
      std::vector<HalfedgeId> got;
      for (HalfedgeId h : HalfedgeCirculator(&m, stored[k], kind)) {
        got.push_back(h);
        ASSERT_LE(got.size(), stored.size()) << cycle << " from its halfedge " << k;
      }
      ASSERT_EQ(got.size(), stored.size()) << cycle << " from its halfedge " << k;
      for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i], stored[(k + i) % got.size()]) << cycle;
    }
  };
  for (VertexId v : m.vertices()) {
    std::vector<HalfedgeId> stored;
    for (HalfedgeId h : m.outgoing_halfedges(v)) stored.push_back(h);
    expect_rotations(stored, HalfedgeCirculator::Kind::vertex, "vertex " + std::to_string(v.index()));
  }
  for (FaceId f : m.faces()) {
    std::vector<HalfedgeId> stored;
    for (HalfedgeId h : m.face_halfedges(f)) stored.push_back(h);
    expect_rotations(stored, HalfedgeCirculator::Kind::face, "face " + std::to_string(f.index()));
  }
}

TEST(Mesh, SoupRoundTrip) {
  PolygonSoup soup = test::subdivided(test::cube_quads(), 1);
  Mesh m = Mesh::from_soup(soup);
  PolygonSoup back = m.to_soup();
  EXPECT_EQ(back.points, soup.points);
  EXPECT_EQ(back.face_offsets, soup.face_offsets);
  EXPECT_EQ(back.face_indices, soup.face_indices);
}

TEST(Mesh, WithPositionsKeepsConnectivity) {
  Mesh m = Mesh::from_soup(test::tetrahedron());
  std::vector<Vec3> moved;
  for (VertexId v : m.vertices()) moved.push_back(m.position(v) + v3(5, 6, 7));
  Mesh t = m.with_positions(moved);
  EXPECT_NO_THROW(t.validate());
  EXPECT_EQ(t.positions(), moved);
  for (HalfedgeId h : m.halfedges()) EXPECT_EQ(t.next(h), m.next(h));
  try {
    (void)m.with_positions({v3(0, 0, 0)});
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
  }
}

TEST(Mesh, TwoSidedPolygonIsAValidClosedSurface) {
  // Topologically a sphere (V - E + F = 3 - 3 + 2); geometry is not Mesh's business.
  Mesh m = Mesh::from_soup(make_soup({v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0)}, {{0, 1, 2}, {0, 2, 1}}));
  EXPECT_EQ(m.num_edges(), 3u);
  EXPECT_NO_THROW(m.validate());
}

// ---- bad input: one test per case -------------------------------------------

TEST(MeshBadInput, EmptySoup) {
  expect_error(PolygonSoup{}, ErrorCategory::topology, {"empty"});
  expect_error(make_soup({v3(0, 0, 0)}, {}), ErrorCategory::topology, {"empty"});
}

TEST(MeshBadInput, MalformedOffsets) {
  PolygonSoup s = test::tetrahedron();
  s.face_offsets.back() += 1;
  expect_error(s, ErrorCategory::invalid_argument, {"face_offsets"});
  PolygonSoup t = test::tetrahedron();
  t.face_offsets.clear();
  expect_error(t, ErrorCategory::invalid_argument, {"face_offsets"});
  PolygonSoup u = test::tetrahedron();
  std::swap(u.face_offsets[1], u.face_offsets[2]);
  expect_error(u, ErrorCategory::invalid_argument, {"face 1"});
}

TEST(MeshBadInput, FaceWithTwoVertices) {
  PolygonSoup s = test::tetrahedron();
  s.add_face({0, 1});
  expect_error(s, ErrorCategory::topology, {"face 4", "2 vertices"});
}

TEST(MeshBadInput, RepeatedVertexInFace) {
  PolygonSoup s = make_soup(test::tetrahedron().points, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2, 3}, {1, 2, 3}});
  expect_error(s, ErrorCategory::topology, {"face 2", "vertex 3", "more than once"});
}

TEST(MeshBadInput, IndexOutOfRange) {
  PolygonSoup s = make_soup(test::tetrahedron().points, {{0, 2, 1}, {0, 1, 3}, {0, 3, 7}, {1, 2, 3}});
  expect_error(s, ErrorCategory::topology, {"face 2", "index 7", "out of range"});
}

TEST(MeshBadInput, OpenMesh) {
  PolygonSoup cube = test::cube_quads();
  PolygonSoup s;
  s.points = cube.points;
  for (std::size_t f = 1; f < cube.num_faces(); ++f) s.add_face(cube.face(f));  // bottom face missing
  // The bottom face gone, faces are renumbered: edge (0, 1) is left in {0, 1, 5, 4}, now face 1.
  expect_error(s, ErrorCategory::topology, {"boundary edge", "open", "edge (0, 1) of face 1 "});
}

TEST(MeshBadInput, NonManifoldEdge) {
  // Two tetrahedra sharing edge (0, 1): four faces on that edge.
  std::vector<Vec3> p{v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 1), v3(0, -1, 0), v3(0, 0, -1)};
  PolygonSoup s = make_soup(p, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3},    // tetra 0,1,2,3
                                {0, 4, 1}, {0, 1, 5}, {0, 5, 4}, {1, 4, 5}});  // tetra 0,1,4,5
  expect_error(s, ErrorCategory::topology, {"edge (0, 1)", "4 faces (0, 1, 4, 5)", "non-manifold edge"});
}

TEST(MeshBadInput, NonManifoldVertex) {
  // Two tetrahedra sharing only vertex 0.
  std::vector<Vec3> p{v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 1), v3(-1, 0, 0), v3(0, -1, 0), v3(0, 0, -1)};
  PolygonSoup s = make_soup(p, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3},    //
                                {0, 4, 5}, {0, 5, 6}, {0, 6, 4}, {4, 6, 5}});  //
  expect_error(s, ErrorCategory::topology, {"vertex 0", "non-manifold vertex"});
}

TEST(MeshBadInput, OneFlippedFace) {
  PolygonSoup cube = test::cube_triangles();
  PolygonSoup s;
  s.points = cube.points;
  for (std::size_t f = 0; f < cube.num_faces(); ++f) {
    auto face = cube.face(f);
    if (f == 5)
      s.add_face({face[0], face[2], face[1]});
    else
      s.add_face(face);
  }
  expect_error(s, ErrorCategory::topology, {"same direction", "inconsistent orientation", "faces 5 and"});
}

TEST(MeshBadInput, InconsistentOrientationNamesEdgeAndFaces) {
  // Half of a tetrahedron flipped: edge (1, 2) used 1 -> 2 by faces 0 and 3... build it by hand.
  PolygonSoup s = make_soup(test::tetrahedron().points, {{0, 1, 2}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
  // faces 0 and 1 both use 0 -> 1.
  expect_error(s, ErrorCategory::topology, {"edge (0, 1)", "faces 0 and 1", "inconsistent orientation"});
}

TEST(MeshBadInput, DuplicatePoints) {
  PolygonSoup s = test::tetrahedron();
  s.points.push_back(v3(1, 0, 0));  // equal to vertex 1
  s.add_face({4, 2, 3});           // keep it referenced; topology errors follow, but duplicates come first
  expect_error(s, ErrorCategory::topology, {"vertices 1 and 4", "same point"});
}

TEST(MeshBadInput, DuplicatePointsWrittenDifferently) {
  // 0/3 built without canonicalisation still equals 0.
  PolygonSoup s = test::tetrahedron();
  s.points.push_back(Vec3{Rational(0, 3), Rational(2, 2), Rational(0)});  // equal to vertex 2
  s.add_face({4, 1, 3});
  expect_error(s, ErrorCategory::topology, {"vertices 2 and 4", "same point"});
  // Negative and power-of-two denominators over even or negative numerators.
  PolygonSoup t = test::tetrahedron();
  t.points.push_back(Vec3{Rational(-4, -4), Rational(0, -8), Rational(0, 1)});  // equal to vertex 1
  t.add_face({4, 2, 3});
  expect_error(t, ErrorCategory::topology, {"vertices 1 and 4", "same point"});
}

// Fractions over 2^a 5^b (decimals) as a caller may build them without
// canonicalisation: the numerator shares a 2 (6/20), a 5 (15/10), both
// (50/100) or neither (3/10, already canonical), and zero over 10. The
// mesh holds them in lowest terms (hand-reduced values and denominators),
// and an unreduced copy of a point is found as a duplicate.
TEST(Mesh, DecimalFractionsAreKeptInLowestTerms) {
  PolygonSoup s = test::tetrahedron();
  s.points[1] = Vec3{Rational(6, 20), Rational(0, 10), Rational(0)};
  s.points[2] = Vec3{Rational(0), Rational(15, 10), Rational(0)};
  s.points[3] = Vec3{Rational(0), Rational(0), Rational(50, 100)};
  s.points[0] = Vec3{Rational(0), Rational(0), Rational(-3, 10)};
  const Mesh m = Mesh::from_soup(s);
  const struct {
    std::uint32_t vertex;
    int axis;
    long num, den;
  } expected[] = {{1, 0, 3, 10}, {1, 1, 0, 1}, {2, 1, 3, 2}, {3, 2, 1, 2}, {0, 2, -3, 10}};
  for (const auto& e : expected) {
    const Rational& q = m.position(VertexId(e.vertex))[e.axis];
    EXPECT_EQ(q.get_num(), e.num) << "vertex " << e.vertex << " axis " << e.axis;
    EXPECT_EQ(q.get_den(), e.den) << "vertex " << e.vertex << " axis " << e.axis;
  }
  PolygonSoup t = s;
  t.points.push_back(Vec3{Rational(0), Rational(300, 200), Rational(0, 1000)});  // equal to vertex 2
  t.add_face({4, 1, 3});
  expect_error(t, ErrorCategory::topology, {"vertices 2 and 4", "same point"});
}

// Distinct points whose coordinates round to the same doubles: here one
// sits between the two copies of a duplicated point in index order. A check
// that took equal approximations for equal points, or that ordered points
// with equal sort keys by index alone, would miss the pair (or name the
// wrong one).
TEST(MeshBadInput, DuplicatePointsAmongDistinctPointsWithEqualDoubles) {
  const Rational third(1, 3);
  const Rational a = third + Rational(1, mpz_class(1) << 200);
  const Rational b = third + Rational(1, mpz_class(1) << 199);
  ASSERT_NE(a, b);
  ASSERT_EQ(a.get_d(), b.get_d());
  ASSERT_EQ(to_double_nearest(a), to_double_nearest(b));
  PolygonSoup s = test::tetrahedron();
  s.points.push_back(Vec3{a, 7, b});  // 4
  s.points.push_back(Vec3{b, 7, a});  // 5: same doubles as 4, and distinct
  s.points.push_back(Vec3{a, 7, a});  // 6: same doubles, and distinct
  s.points.push_back(Vec3{a, 7, b});  // 7: equal to 4
  s.add_face({4, 5, 6});
  s.add_face({5, 6, 7});
  expect_error(s, ErrorCategory::topology, {"vertices 4 and 7 are at the same point"});
}

// The oracle for the duplicate check: the message naming the first pair a
// quadratic scan in index order finds, or "" when the points are distinct.
std::string first_duplicate_by_scan(const PolygonSoup& s) {
  const auto n = static_cast<std::uint32_t>(s.points.size());
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < j; ++i)
      if (s.points[i] == s.points[j])
        return "vertices " + std::to_string(i) + " and " + std::to_string(j) + " are at the same point";
  return "";
}

// The duplicate check sorts on a key made of each coordinate's sizes and
// lowest limbs. Coordinates that differ only above their lowest limb
// (k 2^64 + 5) give every point one key: the check must then tell them
// apart exactly, still in O(n log n), and name the first pair a scan in
// index order finds (brute force on a prefix, then at scale).
TEST(MeshBadInput, DuplicatePointsAmongPointsWithOneKey) {
  const auto high = [](std::uint32_t k, unsigned low) { return Rational((mpz_class(k) << 64) + low); };
  const auto points = [&](std::uint32_t n) {
    PolygonSoup s;
    for (std::uint32_t i = 0; i < n; ++i)
      s.points.push_back(Vec3{high(1 + i % 97, 5), high(1 + i / 97, 3), 1});
    return s;
  };
  // 97 * 3 distinct points, then copies of points 200 and 150 (in that order).
  PolygonSoup s = points(97 * 3);
  s.points.push_back(s.points[200]);
  s.points.push_back(s.points[150]);
  const auto n = static_cast<std::uint32_t>(s.points.size());
  for (std::uint32_t i = 0; i < n; ++i) s.add_face({i, (i + 1) % n, (i + 2) % n});
  const std::string expected = first_duplicate_by_scan(s);
  ASSERT_EQ(expected, "vertices 200 and 291 are at the same point");
  expect_error(s, ErrorCategory::topology, {expected});

  PolygonSoup large = points(97 * 1000);
  large.points.push_back(large.points[777]);
  const auto m = static_cast<std::uint32_t>(large.points.size());
  for (std::uint32_t i = 0; i < m; ++i) large.add_face({i, (i + 1) % m, (i + 2) % m});
  expect_error(large, ErrorCategory::topology, {"vertices 777 and 97000 are at the same point"});
}

// Against a brute-force oracle: points drawn from a few values whose doubles
// coincide (within each group) or nearly do, in many orders; from_soup must
// name the first pair the quadratic scan finds, or no duplicate at all.
TEST(MeshBadInput, DuplicatePointsMatchABruteForceScan) {
  const Rational third(1, 3), tenth(1, 10);
  const std::vector<Rational> pool = {third,
                                      third + Rational(1, mpz_class(1) << 200),
                                      third + Rational(1, mpz_class(1) << 199),
                                      third - Rational(1, mpz_class(1) << 300),
                                      tenth,
                                      tenth + Rational(1, mpz_class(1) << 120),
                                      Rational(0),
                                      Rational(1, mpz_class(1) << 2000),
                                      -Rational(1, mpz_class(1) << 2000)};
  std::mt19937 rng(14);
  std::uniform_int_distribution<std::size_t> pick(0, pool.size() - 1);
  int with_duplicate = 0;
  for (int round = 0; round < 300; ++round) {
    PolygonSoup s;
    const std::uint32_t n = 3 + static_cast<std::uint32_t>(round % 40);
    for (std::uint32_t i = 0; i < n; ++i) s.points.push_back(Vec3{pool[pick(rng)], pool[pick(rng)], pool[pick(rng) % 3]});
    for (std::uint32_t i = 0; i < n; ++i) s.add_face({i, (i + 1) % n, (i + 2) % n});
    const std::string expected = first_duplicate_by_scan(s);
    with_duplicate += !expected.empty();
    try {
      (void)Mesh::from_soup(s);
      EXPECT_TRUE(expected.empty()) << "round " << round << ": no error, expected " << expected;
    } catch (const Error& e) {
      const std::string message = e.what();
      if (expected.empty())
        EXPECT_EQ(message.find("same point"), std::string::npos) << "round " << round << ": " << message;
      else
        EXPECT_NE(message.find(expected), std::string::npos) << "round " << round << ": " << message;
    }
  }
  EXPECT_GT(with_duplicate, 100);
  EXPECT_LT(with_duplicate, 300);
}

TEST(MeshBadInput, UnreferencedVertex) {
  PolygonSoup s = test::tetrahedron();
  s.points.push_back(v3(5, 5, 5));
  expect_error(s, ErrorCategory::topology, {"vertex 4", "unreferenced"});
}

}  // namespace
}  // namespace cvms
