// SPDX-License-Identifier: MIT
// The filtered predicates against direct exact rational evaluation written
// here (cofactor/Sarrus forms, independent of lib/predicates/predicates_exact.cpp), on
// random inputs of every kind and on inputs built to defeat the filter whose
// exact answer is known by construction. The counters show that the filter
// answers the easy cases and that the exact fallback really runs on the
// degenerate ones.
#include "filtered_predicates.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "support/random_numbers.hpp"

namespace cvms {
namespace {

using test::fraction;
using test::power_of_ten;
using test::power_of_two;
using test::Rng;

// ---------- oracles: plain rational arithmetic, written out ----------

Sign oracle_det3(const Vec3& r1, const Vec3& r2, const Vec3& r3) {
  // Rule of Sarrus on the rows r1, r2, r3.
  Rational det = r1.x * r2.y * r3.z + r1.y * r2.z * r3.x + r1.z * r2.x * r3.y - r1.z * r2.y * r3.x -
                 r1.y * r2.x * r3.z - r1.x * r2.z * r3.y;
  return sign_of(sgn(det));
}
Sign oracle_orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return oracle_det3(b - a, c - a, d - a);
}
Sign oracle_orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  Rational det = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  return sign_of(sgn(det));
}
Sign oracle_cross2(const Vec2& u, const Vec2& v) { return sign_of(sgn(u.x * v.y - u.y * v.x)); }
Sign oracle_dot2(const Vec2& u, const Vec2& v) { return sign_of(sgn(u.x * v.x + u.y * v.y)); }
Sign oracle_dot(const Vec3& u, const Vec3& v) { return sign_of(sgn(u.x * v.x + u.y * v.y + u.z * v.z)); }
Sign oracle_compare_dot(const Vec3& v, const Vec3& w, const Vec3& n) {
  Rational dv = v.x * n.x + v.y * n.y + v.z * n.z;
  Rational dw = w.x * n.x + w.y * n.y + w.z * n.z;
  return sign_of(cmp(dv, dw));
}
Sign oracle_side(const Vec3& p, const Vec3& n, const Rational& offset) {
  return sign_of(cmp(p.x * n.x + p.y * n.y + p.z * n.z, offset));
}
bool oracle_parallel(const Vec3& u, const Vec3& v) {
  // Rank <= 1: every 2x2 minor of the 2x3 matrix [u; v] vanishes.
  return u.x * v.y == u.y * v.x && u.x * v.z == u.z * v.x && u.y * v.z == u.z * v.y;
}

// ---------- inputs ----------

enum class Kind { small_integer, decimal, unit_double, mixed_double, fraction, large_offset, any_rational };
const Kind all_kinds[] = {Kind::small_integer, Kind::decimal,      Kind::unit_double, Kind::mixed_double,
                          Kind::fraction,      Kind::large_offset, Kind::any_rational};

std::string random_decimal_text(Rng& rng) {
  std::string s = (rng() & 1) ? "-" : "";
  s += std::to_string(rng() % 1000) + "." + std::to_string(100000 + rng() % 900000);
  return s;
}

Rational coordinate(Rng& rng, Kind kind) {
  switch (kind) {
    case Kind::small_integer:
      return Rational(static_cast<long>(rng() % 7) - 3);
    case Kind::decimal:
      return parse_rational(random_decimal_text(rng));  // "0.1" is 1/10
    case Kind::unit_double:
      return Rational(test::random_uniform(rng, -1, 1));
    case Kind::mixed_double:
      return Rational(test::random_magnitude(rng, -40, 40));
    case Kind::fraction:
      return fraction(static_cast<long>(rng() % 201) - 100, static_cast<long>(rng() % 30) + 1);
    case Kind::large_offset:
      return Rational(1000000000) + Rational(test::random_uniform(rng, -1, 1));
    case Kind::any_rational:
      return test::random_rational(rng);
  }
  return 0;
}
Vec3 point3(Rng& rng, Kind kind) {
  return {coordinate(rng, kind), coordinate(rng, kind), coordinate(rng, kind)};
}

// A cached approximation whose bound is deliberately loose (still valid), so
// that the Approx (non-exact-leaf) code path also runs on double inputs.
Approx loosen(Approx a) { return {a.value, a.error * 4 + std::fabs(a.value) * 0x1p-60}; }
ApproxVec3 loose3(const Vec3& v) {
  ApproxVec3 a = ApproxVec3::of(v);
  return {loosen(a.x), loosen(a.y), loosen(a.z)};
}
ApproxVec2 loose2(const Vec2& v) {
  ApproxVec2 a = ApproxVec2::of(v);
  return {loosen(a.x), loosen(a.y)};
}

