// SPDX-License-Identifier: MIT
// Tests of the integer path of from_halfspaces
// (lib/halfspaces/integer_dual_hull.hpp, homogeneous_dual.hpp,
// intersection_polyhedron.hpp): the vertices against the brute-force
// enumeration over row triples (support/halfspace_oracle.hpp), the tight
// rows by substitution, and the polyhedron against convex_hull of the
// vertices: the same vertices, oriented facets and exact planes (the
// numbering differs: the polyhedron is read off the dual hull). On random rational
// systems around a rational interior point, with duplicated and scaled
// rows; on the facet planes of a geodesic sphere (many rows through each
// vertex: every dual facet is degenerate); the unbounded cases must give
// nothing.
#include "integer_dual_hull.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/halfspaces.hpp"
#include "cvms/shapes.hpp"
#include "filtered_predicates.hpp"
#include "homogeneous_hull.hpp"
#include "hull_soup.hpp"
#include "intersection_polyhedron.hpp"
#include "support/halfspace_oracle.hpp"

namespace cvms {
namespace {

using Rng = std::mt19937_64;

detail::LpRow lp_row(const HalfspaceRow& r) { return {{r.normal.x, r.normal.y, r.normal.z}, r.offset}; }

std::vector<detail::LpRow> lp_rows(const std::vector<HalfspaceRow>& rows) {
  std::vector<detail::LpRow> out;
  for (const HalfspaceRow& r : rows) out.push_back(lp_row(r));
  return out;
}

std::vector<Rational> chart_point(const Vec3& x) { return {x.x, x.y, x.z}; }

Rational fraction(long n, long d) {
  Rational q(n, d);
  q.canonicalize();
  return q;
}

// Rows through no common point around x0, some scaled by a rational factor
// and some repeated.
std::vector<HalfspaceRow> random_rows(Rng& rng, const Vec3& x0, int count) {
  std::vector<HalfspaceRow> rows;
  auto coordinate = [&] { return Rational(static_cast<long>(rng() % 13) - 6); };
  while (static_cast<int>(rows.size()) < count) {
    Vec3 a{coordinate(), coordinate(), coordinate()};
    if (is_zero(a)) continue;
    Rational b = dot(a, x0) + fraction(1 + static_cast<long>(rng() % 20), 1 + static_cast<long>(rng() % 6));
    if (rng() % 4 == 0) {
      const Rational f = fraction(1 + static_cast<long>(rng() % 9), 1 + static_cast<long>(rng() % 9));
      a = f * a;
      b *= f;
    }
    rows.push_back({a, b});
    if (rng() % 8 == 0) rows.push_back(rows.back());
  }
  return rows;
}

// Independent of the dual: the set is bounded iff no vertex of its
// intersection with the box [−B, B]^3 lies on the box, for B beyond every
// vertex the small rows of random_rows can have (coordinates below 10^4).
bool bounded_by_box(std::vector<HalfspaceRow> rows) {
  const Rational big(1000000);
  for (int k = 0; k < 3; ++k) {
    Vec3 e{0, 0, 0};
    e[k] = 1;
    rows.push_back({e, big});
    rows.push_back({-e, big});
  }
  for (const Vec3& v : test::brute_force_vertices(rows))
    for (int k = 0; k < 3; ++k)
      if (abs(v[k]) == big) return false;
  return true;
}

// Each vertex's tight rows hold with equality there, and each vertex has at
// least three.
void expect_tight_rows_hold(const detail::DualVertices& v, const std::vector<HalfspaceRow>& rows) {
  ASSERT_EQ(v.tight_offsets.size(), v.vertices.size() + 1);
  for (std::size_t k = 0; k < v.vertices.size(); ++k) {
    EXPECT_GE(v.tight_offsets[k + 1] - v.tight_offsets[k], 3u);
    for (std::uint32_t i = v.tight_offsets[k]; i < v.tight_offsets[k + 1]; ++i)
      EXPECT_EQ(dot(rows[v.tight[i]].normal, v.vertices[k]), rows[v.tight[i]].offset);
  }
}

// The same polyhedron up to the numbering of vertices and facets: the same
// vertex set, and the same facets as oriented cycles of positions (each
// rotated to start at its smallest position) with the same exact planes.
struct FacetKey {
  std::vector<Vec3> cycle;
  Vec3 normal;
  Rational offset;
  friend bool operator<(const FacetKey& a, const FacetKey& b) {
    return std::tie(a.cycle, a.normal, a.offset) < std::tie(b.cycle, b.normal, b.offset);
  }
  friend bool operator==(const FacetKey& a, const FacetKey& b) {
    return std::tie(a.cycle, a.normal, a.offset) == std::tie(b.cycle, b.normal, b.offset);
  }
};

std::vector<FacetKey> facet_keys(const ConvexPolyhedron& p) {
  const PolygonSoup soup = p.mesh().to_soup();
  std::vector<FacetKey> keys;
  for (FaceId f : p.mesh().faces()) {
    FacetKey key{{}, p.normal(f), p.plane_offset(f)};
    for (std::uint32_t i : soup.face(f.index())) key.cycle.push_back(soup.points[i]);
    std::rotate(key.cycle.begin(), std::min_element(key.cycle.begin(), key.cycle.end()), key.cycle.end());
    keys.push_back(std::move(key));
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

void expect_same_polyhedron(const ConvexPolyhedron& p, const ConvexPolyhedron& q) {
  ASSERT_EQ(p.num_vertices(), q.num_vertices());
  ASSERT_EQ(p.num_facets(), q.num_facets());
  std::vector<Vec3> pv = p.mesh().positions(), qv = q.mesh().positions();
  std::sort(pv.begin(), pv.end());
  std::sort(qv.begin(), qv.end());
  EXPECT_EQ(pv, qv);
  EXPECT_TRUE(facet_keys(p) == facet_keys(q));
}

std::vector<Vec3> sorted(std::vector<Vec3> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(IntegerDualHull, RandomSystemsMatchTheTripleEnumeration) {
  Rng rng(1602);
  int bounded = 0;
  for (int round = 0; round < 150; ++round) {
    SCOPED_TRACE("seed 1602 round " + std::to_string(round));
    const Vec3 x0{fraction(static_cast<long>(rng() % 11) - 5, 3), fraction(-2, 7), fraction(5, 11)};
    const std::vector<HalfspaceRow> rows = random_rows(rng, x0, 6 + round % 18);
    std::optional<detail::DualVertices> v = detail::bounded_vertices(lp_rows(rows), chart_point(x0));
    ASSERT_EQ(v.has_value(), bounded_by_box(rows));
    if (!v) continue;
    ++bounded;
    EXPECT_EQ(sorted(v->vertices), test::brute_force_vertices(rows));
    expect_tight_rows_hold(*v, rows);
    const ConvexPolyhedron hull = convex_hull(v->vertices);
    expect_same_polyhedron(detail::intersection_polyhedron(std::move(*v)), hull);
  }
  EXPECT_GE(bounded, 100);
}

TEST(IntegerDualHull, SphereFacetPlanesThroughEveryVertex) {
  const ConvexPolyhedron s = shapes::geodesic_sphere(2);
  const HalfspaceSystem h = to_halfspaces(ConvexSet(s));
  std::optional<detail::DualVertices> v =
      detail::bounded_vertices(lp_rows(h.inequalities), chart_point(Vec3{0, 0, 0}));
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(sorted(v->vertices), sorted(s.mesh().positions()));
  expect_tight_rows_hold(*v, h.inequalities);
  const ConvexPolyhedron hull = convex_hull(v->vertices);
  expect_same_polyhedron(detail::intersection_polyhedron(std::move(*v)), hull);
}

// Whole-pipeline check of a system: the vertices against the triple
// enumeration, the polyhedron against convex_hull of them (as sets).
void expect_matches_oracles(const std::vector<HalfspaceRow>& rows, const Vec3& x0) {
  std::optional<detail::DualVertices> v = detail::bounded_vertices(lp_rows(rows), chart_point(x0));
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(sorted(v->vertices), test::brute_force_vertices(rows));
  expect_tight_rows_hold(*v, rows);
  const ConvexPolyhedron hull = convex_hull(v->vertices);
  expect_same_polyhedron(detail::intersection_polyhedron(std::move(*v)), hull);
  expect_same_polyhedron(from_halfspaces(rows).polyhedron(), hull);
}

// The integer hull decides as the quickhull on the rational points a/s
// (homogeneous_hull.hpp): the same soup, face by face, and the same source
// points. On a geodesic sphere's facet planes the dual points are coplanar
// in fives and sixes, so the farthest-point choice meets exact ties that its
// integer comparison must break as compare_dot does.
// Returns the number of exact evaluations the integer hull made.
std::uint64_t expect_same_soup_as_rational_hull(const std::vector<HalfspaceRow>& rows, const Vec3& x0) {
  const detail::HomogeneousDual dual = detail::homogeneous_dual(lp_rows(rows), chart_point(x0));
  std::vector<Vec3> q;
  for (const HomogeneousPoint& p : dual.points) q.push_back(detail::standing_for(p));
  std::vector<std::uint32_t> source, homogeneous_source;
  const PolygonSoup expected = hull_soup(q, &source);
  const std::uint64_t exact_before = predicate_counters().exact;
  detail::FacePoles face_poles;
  const PolygonSoup got = detail::homogeneous_hull(
      dual.points, [&](std::uint32_t i) { return q[i]; }, homogeneous_source, &face_poles);
  const std::vector<HomogeneousPoint>& poles = face_poles.poles;
  const std::uint64_t exact = predicate_counters().exact - exact_before;
  // Each face's pole y: a·y_xyz == s y_w at every corner (a, s), y_w > 0
  // for a bounded system (the origin strictly below every dual facet).
  EXPECT_EQ(poles.size(), got.num_faces());
  for (std::size_t f = 0; f < got.num_faces() && f < poles.size(); ++f) {
    const HomogeneousPoint& y = poles[f];
    EXPECT_GT(sgn(y.w), 0) << "face " << f;
    for (std::uint32_t c : got.face(f)) {
      const HomogeneousPoint& a = dual.points[homogeneous_source[c]];
      EXPECT_EQ(a.x * y.x + a.y * y.y + a.z * y.z, a.w * y.w) << "face " << f << " corner " << c;
    }
  }
  EXPECT_EQ(got.face_offsets, expected.face_offsets);
  EXPECT_EQ(got.face_indices, expected.face_indices);
  EXPECT_EQ(homogeneous_source, source);
  return exact;
}

TEST(IntegerDualHull, DecidesAsTheRationalHull) {
  for (int k = 1; k <= 3; ++k) {
    SCOPED_TRACE("sphere " + std::to_string(k));
    const HalfspaceSystem h = to_halfspaces(ConvexSet(shapes::geodesic_sphere(k)));
    // The coplanar dual points leave many decisions to the exact stages
    // (43 on the icosahedron's 20 rows, with the triangles of one plane
    // sharing its exact tests).
    EXPECT_GT(expect_same_soup_as_rational_hull(h.inequalities, Vec3{0, 0, 0}), 30u);
    EXPECT_GT(expect_same_soup_as_rational_hull(h.inequalities,
                                                Vec3{fraction(1, 7), fraction(-1, 9), fraction(1, 11)}),
              30u);
  }
  Rng rng(1607);
  for (int round = 0; round < 40; ++round) {
    SCOPED_TRACE("seed 1607 round " + std::to_string(round));
    const Vec3 x0{fraction(1, 3), fraction(-2, 7), fraction(5, 11)};
    const std::vector<HalfspaceRow> rows = random_rows(rng, x0, 12 + round);
    if (!bounded_by_box(rows)) continue;
    expect_same_soup_as_rational_hull(rows, x0);
  }
}

TEST(IntegerDualHull, ManyRowsThroughOneApex) {
  // A pyramid over a convex 12-gon: 12 rows x_i x + y_i y + z <= 1 all tight
  // at the apex (0, 0, 1) (one dual facet of 12 coplanar points), the
  // points (x_i, y_i) on the circle x^2 + y^2 = 25 (in convex position),
  // and a floor z >= −1; every row repeated once, one scaled by 3.
  const long pts[12][2] = {{5, 0},  {4, 3},   {3, 4},   {0, 5},  {-3, 4}, {-4, 3},
                           {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  std::vector<HalfspaceRow> rows;
  for (int i = 0; i < 12; ++i) {
    rows.push_back({Vec3{Rational(pts[i][0]), Rational(pts[i][1]), Rational(1)}, Rational(1)});
    rows.push_back(rows.back());
  }
  rows[3] = {Rational(3) * rows[3].normal, Rational(3) * rows[3].offset};
  rows.push_back({Vec3{0, 0, -1}, Rational(1)});
  expect_matches_oracles(rows, Vec3{0, 0, 0});
}

TEST(IntegerDualHull, RowsBeyondTheFixedWidthTakeMpz) {
  // Rows with normals of about 300 bits (a perturbation over 2^300 + k),
  // so the dual points exceed the fixed-width determinant's 255 bits.
  Rng rng(1604);
  int bounded = 0;
  for (int round = 0; round < 20; ++round) {
    SCOPED_TRACE("seed 1604 round " + std::to_string(round));
    const Vec3 x0{fraction(1, 3), fraction(-2, 7), fraction(5, 11)};
    std::vector<HalfspaceRow> rows = random_rows(rng, x0, 8 + round % 8);
    mpz_class big = 1;
    big <<= 300;
    for (HalfspaceRow& r : rows) {
      Rational tiny(mpz_class(1 + static_cast<long>(rng() % 5)), big + static_cast<long>(rng() % 1000));
      tiny.canonicalize();
      r.normal.x += tiny;
      r.offset = dot(r.normal, x0) + 1 + static_cast<long>(rng() % 9);
    }
    if (!bounded_by_box(rows)) continue;
    ++bounded;
    expect_matches_oracles(rows, x0);
    // The poles from Cramer's rule in mpz satisfy their facets' rows.
    expect_same_soup_as_rational_hull(rows, x0);
  }
  EXPECT_GE(bounded, 10);
}

// A row whose normal has a content of more than one limb: (c, 2c, 3c)·x <= 1
// cuts a box near the origin, and its facet's offset is 1 / c, a fraction
// whose denominator the polyhedron's arena holds as well. c = 2^70 + 1 takes
// the exact division, c = 2^70 the shift by 70 bits (more than a limb).
TEST(IntegerDualHull, RowsWithALongContentKeepTheirOffsetsExact) {
  for (const mpz_class& c : {mpz_class((mpz_class(1) << 70) + 1), mpz_class(mpz_class(1) << 70)}) {
    SCOPED_TRACE("c = " + c.get_str());
    std::vector<HalfspaceRow> rows;
    for (int axis = 0; axis < 3; ++axis)
      for (const long sign : {1L, -1L}) {
        Vec3 n{0, 0, 0};
        n[axis] = sign;
        rows.push_back({n, Rational(1)});
      }
    rows.push_back({Vec3{Rational(c), Rational(2 * c), Rational(3 * c)}, Rational(1)});
    expect_matches_oracles(rows, Vec3{0, 0, 0});
    expect_matches_oracles(rows, Vec3{fraction(-1, 2), fraction(-1, 3), fraction(-1, 5)});
    const ConvexPolyhedron p = from_halfspaces(rows).polyhedron();
    bool cut = false;
    for (FaceId f : p.mesh().faces()) {
      if (p.normal(f) != Vec3{1, 2, 3}) continue;
      cut = true;
      EXPECT_EQ(p.plane_offset(f), Rational(mpz_class(1), c));
    }
    EXPECT_TRUE(cut);
  }
}

TEST(IntegerDualHull, UnboundedSystemsGiveNothing) {
  const Vec3 o{0, 0, 0};
  auto row = [](long x, long y, long z, long b) { return HalfspaceRow{Vec3{x, y, z}, Rational(b)}; };
  // Open towards −z: every normal has a_z >= 0.
  const std::vector<HalfspaceRow> cone = {row(1, 0, 1, 1), row(-1, 0, 1, 1), row(0, 1, 1, 1),
                                          row(0, -1, 1, 1)};
  EXPECT_FALSE(detail::bounded_vertices(lp_rows(cone), chart_point(o)));
  // A prism along z: the dual points span only a plane.
  const std::vector<HalfspaceRow> prism = {row(1, 0, 0, 1), row(-1, 0, 0, 1), row(0, 1, 0, 1),
                                           row(0, -1, 0, 1), row(1, 1, 0, 3)};
  EXPECT_FALSE(detail::bounded_vertices(lp_rows(prism), chart_point(o)));
  // Too few rows to bound anything, and a slab: the origin on a dual facet.
  EXPECT_FALSE(
      detail::bounded_vertices(lp_rows({row(1, 0, 0, 1), row(0, 1, 0, 1), row(0, 0, 1, 1)}), chart_point(o)));
  const std::vector<HalfspaceRow> half_box = {row(1, 0, 0, 1), row(0, 1, 0, 1), row(0, -1, 0, 1),
                                              row(0, 0, 1, 1), row(0, 0, -1, 1)};
  EXPECT_FALSE(detail::bounded_vertices(lp_rows(half_box), chart_point(o)));
}

}  // namespace
}  // namespace cvms
