// SPDX-License-Identifier: MIT
// Tests of the planar convolution against an independent oracle: the convex
// hull (Andrew's monotone chain, plain rational arithmetic, no cvms
// predicates) of all pairwise vertex sums, compared exactly as vertex
// sequences starting at the lowest vertex.
#include "cvms/planar_sum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "cvms/error.hpp"

namespace cvms {
namespace {

using Poly = std::vector<Vec2>;

Rational oracle_cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Strictly convex hull, counterclockwise, starting at the lowest (min y, then
// min x) point; a point or a segment (lowest endpoint first) when degenerate.
Poly oracle_hull(Poly pts) {
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() <= 1) return pts;
  Poly hull(2 * pts.size());
  std::size_t k = 0;
  for (const Vec2& pt : pts) {
    while (k >= 2 && oracle_cross(hull[k - 2], hull[k - 1], pt) <= 0) --k;
    hull[k++] = pt;
  }
  for (std::size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && oracle_cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  auto lowest = std::min_element(hull.begin(), hull.end(), [](const Vec2& a, const Vec2& b) {
    return a.y != b.y ? a.y < b.y : a.x < b.x;
  });
  std::rotate(hull.begin(), lowest, hull.end());
  return hull;
}

Poly pairwise_sums(const Poly& p, const Poly& q) {
  Poly out;
  for (const Vec2& a : p)
    for (const Vec2& b : q) out.push_back(a + b);
  return out;
}

std::string show(const Poly& poly) {
  std::string s;
  // Appended piece by piece: "literal" + std::string&& makes GCC 12 at -O3
  // warn a false -Wrestrict (GCC bug 105329).
  for (const Vec2& v : poly) {
    s += '(';
    s += v.x.get_str();
    s += ", ";
    s += v.y.get_str();
    s += ") ";
  }
  return s;
}

// Checks planar_sum(p, q) and planar_sum(q, p) against the oracle.
void expect_sum(const Poly& p, const Poly& q) {
  SCOPED_TRACE("p = " + show(p) + "\nq = " + show(q));
  const Poly expected = oracle_hull(pairwise_sums(p, q));
  const std::vector<IndexPair> pairs = planar_sum_indices(p, q);
  ASSERT_LE(pairs.size(), p.size() + q.size() + (p.size() == 1 && q.size() == 1 ? 1 : 0));
  Poly got;
  for (const IndexPair& pair : pairs) {
    ASSERT_LT(pair.first, p.size());
    ASSERT_LT(pair.second, q.size());
    got.push_back(p[pair.first] + q[pair.second]);
  }
  EXPECT_EQ(show(got), show(expected));
  EXPECT_TRUE(planar_sum(p, q) == expected);
  EXPECT_TRUE(planar_sum(q, p) == expected) << "not commutative";
}

// Starts the vertex list at a different index (the input need not start at
// the lowest vertex).
Poly rotated_start(Poly poly, std::size_t shift) {
  if (!poly.empty())
    std::rotate(poly.begin(), poly.begin() + static_cast<std::ptrdiff_t>(shift % poly.size()), poly.end());
  return poly;
}

Poly negated(Poly poly) {
  for (Vec2& v : poly) v = -v;
  return poly;
}

Poly scaled(Poly poly, const Rational& s, const Vec2& offset) {
  for (Vec2& v : poly) v = s * v + offset;
  return poly;
}

Poly random_points(std::mt19937_64& rng, int n, int range, int max_den) {
  std::uniform_int_distribution<int> coord(-range, range);
  std::uniform_int_distribution<int> den(1, max_den);
  Poly pts;
  for (int i = 0; i < n; ++i) {
    Rational x(coord(rng), den(rng));
    Rational y(coord(rng), den(rng));
    x.canonicalize();
    y.canonicalize();
    pts.push_back({x, y});
  }
  return pts;
}

Poly v2(std::initializer_list<std::pair<int, int>> pts) {
  Poly out;
  for (auto [x, y] : pts) out.push_back({Rational(x), Rational(y)});
  return out;
}

// The integer points on the circle x^2 + y^2 = r^2 (r = 5*13 has 12 primitive
// directions up to symmetry): a centrally and axis-symmetric polygon with many
// pairs of parallel edges.
Poly lattice_circle(int r) {
  Poly pts;
  for (int x = -r; x <= r; ++x)
    for (int y = -r; y <= r; ++y)
      if (x * x + y * y == r * r) pts.push_back({Rational(x), Rational(y)});
  return oracle_hull(pts);
}

TEST(PlanarSum, PointPlusPoint) {
  Poly p = v2({{3, -2}});
  Poly q = v2({{-1, 5}});
  EXPECT_EQ(planar_sum_indices(p, q), (std::vector<IndexPair>{{0, 0}}));
  expect_sum(p, q);
}

TEST(PlanarSum, SquarePlusSquareHandChecked) {
  Poly sq = v2({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  // Start q elsewhere: its lowest vertex is index 2.
  Poly q = rotated_start(v2({{0, 0}, {2, 0}, {2, 3}, {0, 3}}), 2);
  std::vector<IndexPair> pairs = planar_sum_indices(sq, q);
  EXPECT_EQ(pairs, (std::vector<IndexPair>{{0, 2}, {1, 3}, {2, 0}, {3, 1}}));
  EXPECT_TRUE(planar_sum(sq, q) == v2({{0, 0}, {3, 0}, {3, 4}, {0, 4}}));
}

TEST(PlanarSum, TrianglePlusReflectedTriangleIsHexagon) {
  Poly t = v2({{0, 0}, {2, 0}, {0, 2}});
  EXPECT_TRUE(planar_sum(t, negated(t)) == v2({{0, -2}, {2, -2}, {2, 0}, {0, 2}, {-2, 2}, {-2, 0}}));
  expect_sum(t, negated(t));
}

TEST(PlanarSum, SegmentPlusSegment) {
  // Non-parallel: a parallelogram.
  Poly s = v2({{0, 0}, {2, 1}});
  Poly t = v2({{0, 3}, {1, 0}});
  EXPECT_TRUE(planar_sum(s, t) == v2({{1, 0}, {3, 1}, {2, 4}, {0, 3}}));
  // Parallel, same and opposite orientation: a segment.
  Poly u = v2({{4, 2}, {0, 0}});
  EXPECT_TRUE(planar_sum(s, u) == v2({{0, 0}, {6, 3}}));
  Poly w = v2({{-2, -1}, {-4, -2}});
  EXPECT_TRUE(planar_sum(s, w) == v2({{-4, -2}, {0, 0}}));
  expect_sum(s, t);
  expect_sum(s, u);
  expect_sum(s, w);
  // Horizontal and vertical.
  expect_sum(v2({{0, 0}, {5, 0}}), v2({{1, 1}, {-3, 1}}));
  expect_sum(v2({{0, 0}, {0, 5}}), v2({{1, 1}, {1, -3}}));
  expect_sum(v2({{0, 0}, {5, 0}}), v2({{0, 0}, {0, 5}}));
}

TEST(PlanarSum, SegmentsInAllDirectionsWithPolygonsAndPoints) {
  std::vector<Poly> others = {
      v2({{7, -3}}),
      v2({{0, 0}, {1, 0}, {1, 1}, {0, 1}}),
      v2({{0, 0}, {3, 1}, {2, 3}, {-1, 2}}),
      v2({{0, 0}, {2, 0}, {3, 1}, {3, 2}, {2, 3}, {0, 3}, {-1, 2}, {-1, 1}}),
      lattice_circle(5),
  };
  for (int dx = -3; dx <= 3; ++dx) {
    for (int dy = -3; dy <= 3; ++dy) {
      if (dx == 0 && dy == 0) continue;
      Poly seg = v2({{1, 2}, {1 + dx, 2 + dy}});
      for (const Poly& other : others) expect_sum(seg, other);
      for (int ex = -2; ex <= 2; ++ex)
        for (int ey = -2; ey <= 2; ++ey)
          if (ex != 0 || ey != 0) expect_sum(seg, v2({{0, 0}, {ex, ey}}));
    }
  }
}

TEST(PlanarSum, PolygonPlusPoint) {
  Poly poly = v2({{0, 0}, {3, 1}, {2, 3}, {-1, 2}});
  for (std::size_t shift = 0; shift < poly.size(); ++shift) {
    Poly p = rotated_start(poly, shift);
    std::vector<IndexPair> pairs = planar_sum_indices(p, v2({{10, 10}}));
    ASSERT_EQ(pairs.size(), 4U);
    for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(pairs[k].first, (k + 4 - shift) % 4);
    expect_sum(p, v2({{10, 10}}));
  }
}

TEST(PlanarSum, ParallelEdges) {
  Poly rect = v2({{0, 0}, {4, 0}, {4, 1}, {0, 1}});
  Poly rect2 = v2({{-1, -5}, {0, -5}, {0, 2}, {-1, 2}});
  expect_sum(rect, rect2);
  expect_sum(rect, rect);
  Poly oct = v2({{0, 0}, {2, 0}, {3, 1}, {3, 2}, {2, 3}, {0, 3}, {-1, 2}, {-1, 1}});
  expect_sum(oct, oct);
  expect_sum(oct, negated(oct));
  expect_sum(oct, rect);
  // A polygon and itself, and its 180-degree rotation, from every start.
  for (int r : {5, 25, 65}) {
    Poly c = lattice_circle(r);
    SCOPED_TRACE("r " + std::to_string(r));
    for (std::size_t shift = 0; shift < c.size(); shift += 3) {
      expect_sum(c, rotated_start(c, shift));
      expect_sum(rotated_start(c, shift), negated(c));
      expect_sum(c, rect);
    }
    // Every vertex of c + c is 2 c[i]: each pair must be (i, i).
    for (const IndexPair& pair : planar_sum_indices(c, c)) EXPECT_EQ(pair.first, pair.second);
  }
  // A triangle and its reflection share no direction but every edge line is
  // parallel to one of the other's.
  Poly tri = v2({{0, 0}, {5, 1}, {1, 4}});
  expect_sum(tri, negated(tri));
  expect_sum(tri, scaled(tri, Rational(3, 7), {Rational(1, 3), Rational(-2)}));
}

TEST(PlanarSum, RandomConvexPolygons) {
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> count(1, 30);
    std::uniform_int_distribution<int> style(0, 4);
    auto make = [&]() {
      int s = style(rng);
      int range = s == 0 ? 3 : (s == 1 ? 20 : 1000);  // small ranges force parallel edges
      int max_den = s == 2 ? 7 : 1;
      Poly pts = random_points(rng, count(rng), range, max_den);
      if (s == 3) {  // centrally symmetric: all edges come in parallel pairs
        Poly mirrored = negated(pts);
        pts.insert(pts.end(), mirrored.begin(), mirrored.end());
      }
      Poly hull = oracle_hull(pts);
      return rotated_start(hull, static_cast<std::size_t>(rng() % hull.size()));
    };
    Poly p = make();
    Poly q = make();
    expect_sum(p, q);
    expect_sum(p, p);
    expect_sum(p, negated(p));
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(PlanarSum, HugeAndTinyCoordinates) {
  std::mt19937_64 rng(7);
  const Rational huge = Rational(mpz_class("1000000000000"));  // 1e12
  const Rational tiny = 1 / huge;                              // 1e-12
  const Vec2 far{Rational(mpz_class("1000000000"), 3), Rational(-1000000000)};
  for (int round = 0; round < 30; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    Poly p = oracle_hull(random_points(rng, 12, 50, 3));
    Poly q = oracle_hull(random_points(rng, 12, 50, 3));
    expect_sum(scaled(p, huge, far), scaled(q, tiny, {}));
    expect_sum(scaled(p, tiny, far), scaled(q, tiny, far));
    expect_sum(scaled(p, huge, {}), scaled(p, huge, far));
  }
  // A needle: an extremely thin polygon next to its own reflection.
  Poly needle = {{Rational(0), Rational(0)}, {huge, Rational(0)}, {huge, tiny}};
  expect_sum(needle, negated(needle));
  expect_sum(needle, v2({{0, 0}, {1, 0}}));
}

TEST(PlanarSum, NearlyParallelEdgesBeyondDoublePrecision) {
  // Edge directions (N+1, N), (N, N-1), (2N+2, 2N) with N = 2^60: the first
  // two differ by an angle far below double resolution, the first and third
  // are exactly parallel. Only exact decisions get all three sums right.
  const Rational n(mpz_class(1) << 60);
  const Rational one(1);
  auto tri = [](const Rational& dx, const Rational& dy) {
    return Poly{{Rational(0), Rational(0)}, {dx, dy}, {Rational(0), dy}};
  };
  Poly a = tri(n + one, n);
  Poly b = tri(n, n - one);
  Poly c = tri(2 * (n + one), 2 * n);
  expect_sum(a, b);
  expect_sum(a, c);
  expect_sum(b, c);
  expect_sum(a, negated(b));
  EXPECT_EQ(planar_sum(a, c).size(), 3U);  // a and c are homothetic
  EXPECT_EQ(planar_sum(a, b).size(), 4U);  // the near-parallel long edges stay apart
  expect_sum(a, Poly{{Rational(0), Rational(0)}, {n, n - one}});
}

// Operands whose coordinates share a denominator L with every L * x below
// 2^62 in magnitude are merged in machine integers (lib/planar/
// small_points.hpp); these straddle that bound, so that an overflow in the
// integer path, or a wrong choice between the paths, disagrees with the
// oracle.
TEST(PlanarSum, CoordinatesAtTheMachineIntegerBound) {
  const mpz_class below = (mpz_class(1) << 62) - 1;
  for (const mpz_class& m : {below, mpz_class(below + 1), mpz_class(below + 2)}) {
    SCOPED_TRACE("m = " + m.get_str());
    const Rational big(m);
    const Rational one(1);
    // Extreme corners: every edge vector has a coordinate near 2m, and the
    // cross products of near-parallel edges come within a few units of
    // 2^126 before they cancel.
    Poly square{{-big, -big}, {big, -big}, {big, big}, {-big, big}};
    Poly near_diagonal{{-big, -big}, {big, big - one}, {big - one, big}};
    Poly thin{{-big, -big + one}, {big - one, big}, {-big, -big + 2}};
    expect_sum(square, near_diagonal);
    expect_sum(near_diagonal, negated(near_diagonal));
    expect_sum(thin, near_diagonal);
    expect_sum(thin, negated(thin));
    // The same shapes over a denominator: L * x reaches the bound only
    // through the common denominator.
    const Rational third(1, 3);
    expect_sum(scaled(near_diagonal, third, {}), scaled(thin, third, {third, third}));
  }
}

// Denominators whose least common multiple overflows 64 bits, though each is
// small, and short decimals (the scanned-mesh case, all in machine integers).
TEST(PlanarSum, ManyDenominatorsAndShortDecimals) {
  Poly primes;
  const int denominators[] = {1000003, 999983, 1000033, 999979};
  const std::pair<int, int> corners[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int k = 0; k < 4; ++k) {
    Rational x(corners[k].first * 2 * denominators[k] + 1, denominators[k]);
    Rational y(corners[k].second * 2 * denominators[k] + 1, denominators[k]);
    x.canonicalize();
    y.canonicalize();
    primes.push_back({x, y});
  }
  expect_sum(primes, negated(primes));
  expect_sum(primes, v2({{0, 0}, {3, 1}, {1, 2}}));
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> micro(-2000000, 2000000);
    Poly pts;
    for (int i = 0; i < 40; ++i) {
      Rational x(micro(rng), 1000000);
      Rational y(micro(rng), 1000000);
      x.canonicalize();
      y.canonicalize();
      pts.push_back({x, y});
    }
    const Poly hull = oracle_hull(pts);
    expect_sum(hull, hull);
    expect_sum(hull, negated(hull));
    if (::testing::Test::HasFailure()) return;
  }
}

void expect_invalid(const Poly& p, const Poly& q, const std::string& fragment) {
  try {
    (void)planar_sum_indices(p, q);
    ADD_FAILURE() << "no error for " << fragment;
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(PlanarSum, RejectsBadInput) {
  Poly sq = v2({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  expect_invalid({}, sq, "operand p: empty");
  expect_invalid(sq, {}, "operand q: empty");
  expect_invalid(v2({{1, 1}, {1, 1}}), sq, "coincide");
  expect_invalid(sq, v2({{0, 0}, {1, 0}, {1, 0}, {0, 1}}), "coincide");
  expect_invalid(v2({{0, 0}, {0, 1}, {1, 1}, {1, 0}}), sq, "counterclockwise");  // clockwise
  expect_invalid(v2({{0, 0}, {1, 0}, {2, 0}, {1, 1}}), sq, "vertex 1");          // collinear
  expect_invalid(v2({{0, 0}, {2, 1}, {1, 0}}), sq, "counterclockwise");          // clockwise triangle
  expect_invalid(v2({{0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}}), sq, "vertex");    // reflex
  expect_invalid(v2({{0, 0}, {1, 0}, {2, 0}}), sq, "counterclockwise");          // flat
  // A pentagram turns left at every vertex but winds twice.
  expect_invalid(v2({{0, 0}, {4, 3}, {-1, 3}, {3, 0}, {2, 5}}), sq, "counterclockwise");
}

}  // namespace
}  // namespace cvms