// Counter changes since construction.
struct CountersSince {
  PredicateCounters start = predicate_counters();
  [[nodiscard]] std::uint64_t filtered() const { return predicate_counters().filtered - start.filtered; }
  [[nodiscard]] std::uint64_t exact() const { return predicate_counters().exact - start.exact; }
};

// Evaluates the 3D predicates in all three forms (plain, cached, loose
// cached) and returns "" if they all match the oracle.
std::string check_3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  ApproxVec3 pa = ApproxVec3::of(a), pb = ApproxVec3::of(b), pc = ApproxVec3::of(c), pd = ApproxVec3::of(d);
  ApproxVec3 la = loose3(a), lb = loose3(b), lc = loose3(c), ld = loose3(d);
  Vec3Ref ra{a, pa}, rb{b, pb}, rc{c, pc}, rd{d, pd};
  Vec3Ref xa{a, la}, xb{b, lb}, xc{c, lc}, xd{d, ld};
  std::string out;
  auto expect = [&](const char* name, Sign expected, Sign plain, Sign cached, Sign loose) {
    if (plain != expected || cached != expected || loose != expected)
      out += std::string(name) + " expected " + std::to_string(static_cast<int>(expected)) + " got " +
             std::to_string(static_cast<int>(plain)) + "/" + std::to_string(static_cast<int>(cached)) + "/" +
             std::to_string(static_cast<int>(loose)) + "; ";
  };
  expect("orient3d", oracle_orient3d(a, b, c, d), orient3d(a, b, c, d), orient3d(ra, rb, rc, rd),
         orient3d(xa, xb, xc, xd));
  expect("sign_dot", oracle_dot(a, b), sign_dot(a, b), sign_dot(ra, rb), sign_dot(xa, xb));
  expect("compare_dot", oracle_compare_dot(a, b, c), compare_dot(a, b, c), compare_dot(ra, rb, rc),
         compare_dot(xa, xb, xc));
  expect("sign_triple", oracle_det3(a, b, c), sign_triple(a, b, c), sign_triple(ra, rb, rc),
         sign_triple(xa, xb, xc));
  Rational offset = d.x;
  expect("side_of_plane", oracle_side(a, b, offset), side_of_plane(a, b, offset),
         side_of_plane(ra, rb, offset, Approx::of(offset)),
         side_of_plane(xa, xb, offset, loosen(Approx::of(offset))));
  bool parallel = oracle_parallel(a, b);
  if (is_parallel(a, b) != parallel || is_parallel(ra, rb) != parallel || is_parallel(xa, xb) != parallel)
    out += "is_parallel wrong; ";
  return out;
}

std::string check_2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  ApproxVec2 pa = ApproxVec2::of(a), pb = ApproxVec2::of(b), pc = ApproxVec2::of(c);
  ApproxVec2 la = loose2(a), lb = loose2(b), lc = loose2(c);
  Vec2Ref ra{a, pa}, rb{b, pb}, rc{c, pc};
  Vec2Ref xa{a, la}, xb{b, lb}, xc{c, lc};
  std::string out;
  Sign o = oracle_orient2d(a, b, c);
  if (orient2d(a, b, c) != o || orient2d(ra, rb, rc) != o || orient2d(xa, xb, xc) != o) out += "orient2d; ";
  Sign x = oracle_cross2(a, b);
  if (sign_cross2(a, b) != x || sign_cross2(ra, rb) != x || sign_cross2(xa, xb) != x) out += "sign_cross2; ";
  Sign d = oracle_dot2(a, b);
  if (sign_dot(a, b) != d || sign_dot(ra, rb) != d || sign_dot(xa, xb) != d) out += "sign_dot2; ";
  return out;
}

// ---------- random inputs ----------

TEST(Predicates, HandCheckedConventions) {
  Vec3 o{0, 0, 0}, ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
  EXPECT_EQ(orient3d(o, ex, ey, ez), Sign::positive);  // d on the side cross(b-a, c-a) points to
  EXPECT_EQ(orient3d(o, ey, ex, ez), Sign::negative);
  EXPECT_EQ(orient3d(o, ex, ey, Vec3{5, 7, 0}), Sign::zero);
  EXPECT_EQ(orient2d(Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}), Sign::positive);  // left turn
  EXPECT_EQ(sign_cross2(Vec2{1, 0}, Vec2{0, 1}), Sign::positive);           // ccw
  EXPECT_EQ(compare_dot(Vec3{2, 0, 0}, Vec3{1, 5, 5}, ex), Sign::positive);
  EXPECT_EQ(side_of_plane(Vec3{0, 0, 2}, ez, Rational(1)), Sign::positive);
  EXPECT_EQ(side_of_plane(Vec3{0, 0, 1}, ez, Rational(1)), Sign::zero);
  EXPECT_EQ(sign_triple(ex, ey, ez), Sign::positive);
  EXPECT_EQ(sign_dot(ex, ey), Sign::zero);
  EXPECT_TRUE(is_parallel(ex, Vec3{-3, 0, 0}));
  EXPECT_TRUE(is_parallel(ex, o));
  EXPECT_FALSE(is_parallel(ex, ey));
}

