// SPDX-License-Identifier: MIT
// The filtered input path of ConvexPolyhedron::from_mesh and its linear cost
// in the face degree: the predicates on
// differences of points against an exact reference written out here, and
// polygon faces (random, collinear runs, nearly coplanar, reflex, wound
// twice, tiny and 1e9-scale, rationals of different denominators) judged by
// an independent exact face oracle and, when accepted, by the brute-force
// hull. Randomised cases use fixed seeds and name them on failure.
#include <gtest/gtest.h>

#include <iostream>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/error.hpp"
#include "filtered_predicates.hpp"
#include "support/cpu_time.hpp"
#include "support/hand_solids.hpp"
#include "support/oracle.hpp"

namespace cvms {
namespace {

// ---- the exact reference: determinants written out in rationals -----------

Rational det3(const Vec3& a, const Vec3& b, const Vec3& c) {
  return a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
}

Vec3 minus(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

Sign sign_of_rational(const Rational& q) { return sign_of(sgn(q)); }

// p / q in lowest terms (gmpxx's two-argument constructor does not reduce).
Rational fraction(long p, long q) {
  Rational r(p, q);
  r.canonicalize();
  return r;
}

// Points of one configuration with their approximations.
struct Cloud {
  std::vector<Vec3> p;
  std::vector<ApproxVec3> a;
  void add(const Vec3& v) {
    p.push_back(v);
    a.push_back(ApproxVec3::of(v));
  }
  [[nodiscard]] Vec3Ref operator[](std::size_t i) const { return {p[i], a[i]}; }
};

Rational from_double(double d) { return Rational(d); }

// A deterministic small integer in [-4, 4].
long small_int(int round, int i) { return ((round * (2 * i + 3) + i) % 9) - 4; }

// Random configurations: each has 6 points; some are on purpose collinear,
// coplanar up to one ulp, tiny or large.
Cloud random_cloud(std::mt19937_64& rng, int kind) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> small(-4, 4);
  std::uniform_int_distribution<long> den(1, 1000);
  Cloud c;
  const double scale = kind % 4 == 0 ? 1.0 : kind % 4 == 1 ? 1e-300 : kind % 4 == 2 ? 1e9 : 1.0;
  auto random_point = [&] {
    if (kind % 4 == 3)  // rationals with different denominators
      return Vec3{fraction(small(rng), den(rng)), fraction(small(rng), den(rng)), fraction(small(rng), den(rng))};
    return Vec3{from_double(unit(rng) * scale), from_double(unit(rng) * scale), from_double(unit(rng) * scale)};
  };
  switch ((kind / 4) % 3) {
    case 0:  // general position
      for (int i = 0; i < 6; ++i) c.add(random_point());
      break;
    case 1: {  // a collinear run: a + t d for small rational t
      const Vec3 a = random_point(), d = random_point();
      for (int i = 0; i < 6; ++i) {
        const Rational t = fraction(small(rng), 1 + (i % 3));
        c.add({a.x + t * d.x, a.y + t * d.y, a.z + t * d.z});
      }
      break;
    }
    default: {  // coplanar a + s u + t v, then one point moved by an ulp
      const Vec3 a = random_point(), u = random_point(), v = random_point();
      for (int i = 0; i < 6; ++i) {
        const Rational s(small(rng)), t(small(rng));
        c.add({a.x + s * u.x + t * v.x, a.y + s * u.y + t * v.y, a.z + s * u.z + t * v.z});
      }
      Vec3 moved = c.p[5];
      const double z = moved.z.get_d();
      moved.z = from_double(std::nextafter(z, 2.0 * z + 1.0));
      c.p[5] = moved;
      c.a[5] = ApproxVec3::of(moved);
      break;
    }
  }
  return c;
}

TEST(FilteredDifferencePredicates, MatchTheExactReferenceOnRandomAndDegenerateInput) {
  std::mt19937_64 rng(20261201);
  const PredicateCounters before = predicate_counters();
  for (int round = 0; round < 3000; ++round) {
    const int kind = round % 12;
    SCOPED_TRACE("seed 20261201, round " + std::to_string(round) + ", kind " + std::to_string(kind));
    const Cloud c = random_cloud(rng, kind);
    const Vec3 n = minus(c.p[1], c.p[0]);  // a normal-like vector from the cloud
    const ApproxVec3 n_approx = ApproxVec3::of(n);
    const Vec3Ref nr{n, n_approx};
    EXPECT_EQ(sign_triple_of_differences(nr, c[0], c[2], c[3], c[4]),
              sign_of_rational(det3(n, minus(c.p[2], c.p[0]), minus(c.p[4], c.p[3]))));
    EXPECT_EQ(sign_triple_of_differences(nr, c[2], c[3], c[3], c[5]),
              sign_of_rational(det3(n, minus(c.p[3], c.p[2]), minus(c.p[5], c.p[3]))));
    const Vec3 d1 = minus(c.p[2], c.p[1]), d2 = minus(c.p[4], c.p[3]);
    EXPECT_EQ(sign_dot_of_differences(c[1], c[2], c[3], c[4]),
              sign_of_rational(d1.x * d2.x + d1.y * d2.y + d1.z * d2.z));
    EXPECT_EQ(sign_triple_with_difference(c[0], c[1], c[4], c[5]),
              sign_of_rational(det3(c.p[0], c.p[1], minus(c.p[5], c.p[4]))));
    const Vec3 u = minus(c.p[3], c.p[2]), v = minus(c.p[4], c.p[2]);
    const bool on_line = u.y * v.z == u.z * v.y && u.z * v.x == u.x * v.z && u.x * v.y == u.y * v.x;
    EXPECT_EQ(collinear(c[2], c[3], c[4]), on_line);
    // In a plane: points 0..4 of the coplanar configurations, n their normal.
    if ((kind / 4) % 3 == 2) {
      const Vec3 u = minus(c.p[1], c.p[0]), v = minus(c.p[2], c.p[0]);
      const Vec3 normal{u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
      if (!is_zero(normal)) {
        const ApproxVec3 normal_approx = ApproxVec3::of(normal);
        const Vec3Ref w{normal, normal_approx};
        for (std::size_t i = 0; i < 3; ++i)
          EXPECT_EQ(sign_triple_in_plane(w, c[i], c[i + 1], c[i + 1], c[i + 2]),
                    sign_of_rational(det3(normal, minus(c.p[i + 1], c.p[i]), minus(c.p[i + 2], c.p[i + 1]))));
        EXPECT_EQ(sign_triple_in_plane(w, c[0], c[3], c[4], c[1]),
                  sign_of_rational(det3(normal, minus(c.p[3], c.p[0]), minus(c.p[1], c.p[4]))));
      }
    }
    // side_of_plane with an integer normal (its exact fallback is new).
    const Vec3 m{Rational(small_int(round, 0)), Rational(small_int(round, 1)), Rational(small_int(round, 2))};
    const ApproxVec3 m_approx = ApproxVec3::of(m);
    const Rational offset = m.x * c.p[0].x + m.y * c.p[0].y + m.z * c.p[0].z;
    for (int i = 0; i < 6; ++i) {
      const Rational side = m.x * c.p[i].x + m.y * c.p[i].y + m.z * c.p[i].z - offset;
      EXPECT_EQ(side_of_plane(c[static_cast<std::size_t>(i)], {m, m_approx}, offset, Approx::of(offset)),
                sign_of_rational(side));
    }
  }
  const PredicateCounters after = predicate_counters();
  EXPECT_GT(after.exact, before.exact);        // the degenerate cases reached the exact fallback
  EXPECT_GT(after.filtered, before.filtered);  // and the rest were decided in double
}

// ---- faces: an independent exact oracle ------------------------------------

// The verdict on face 0 of a pyramid whose base is the polygon q (in the
// plane of its first three points when planar).
enum class FaceVerdict { accepted, collinear, not_planar, not_convex };

// Independent of the library's method: planar iff every point is on the
// plane of some non-collinear triple (det = 0); then a weakly convex,
// counterclockwise (about the normal w), simple polygon iff every point lies
// on or to the left of every edge's line and the area is positive, and no
// edge doubles back along the line of its neighbour.
FaceVerdict face_oracle(const std::vector<Vec3>& q, const Vec3& w) {
  const std::size_t m = q.size();
  std::size_t k = 2;
  auto cross_of = [&](std::size_t a, std::size_t b, std::size_t c) {
    const Vec3 u = minus(q[b], q[a]), v = minus(q[c], q[a]);
    return Vec3{u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
  };
  while (k < m && is_zero(cross_of(0, 1, k))) ++k;
  if (k == m) return FaceVerdict::collinear;
  for (std::size_t i = 0; i < m; ++i)
    if (sgn(det3(minus(q[1], q[0]), minus(q[k], q[0]), minus(q[i], q[0]))) != 0) return FaceVerdict::not_planar;
  Rational area = 0;
  for (std::size_t i = 1; i + 1 < m; ++i) {
    const Vec3 c = cross_of(0, i, i + 1);
    area += c.x * w.x + c.y * w.y + c.z * w.z;
  }
  if (sgn(area) == 0) return FaceVerdict::not_convex;
  // A clockwise base makes the whole pyramid consistently inward, which
  // from_mesh flips: judge the base from the other side.
  const Vec3 side = sgn(area) > 0 ? w : Vec3{-w.x, -w.y, -w.z};
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t j = (i + 1) % m;
    for (std::size_t t = 0; t < m; ++t)
      if (sgn(det3(side, minus(q[j], q[i]), minus(q[t], q[i]))) < 0) return FaceVerdict::not_convex;
    const std::size_t h = (i + m - 1) % m;
    const Vec3 a = minus(q[i], q[h]), b = minus(q[j], q[i]);
    if (sgn(det3(side, a, b)) == 0 && sgn(a.x * b.x + a.y * b.y + a.z * b.z) <= 0) return FaceVerdict::not_convex;
  }
  return FaceVerdict::accepted;
}

// The pyramid over the polygon q (face 0, counterclockwise about w) with the
// apex on the other side of its plane.
PolygonSoup pyramid(const std::vector<Vec3>& q, const Vec3& apex) {
  PolygonSoup s;
  s.points = q;
  s.points.push_back(apex);
  std::vector<std::uint32_t> base;
  for (std::uint32_t i = 0; i < q.size(); ++i) base.push_back(i);
  s.add_face(base);
  const auto m = static_cast<std::uint32_t>(q.size());
  for (std::uint32_t i = 0; i < m; ++i) s.add_face({(i + 1) % m, i, m});
  return s;
}

// A polygon in the plane through o spanned by e1, e2: 2D points (u, v)
// mapped to o + u e1 + v e2.
struct PlaneMap {
  Vec3 o, e1, e2;
  [[nodiscard]] Vec3 at(const Rational& u, const Rational& v) const {
    return {o.x + u * e1.x + v * e2.x, o.y + u * e1.y + v * e2.y, o.z + u * e1.z + v * e2.z};
  }
  [[nodiscard]] Vec3 normal() const {
    return {e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x};
  }
};

// 2D polygons: a convex one with collinear runs, then perturbed on purpose.
std::vector<Vec2> random_polygon(std::mt19937_64& rng, int kind) {
  // Corners of an octagon-ish convex polygon with midpoints (collinear runs).
  const long corners[8][2] = {{4, 0}, {3, 3}, {0, 4}, {-3, 3}, {-4, 0}, {-3, -3}, {0, -4}, {3, -3}};
  const int n = 3 + static_cast<int>(rng() % 6);
  std::vector<Vec2> p;
  for (int i = 0; i < n; ++i) {
    const long* a = corners[(i * 8) / n];
    const long* b = corners[(((i + 1) * 8) / n) % 8];
    p.push_back({Rational(a[0]), Rational(a[1])});
    if (rng() % 3 == 0) p.push_back({fraction(a[0] + b[0], 2), fraction(a[1] + b[1], 2)});  // straight on
  }
  switch (kind % 5) {
    case 1: p[rng() % p.size()].x *= fraction(1, 4); break;  // maybe a reflex corner
    case 2: std::swap(p[0], p[1]); break;                     // maybe self-intersecting
    case 3: {                                                  // a dent on a straight run
      const std::size_t i = rng() % p.size();
      p[i].x *= fraction(99, 100);
      break;
    }
    default: break;
  }
  return p;
}

void check_pyramid(const std::vector<Vec3>& q, const Vec3& w, const Vec3& apex, const std::string& trace) {
  std::string pts;
  for (const Vec3& v : q) {
    pts += '(';
    pts += v.x.get_str() + " " + v.y.get_str() + " " + v.z.get_str();
    pts += ") ";
  }
  SCOPED_TRACE(trace + ": " + pts);
  const PolygonSoup s = pyramid(q, apex);
  const FaceVerdict want = face_oracle(q, w);
  try {
    const ConvexPolyhedron p = ConvexPolyhedron::from_soup(s);
    EXPECT_EQ(want, FaceVerdict::accepted);
    EXPECT_EQ(test::check_invariants(p), "");
    const test::Shape hull = test::brute_force_hull(s.points);
    const test::Shape got = test::describe(p);
    EXPECT_TRUE(hull == got) << test::difference(hull, got);
  } catch (const Error& e) {
    const std::string what = e.what();
    switch (want) {
      case FaceVerdict::accepted: ADD_FAILURE() << "oracle accepts the base, from_soup says: " << what; break;
      case FaceVerdict::collinear:
        EXPECT_EQ(e.category(), ErrorCategory::degenerate) << what;
        EXPECT_NE(what.find("face 0 has zero area"), std::string::npos) << what;
        break;
      case FaceVerdict::not_planar:
        EXPECT_EQ(e.category(), ErrorCategory::not_convex) << what;
        EXPECT_NE(what.find("face 0 is not planar"), std::string::npos) << what;
        break;
      case FaceVerdict::not_convex:
        EXPECT_EQ(e.category(), ErrorCategory::not_convex) << what;
        EXPECT_NE(what.find("face 0"), std::string::npos) << what;
        break;
    }
  }
}

TEST(FaceValidation, PolygonFacesAgreeWithAnExactOracle) {
  const std::uint64_t seed = 1412;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> coefficient(-3, 3);
  int verdicts[4] = {0, 0, 0, 0};
  for (int round = 0; round < 400; ++round) {
    const int kind = round % 5;
    std::vector<Vec2> poly = random_polygon(rng, kind);
    // Planes: axis-aligned, tilted with integer or rational spans, at scales
    // 1, 1e9 and 2^-900 (tiny doubles), some with a vertex one ulp off.
    const int plane_kind = (round / 5) % 4;
    const Rational scale = plane_kind == 1 ? Rational(1000000000) : plane_kind == 2 ? Rational(std::ldexp(1.0, -900)) : Rational(1);
    PlaneMap map{{Rational(coefficient(rng)) * scale, Rational(coefficient(rng)) * scale, Rational(coefficient(rng)) * scale},
                 {scale, 0, fraction(coefficient(rng), 7) * scale},
                 {0, scale, fraction(coefficient(rng), 5) * scale}};
    if (plane_kind == 3) map.e1 = {fraction(3, 7), fraction(1, 11), fraction(2, 13)};  // different denominators
    std::vector<Vec3> q;
    for (const Vec2& v : poly) q.push_back(map.at(v.x, v.y));
    if (kind == 4 && q.size() > 3) {  // nearly coplanar: one vertex off by an ulp in z
      Vec3& last = q[q.size() / 2];
      const double z = last.z.get_d();
      last.z = Rational(std::nextafter(z, z >= 0 ? 1e300 : -1e300));
    }
    const Vec3 w = map.normal();
    const Rational h = 3;
    const Vec3 apex = map.at(fraction(1, 3), fraction(1, 5));
    const Vec3 below{apex.x - h * w.x, apex.y - h * w.y, apex.z - h * w.z};
    const std::string trace = "seed " + std::to_string(seed) + ", round " + std::to_string(round);
    check_pyramid(q, w, below, trace);
    ++verdicts[static_cast<int>(face_oracle(q, w))];
  }
  EXPECT_GT(verdicts[static_cast<int>(FaceVerdict::accepted)], 80);
  EXPECT_GT(verdicts[static_cast<int>(FaceVerdict::not_planar)], 20);
  EXPECT_GT(verdicts[static_cast<int>(FaceVerdict::not_convex)], 20);
}

// Points (1 - t^2, 2t) / (1 + t^2) on the unit circle for t = p / q: every
// vertex has its own denominator.
std::vector<Vec2> rational_circle(int n) {
  std::vector<Vec2> points;
  const mpz_class q = 4 * n;
  for (int i = 0; i < n; ++i) {
    const double phi = -M_PI / 2 + M_PI * (i + 0.5) / n;
    const mpz_class p = static_cast<long>(std::llround(std::tan(phi) * 4 * n));
    const Rational den(q * q + p * p);
    points.push_back({Rational(q * q - p * p) / den, Rational(2 * p * q) / den});
  }
  return points;
}

// A face of degree d whose vertices have different denominators must cost
// O(d) to check, not O(d^2) (an exact area vector that grows with the face
// and is re-approximated per vertex would take seconds on a 40,000-gon prism).
// CPU seconds of ConvexPolyhedron::from_soup on the prism over the n-gon
// of rational_circle(n); its counts checked.
double seconds_to_validate_prism(int n) {
  const PolygonSoup soup = cvms::test::prism_over(rational_circle(n), -1, 1);
  const auto start = test::cpu_seconds();
  const ConvexPolyhedron p = ConvexPolyhedron::from_soup(soup);
  const double seconds = test::cpu_seconds() - start;
  EXPECT_EQ(p.num_facets(), static_cast<std::uint32_t>(n) + 2u);
  EXPECT_EQ(p.num_vertices(), 2u * static_cast<std::uint32_t>(n));
  EXPECT_EQ(p.normal(FaceId(1)), (Vec3{0, 0, 1}));
  EXPECT_EQ(p.plane_offset(FaceId(1)), 1);
  return seconds;
}

TEST(FaceValidation, BigPrismWithDifferentDenominatorsIsLinear) {
  // Four times the corners take about four times as long where quadratic
  // would take sixteen: a ratio of two runs, so that the machine's speed and
  // a sanitizer's slowdown cancel (an absolute limit would fail under ASan
  // on a slow host), with a little slack for the small run's noise.
  const double small = seconds_to_validate_prism(10000);
  const double big = seconds_to_validate_prism(40000);
  EXPECT_LT(big, 8.0 * small + 0.05) << "10,000-gon " << small << " s, 40,000-gon " << big << " s";
  std::cout << "from_soup of the 10,000- and 40,000-gon prisms: " << small << " s, " << big << " s\n";
}

TEST(FaceValidation, BigNonConvexFaceIsReportedQuickly) {
  // The fault path computes the exact area vector in a balanced sum, so a
  // failing big face is named as before without quadratic cost.
  std::vector<Vec2> circle = rational_circle(20000);
  std::swap(circle[100], circle[101]);  // a reflex corner (a bow tie of two neighbours)
  const PolygonSoup soup = cvms::test::prism_over(circle, -1, 1);
  const auto start = test::cpu_seconds();
  try {
    (void)ConvexPolyhedron::from_soup(soup);
    ADD_FAILURE() << "accepted a non-convex face";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::not_convex) << e.what();
    EXPECT_NE(std::string(e.what()).find("face 0 is not a convex polygon"), std::string::npos) << e.what();
  }
  const double seconds = test::cpu_seconds() - start;
  EXPECT_LT(seconds, 5.0);
}

}  // namespace
}  // namespace cvms