TEST(Predicates, RandomInputsMatchExactEvaluation) {
  for (Kind kind : all_kinds) {
    for (unsigned seed = 1; seed <= 2; ++seed) {
      SCOPED_TRACE("seed " + std::to_string(seed) + " kind " + std::to_string(static_cast<int>(kind)));
      Rng rng(seed * 100 + static_cast<unsigned>(kind));
      for (int i = 0; i < 600; ++i) {
        Vec3 a = point3(rng, kind), b = point3(rng, kind), c = point3(rng, kind), d = point3(rng, kind);
        ASSERT_EQ(check_3d(a, b, c, d), "") << "case " << i;
        ASSERT_EQ(check_2d(Vec2{a.x, a.y}, Vec2{b.x, b.y}, Vec2{c.x, c.y}), "") << "case " << i;
      }
    }
  }
}

TEST(Predicates, FilterAnswersEasyCases) {
  // Random doubles (exact leaves) and random decimals (inexact leaves): the
  // filter must answer practically everything.
  for (Kind kind : {Kind::unit_double, Kind::decimal, Kind::mixed_double}) {
    SCOPED_TRACE("kind " + std::to_string(static_cast<int>(kind)));
    Rng rng(42);
    std::vector<Vec3> pts;
    for (int i = 0; i < 400; ++i) pts.push_back(point3(rng, kind));
    std::vector<ApproxVec3> approx;
    for (const Vec3& p : pts) approx.push_back(ApproxVec3::of(p));
    auto ref = [&](std::size_t i) { return Vec3Ref{pts[i % pts.size()], approx[i % pts.size()]}; };
    CountersSince counters;
    int calls = 0;
    for (std::size_t i = 0; i < 4000; ++i) {
      (void)orient3d(ref(i), ref(i + 1), ref(i + 2), ref(i + 3));
      (void)compare_dot(ref(i), ref(i + 1), ref(i + 2));
      (void)sign_dot(ref(i), ref(i + 1));
      (void)sign_triple(ref(i), ref(i + 1), ref(i + 2));
      (void)is_parallel(ref(i), ref(i + 1));
      (void)side_of_plane(pts[i % pts.size()], pts[(i + 1) % pts.size()], Rational(1, 3));
      (void)orient2d(Vec2{pts[i % 400].x, pts[i % 400].y}, Vec2{pts[(i + 1) % 400].x, pts[(i + 1) % 400].y},
                     Vec2{pts[(i + 2) % 400].z, pts[(i + 3) % 400].x});
      calls += 7;
    }
    EXPECT_EQ(counters.filtered() + counters.exact(), static_cast<std::uint64_t>(calls));
    EXPECT_GT(static_cast<double>(counters.filtered()), 0.99 * calls)
        << "filtered " << counters.filtered() << " exact " << counters.exact();
  }
}

// ---------- inputs built to defeat the filter ----------

// The exact answers of these constructions are known: zero for the exact
// constructions, the sign of epsilon for the perturbed ones.
TEST(Predicates, ExactlyDegenerateNonDoubleInputsFallBack) {
  Rng rng(5);
  const Rational eps = power_of_ten(-40);
  int zero_calls = 0;
  CountersSince counters;
  std::uint64_t perturbed_exact = 0;
  for (int i = 0; i < 300; ++i) {
    Kind kind = i % 2 ? Kind::fraction : Kind::decimal;
    Vec3 a = point3(rng, kind), b = point3(rng, kind), c = point3(rng, kind);
    Rational s = fraction(static_cast<long>(rng() % 19) - 9, 3),
             t = fraction(static_cast<long>(rng() % 19) - 9, 7);
    Vec3 n = cross(b - a, c - a);
    if (is_zero(n)) continue;
    // orient3d: d in the plane of a, b, c (an exact affine combination).
    Vec3 d = a + s * (b - a) + t * (c - a);
    ASSERT_EQ(orient3d(a, b, c, d), Sign::zero);
    // sign_triple: w in the span of u, v.
    ASSERT_EQ(sign_triple(b - a, c - a, d - a), Sign::zero);
    // sign_dot: v perpendicular to u.
    Vec3 perp = cross(a, b);
    ASSERT_EQ(sign_dot(a, perp), Sign::zero);
    // compare_dot: v - w perpendicular to n.
    ASSERT_EQ(compare_dot(a, a + cross(n, c), n), Sign::zero);
    // side_of_plane: p on the plane.
    ASSERT_EQ(side_of_plane(d, n, dot(a, n)), Sign::zero);
    // orient2d / sign_cross2 / sign_dot (2D): collinear, perpendicular.
    Vec2 a2{a.x, a.y}, b2{b.x, b.y};
    Vec2 c2 = a2 + s * (b2 - a2);
    ASSERT_EQ(orient2d(a2, b2, c2), Sign::zero);
    ASSERT_EQ(sign_cross2(b2 - a2, t * (b2 - a2)), Sign::zero);
    ASSERT_EQ(sign_dot(b2, Vec2{-b2.y, b2.x}), Sign::zero);
    zero_calls += 8;
    // is_parallel: true needs the exact path too.
    ASSERT_TRUE(is_parallel(n, t * n));
    zero_calls += 1;

    // Perturbed by +-eps along the normal: sign known by construction.
    Rational e = (i % 4 < 2) ? eps : Rational(-eps);
    Sign expected = sign_of(sgn(e));
    CountersSince perturbed;
    ASSERT_EQ(orient3d(a, b, c, d + e * n), expected);              // det = e |n|^2
    ASSERT_EQ(sign_triple(b - a, c - a, d - a + e * n), expected);  // same
    ASSERT_EQ(sign_dot(a, perp + e * a), is_zero(a) ? Sign::zero : expected);
    ASSERT_EQ(compare_dot(a, a + cross(n, c) - e * n, n), expected);  // dot(v - w, n) = e |n|^2
    ASSERT_EQ(side_of_plane(d + e * n, n, dot(a, n)), expected);
    Vec2 ab = b2 - a2, ab_perp{-ab.y, ab.x};
    if (ab != Vec2{0, 0}) {
      ASSERT_EQ(orient2d(a2, b2, c2 + e * ab_perp), expected);  // cross = e |ab|^2
      ASSERT_EQ(sign_cross2(ab, t * ab + e * ab_perp), expected);
    }
    ASSERT_FALSE(is_parallel(n, t * n + e * (b - a)));
    perturbed_exact += perturbed.exact();
  }
  EXPECT_GT(zero_calls, 1000);
  // Every exact zero must have come from the exact fallback (the filter can
  // never prove zero), so the fallback count is at least their number.
  EXPECT_GE(counters.exact(), static_cast<std::uint64_t>(zero_calls));
  // The perturbations are far below double resolution: the fallback decided.
  EXPECT_GT(perturbed_exact, 1000u);
}

// An integer vector, maybe zero: two coordinates in [-1000, 1000], the third
// of up to `bits` bits (a facet's primitive normal may be long).
Vec3 integer_normal(Rng& rng, unsigned bits) {
  const long x = static_cast<long>(rng() % 2001) - 1000;
  const long y = static_cast<long>(rng() % 2001) - 1000;
  const unsigned z_bits = 1u + static_cast<unsigned>(rng() % bits);
  return {x, y, Rational(test::random_integer(rng, z_bits))};
}

// compare_dot with an integer normal (every facet normal is one) takes its
// own exact path: L (v - w) over the lcm L of the denominators, no rational
// canonicalised. Against the written-out oracle on every kind of coordinate,
// and on exact ties made by construction (w = v + a vector orthogonal to n,
// then nudged by a tiny multiple of n).
TEST(Predicates, CompareDotWithIntegerNormalsMatchesTheOracle) {
  for (Kind kind : all_kinds) {
    const unsigned seed = 900 + static_cast<unsigned>(kind);
    SCOPED_TRACE("seed " + std::to_string(seed));
    Rng rng(seed);
    for (int i = 0; i < 400; ++i) {
      const Vec3 v = point3(rng, kind), w = point3(rng, kind), u = point3(rng, kind);
      const Vec3 n = integer_normal(rng, 120u);
      ASSERT_EQ(compare_dot(v, w, n), oracle_compare_dot(v, w, n)) << "case " << i;
      if (is_zero(n)) continue;
      const Vec3 tie = v + cross(n, u);  // dot(v - tie, n) = 0 exactly
      ASSERT_EQ(compare_dot(v, tie, n), Sign::zero) << "case " << i;
      const Rational e = power_of_ten(-30);
      ASSERT_EQ(compare_dot(v, tie - e * n, n), Sign::positive) << "case " << i;
      ASSERT_EQ(compare_dot(v, tie + e * n, n), Sign::negative) << "case " << i;
    }
  }
}

// The filter-only predicates answer only when the filter proves the sign,
// and then the oracle's sign, with the cached and the loose cached
// approximations alike. compare_dot_if_certain: an exact tie (w = v + a
// vector orthogonal to n) is never answered, one nudged by 10^-30 n may or
// may not be. side_of_plane_if_certain: a point exactly on the plane is
// never answered, points a hair (10^-30 n) off it may or may not be.
TEST(Predicates, IfCertainIsTheOracleOrNothing) {
  for (Kind kind : all_kinds) {
    const unsigned seed = 950 + static_cast<unsigned>(kind);
    SCOPED_TRACE("seed " + std::to_string(seed));
    Rng rng(seed);
    int answered = 0;
    const auto check = [&](std::optional<Sign> s, Sign expected, int i) {
      if (!s) return;
      ++answered;
      ASSERT_EQ(*s, expected) << "case " << i;
    };
    for (int i = 0; i < 400; ++i) {
      const Vec3 v = point3(rng, kind), w = point3(rng, kind), u = point3(rng, kind);
      const Vec3 n = integer_normal(rng, 60u);
      const Vec3 hair = power_of_ten(-30) * n;
      const Vec3 tie = v + cross(n, u);
      const ApproxVec3 pn = ApproxVec3::of(n), ln = loose3(n);
      const ApproxVec3 pv = ApproxVec3::of(v), lv = loose3(v);
      for (const Vec3& other : {w, tie, Vec3(tie - hair)}) {
        const ApproxVec3 po = ApproxVec3::of(other), lo = loose3(other);
        const Sign expected = oracle_compare_dot(v, other, n);
        check(compare_dot_if_certain({v, pv}, {other, po}, {n, pn}), expected, i);
        check(compare_dot_if_certain({v, lv}, {other, lo}, {n, ln}), expected, i);
      }
      ASSERT_FALSE(compare_dot_if_certain({v, pv}, {tie, ApproxVec3::of(tie)}, {n, pn})) << "case " << i;
      const Rational on = dot(n, v);  // the plane through v
      for (const Vec3& x : {w, v, Vec3(v + hair), Vec3(v - hair)}) {
        const Sign expected = oracle_side(x, n, on);
        check(side_of_plane_if_certain(ApproxVec3::of(x), pn, Approx::of(on)), expected, i);
        check(side_of_plane_if_certain(loose3(x), ln, loosen(Approx::of(on))), expected, i);
      }
      ASSERT_FALSE(side_of_plane_if_certain(pv, pn, Approx::of(on))) << "case " << i;
    }
    EXPECT_GT(answered, 800);  // random points are mostly far from a tie or the plane
  }
}

// The exact paths with an integer normal scale a point to the lcm of its
// denominators, skipping the quotient for a denominator equal to it and the
// gcd for one that divides or is divided by the others: points over one
// shared denominator, over nested ones (10^3 and 10^6, 2^40 and 2^90, a
// long odd d and 7 d) and over coprime ones, placed exactly on a plane
// (offset = dot(n, p)), next to it (offset moved by 10^-40 or 2^-300) and
// anywhere, against the written-out oracles.
TEST(Predicates, IntegerNormalsOnPointsOverRelatedDenominators) {
  for (const unsigned seed : {1300U, 1301U, 1302U}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    Rng rng(seed);
    for (int i = 0; i < 400; ++i) {
      const mpz_class odd = test::random_integer(rng, 100) * 2 + 1;
      const Rational related[][2] = {
          {power_of_ten(-3), power_of_ten(-6)},
          {power_of_two(-40), power_of_two(-90)},
          {fraction(1, abs(odd)), fraction(1, abs(odd) * 7)},
          {fraction(1, 3), fraction(1, 1024)},
      };
      const auto& units = related[rng() % 4];
      Vec3 p;
      for (int k = 0; k < 3; ++k)
        p[k] = Rational(test::random_integer(rng, 80)) * units[rng() % 2];
      const Vec3 n{Rational(test::random_integer(rng, 1u + static_cast<unsigned>(rng() % 120))),
                   static_cast<long>(rng() % 21) - 10, Rational(test::random_integer(rng, 60))};
      const Rational on = dot(n, p);
      const Rational moves[] = {0, power_of_ten(-40), -power_of_ten(-40), power_of_two(-300), -power_of_two(-300),
                                test::random_rational(rng)};
      for (const Rational& move : moves) {
        const Rational offset = on + move;
        ASSERT_EQ(side_of_plane(p, n, offset), oracle_side(p, n, offset)) << "case " << i << ", move " << move;
      }
      const Vec3 q = p + cross(n, Vec3{units[0], units[1], 1});  // dot(n, q) = dot(n, p)
      ASSERT_EQ(compare_dot(p, q, n), oracle_compare_dot(p, q, n)) << "case " << i;
      ASSERT_EQ(compare_dot(p, q + power_of_two(-300) * n, n), oracle_compare_dot(p, q + power_of_two(-300) * n, n))
          << "case " << i;
    }
  }
}

TEST(Predicates, ZeroAnswersAlwaysComeFromTheFallback) {
  // One call, one count; a zero is always an exact evaluation.
  Vec3 a{1, 2, 3}, b{2, 4, 6};
  CountersSince c1;
  EXPECT_EQ(orient3d(a, b, Vec3{0, 0, 0}, Vec3{7, 1, 2}), Sign::zero);  // a, b, origin collinear
  EXPECT_EQ(c1.exact(), 1u);
  EXPECT_EQ(c1.filtered(), 0u);
  CountersSince c2;
  // cross(b - a, c - a) = (2, -1, 0), d - a = (6, -1, -1): 13 > 0.
  EXPECT_EQ(orient3d(a, b, Vec3{0, 0, 1}, Vec3{7, 1, 2}), Sign::positive);
  EXPECT_EQ(c2.filtered(), 1u);
  EXPECT_EQ(c2.exact(), 0u);
}

TEST(Predicates, CoplanarUpToTheLastBit) {
  // a, b, c doubles; d = a + s (b - a) + t (c - a) computed exactly, then
  // rounded to the nearest double in each coordinate. The determinant is
  // then of the order of the rounding, far inside the filter's bound: the
  // answer must still be exact, via the fallback.
  Rng rng(11);
  CountersSince counters;
  int calls = 0;
  for (int i = 0; i < 1000; ++i) {
    double scale = (i % 3 == 0) ? 1.0 : (i % 3 == 1 ? 1e-3 : 1e6);
    auto rnd = [&] { return Rational(test::random_uniform(rng, -scale, scale)); };
    Vec3 a{rnd(), rnd(), rnd()}, b{rnd(), rnd(), rnd()}, c{rnd(), rnd(), rnd()};
    Rational s(test::random_uniform(rng, -2, 2)), t(test::random_uniform(rng, -2, 2));
    Vec3 exact_d = a + s * (b - a) + t * (c - a);
    Vec3 d{Rational(to_double_nearest(exact_d.x)), Rational(to_double_nearest(exact_d.y)),
           Rational(to_double_nearest(exact_d.z))};
    ASSERT_EQ(orient3d(a, b, c, d), oracle_orient3d(a, b, c, d)) << "case " << i;
    Vec2 a2{a.x, a.y}, b2{b.x, b.y};
    Vec2 exact_c2 = a2 + s * (b2 - a2);
    Vec2 c2{Rational(to_double_nearest(exact_c2.x)), Rational(to_double_nearest(exact_c2.y))};
    ASSERT_EQ(orient2d(a2, b2, c2), oracle_orient2d(a2, b2, c2)) << "case " << i;
    calls += 2;
  }
  // Most of these cannot be decided in double.
  EXPECT_GT(counters.exact(), static_cast<std::uint64_t>(calls / 2));
}

TEST(Predicates, ExactlyCoplanarDoublesWithLargeOffset) {
  // Points 1e9 + k 2^-20: exact doubles; d = b + c - a is exactly coplanar
  // (and still exact in double). Translating a known positive configuration
  // by 1e9 + 1/3 (not a double) keeps its sign.
  Rng rng(13);
  CountersSince counters;
  for (int i = 0; i < 300; ++i) {
    auto coord = [&] { return Rational(1e9 + std::ldexp(static_cast<double>(rng() % 2048) - 1024, -20)); };
    Vec3 a{coord(), coord(), coord()}, b{coord(), coord(), coord()}, c{coord(), coord(), coord()};
    Vec3 d = b + c - a;
    ASSERT_TRUE(is_double_exact(d.x) && is_double_exact(d.y) && is_double_exact(d.z));
    ASSERT_EQ(orient3d(a, b, c, d), Sign::zero);
  }
  EXPECT_EQ(counters.exact(), 300u);
  Rational offset = Rational(1000000000) + Rational(1, 3);
  Vec3 t{offset, offset, offset};
  Rational small = power_of_ten(-6);
  Vec3 o{0, 0, 0}, ex{small, 0, 0}, ey{0, small, 0}, ez{0, 0, small};
  EXPECT_EQ(orient3d(o + t, ex + t, ey + t, ez + t), Sign::positive);
  EXPECT_EQ(orient3d(o + t, ey + t, ex + t, ez + t), Sign::negative);
  EXPECT_EQ(compare_dot(ex + t, o + t, Vec3{1, 0, 0}), Sign::positive);
  EXPECT_EQ(compare_dot(ey + t, ex + t, Vec3{1, 1, 0}), Sign::zero);
}

// Scaling by a positive factor keeps every sign: the answer is the sign of
// the small integer configuration, whatever the scale does to doubles.
TEST(Predicates, ExtremeScalesKeepTheSign) {
  const std::vector<Rational> scales = {
      power_of_ten(300),  power_of_ten(-300), power_of_two(-1074),  // 5e-324
      power_of_ten(-320), power_of_two(1000), power_of_ten(200) / 3, Rational(1)};
  Rng rng(17);
  for (std::size_t si = 0; si < scales.size(); ++si) {
    SCOPED_TRACE("scale " + std::to_string(si));
    const Rational& k = scales[si];
    CountersSince counters;
    int nonzero = 0;
    for (int i = 0; i < 200; ++i) {
      Vec3 a = point3(rng, Kind::small_integer), b = point3(rng, Kind::small_integer);
      Vec3 c = point3(rng, Kind::small_integer), d = point3(rng, Kind::small_integer);
      Sign o3 = oracle_orient3d(a, b, c, d), dt = oracle_dot(a, b), cd = oracle_compare_dot(a, b, c);
      Sign tr = oracle_det3(a, b, c), sp = oracle_side(a, b, d.x);
      Sign o2 = oracle_orient2d(Vec2{a.x, a.y}, Vec2{b.x, b.y}, Vec2{c.x, c.y});
      bool par = oracle_parallel(a, b);
      Vec3 A = k * a, B = k * b, C = k * c, D = k * d;
      ASSERT_EQ(orient3d(A, B, C, D), o3);
      ASSERT_EQ(sign_dot(A, B), dt);
      ASSERT_EQ(compare_dot(A, B, C), cd);
      ASSERT_EQ(sign_triple(A, B, C), tr);
      ASSERT_EQ(side_of_plane(A, B, k * k * d.x), sp);
      ASSERT_EQ(orient2d(Vec2{A.x, A.y}, Vec2{B.x, B.y}, Vec2{C.x, C.y}), o2);
      ASSERT_EQ(is_parallel(A, B), par);
      if (o3 != Sign::zero) ++nonzero;
    }
    EXPECT_GT(nonzero, 50);
    // Products of 1e300 overflow and of 1e-300 underflow: nothing may be
    // decided in double there. (At scale 1 the filter answers the nonzero
    // cases.)
    if (si <= 4) {
      EXPECT_EQ(counters.filtered(), 0u);
    }
    if (si == 6) {
      EXPECT_GT(counters.filtered(), 400u);
    }
  }
}

TEST(Predicates, MixedMagnitudes) {
  Rational big(1e300), tiny(1e-300), denormal(5e-324);
  Vec3 o{0, 0, 0};
  // det = 1e300 * 1e-300 * 5e-324 (as exact rationals) > 0.
  EXPECT_EQ(orient3d(o, Vec3{big, 0, 0}, Vec3{0, tiny, 0}, Vec3{1, 1, denormal}), Sign::positive);
  EXPECT_EQ(orient3d(o, Vec3{0, tiny, 0}, Vec3{big, 0, 0}, Vec3{1, 1, denormal}), Sign::negative);
  // dot((1e300, 1e-300, 1), (1e-300, -1e300, 0)) = 1e300*1e-300 - 1e-300*1e300 = 0 exactly.
  EXPECT_EQ(sign_dot(Vec3{big, tiny, 1}, Vec3{tiny, -big, 0}), Sign::zero);
  EXPECT_EQ(sign_dot(Vec3{big, tiny, 1}, Vec3{tiny, -big, denormal}), Sign::positive);
  // compare_dot with a huge and a tiny coordinate: the tiny one decides.
  EXPECT_EQ(compare_dot(Vec3{big, denormal, 0}, Vec3{big, 0, 0}, Vec3{1, 1, 0}), Sign::positive);
  EXPECT_EQ(compare_dot(Vec3{big, 0, 0}, Vec3{big, denormal, 0}, Vec3{1, 1, 0}), Sign::negative);
  EXPECT_EQ(side_of_plane(Vec3{big, 1, 0}, Vec3{1, 0, 0}, big), Sign::zero);
  EXPECT_EQ(side_of_plane(Vec3{big, 0, 0}, Vec3{1, denormal, 0}, big - 1), Sign::positive);
  EXPECT_FALSE(is_parallel(Vec3{big, 0, 0}, Vec3{big, denormal, 0}));
  EXPECT_TRUE(is_parallel(Vec3{big, denormal, 0}, Vec3{big * 2, denormal * 2, 0}));
  EXPECT_EQ(sign_cross2(Vec2{big, denormal}, Vec2{big, 0}), Sign::negative);
}

TEST(Predicates, UnknownApproximationsFallBack) {
  // A cached approximation marked unknown (infinite error) is never trusted.
  Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1};
  ApproxVec3 pa = ApproxVec3::of(a), pb = ApproxVec3::of(b), pc = ApproxVec3::of(c), pd = ApproxVec3::of(d);
  pd.z = {-1.0, INFINITY};  // wrong value, but no claim
  CountersSince counters;
  EXPECT_EQ(orient3d(Vec3Ref{a, pa}, Vec3Ref{b, pb}, Vec3Ref{c, pc}, Vec3Ref{d, pd}), Sign::positive);
  EXPECT_EQ(counters.exact(), 1u);
}

// ---------- ccw_in_between against a pseudo-angle oracle ----------

// A strictly increasing function of the counterclockwise angle from +x in
// [0, 4), exact and angle-free: each quadrant is mapped through a ratio.
Rational pseudo_angle(const Vec2& v) {
  const Rational& x = v.x;
  const Rational& y = v.y;
  if (x > 0 && y >= 0) return y / (x + y);
  if (x <= 0 && y > 0) return 1 + (-x) / (-x + y);
  if (x < 0 && y <= 0) return 2 + (-y) / (-x - y);
  return 3 + x / (x - y);  // x >= 0, y < 0
}

bool oracle_ccw_in_between(const Vec2& d, const Vec2& d1, const Vec2& d2) {
  auto relative = [&](const Vec2& v) {
    Rational r = pseudo_angle(v) - pseudo_angle(d1);
    return r < 0 ? Rational(r + 4) : r;
  };
  Rational r = relative(d), r2 = relative(d2);
  if (r2 == 0) return r != 0;  // same direction: all but that direction
  return r > 0 && r < r2;
}

TEST(Predicates, CcwInBetweenExhaustive) {
  std::vector<Vec2> dirs;
  for (int x = -2; x <= 2; ++x)
    for (int y = -2; y <= 2; ++y)
      if (x != 0 || y != 0) dirs.push_back(Vec2{x, y});  // includes same directions, e.g. (1,1), (2,2)
  Rational third(1, 3), tiny = power_of_ten(-300), huge = power_of_ten(300);
  for (const Vec2& extra :
       {Vec2{third, third}, Vec2{third, 2 * third}, Vec2{Rational(-1, 7), third}, Vec2{tiny, 1},
        Vec2{-huge, tiny}, Vec2{3, 1 + tiny}, Vec2{-third, -third}, Vec2{Rational(5e-324), -1}})
    dirs.push_back(extra);
  std::vector<ApproxVec2> approx;
  for (const Vec2& v : dirs) approx.push_back(ApproxVec2::of(v));
  CountersSince counters;
  int inside = 0;
  for (std::size_t i = 0; i < dirs.size(); ++i)
    for (std::size_t j = 0; j < dirs.size(); ++j)
      for (std::size_t k = 0; k < dirs.size(); ++k) {
        bool expected = oracle_ccw_in_between(dirs[i], dirs[j], dirs[k]);
        ASSERT_EQ(ccw_in_between(dirs[i], dirs[j], dirs[k]), expected) << i << " " << j << " " << k;
        ASSERT_EQ(ccw_in_between(Vec2Ref{dirs[i], approx[i]}, Vec2Ref{dirs[j], approx[j]},
                                 Vec2Ref{dirs[k], approx[k]}),
                  expected)
            << i << " " << j << " " << k;
        inside += expected;
      }
  EXPECT_GT(inside, 1000);
  EXPECT_GT(counters.exact(), 0u);     // collinear directions needed the fallback
  EXPECT_GT(counters.filtered(), 0u);  // and most did not
}

TEST(Predicates, CcwInBetweenSpecialSectors) {
  Vec2 ex{1, 0}, ey{0, 1};
  EXPECT_TRUE(ccw_in_between(Vec2{1, 1}, ex, ey));
  EXPECT_FALSE(ccw_in_between(Vec2{1, -1}, ex, ey));
  EXPECT_FALSE(ccw_in_between(ex, ex, ey));  // boundaries excluded
  EXPECT_FALSE(ccw_in_between(ey, ex, ey));
  EXPECT_TRUE(ccw_in_between(Vec2{1, -1}, ey, ex));          // the wide sector
  EXPECT_TRUE(ccw_in_between(Vec2{-1, 0}, ex, Vec2{2, 0}));  // whole turn minus +x
  EXPECT_FALSE(ccw_in_between(Vec2{3, 0}, ex, Vec2{2, 0}));
  EXPECT_TRUE(ccw_in_between(ey, ex, Vec2{-1, 0}));  // half-turn: left of d1
  EXPECT_FALSE(ccw_in_between(Vec2{0, -1}, ex, Vec2{-1, 0}));
}

}  // namespace
}  // namespace cvms
