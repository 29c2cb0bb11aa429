// SPDX-License-Identifier: MIT
// The warm starts of the exact GJK and EPA (lib/proximity/gjk.cpp and
// epa.cpp, "Warm start"): whatever the floating-point guess, the answer is
// the exact one. The guesses are forced wrong here (random vertex pairs,
// repeated and affinely dependent pairs, no guess at all) and the answers
// checked against the brute-force oracle (test/support/proximity_oracle.hpp)
// and the whole-sum reference; then operands on which the double GJK and
// EPA themselves go wrong: coordinates beyond the double range (infinite
// approximations), below it (all zero), and ties closer than a double can
// tell (1e-30 apart).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/proximity.hpp"
#include "cvms/shapes.hpp"
#include "epa.hpp"
#include "gjk.hpp"
#include "penetration_by_sum.hpp"
#include "penetration_result.hpp"
#include "query_operands.hpp"
#include "support/hand_solids.hpp"
#include "support/oracle.hpp"
#include "support/proximity_oracle.hpp"

namespace cvms {
namespace {

using test::v3;

VertexId random_vertex(std::mt19937_64& rng, const ConvexPolyhedron& p) {
  return VertexId(static_cast<std::uint32_t>(rng() % p.num_vertices()));
}

// 1 to 4 random pairs; with some luck repeated or dependent.
detail::GjkCandidate wrong_gjk_guess(std::mt19937_64& rng, const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  detail::GjkCandidate g;
  g.size = 1 + static_cast<int>(rng() % 4);
  for (int i = 0; i < g.size; ++i) {
    g.vertex_a[i] = random_vertex(rng, a);
    g.vertex_b[i] = rng() % 4 == 0 && i > 0 ? g.vertex_b[i - 1] : random_vertex(rng, b);
  }
  if (rng() % 5 == 0 && g.size > 1) {  // a repeated pair
    g.vertex_a[1] = g.vertex_a[0];
    g.vertex_b[1] = g.vertex_b[0];
  }
  return g;
}

std::vector<detail::VertexPair> wrong_epa_guess(std::mt19937_64& rng, const ConvexPolyhedron& a,
                                                const ConvexPolyhedron& b) {
  std::vector<detail::VertexPair> g(rng() % 12);
  for (auto& [va, vb] : g) {
    va = random_vertex(rng, a);
    vb = random_vertex(rng, b);
  }
  return g;
}

// penetration() as penetration.cpp runs it, with the guesses given.
PenetrationResult penetration_with(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                                   const detail::GjkCandidate& gjk_guess,
                                   const std::vector<detail::VertexPair>& epa_guess) {
  const PlacedPolyhedron pa(a);
  const PlacedPolyhedron pb(b);
  const detail::SupportOperand sa(pa);
  const detail::SupportOperand sb(pb);
  const detail::GjkOutcome g = detail::exact_gjk_from(sa, sb, detail::GjkGoal::distance, nullptr, gjk_guess);
  PenetrationResult r = detail::penetration_from_distance(detail::distance_from(sa, g));
  if (!r.intersect) return r;
  detail::NearestFacet f = *detail::epa_nearest_facet_from(sa, sb, g, &epa_guess);
  detail::set_depth(r, std::move(f.direction), std::move(f.offset));
  r.witness_a = std::move(f.witness_a);
  r.witness_b = std::move(f.witness_b);
  return r;
}

std::string same_answer(const PenetrationResult& p, const PenetrationResult& sum) {
  if (p.intersect != sum.intersect) return "intersect differs";
  if (p.squared_depth != sum.squared_depth) return "squared_depth differs";
  if (p.direction != sum.direction) return "direction differs";
  return "";
}

TEST(ProximityWarmStart, WrongGuessesGiveTheExactAnswer) {
  std::mt19937_64 rng(1717);
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    const test::RandomPlacement r = test::random_placement(seed);
    ASSERT_EQ(r.failure, "") << "seed " << seed << ": " << r.description;
    const PlacedPolyhedron pa(r.a);
    const PlacedPolyhedron pb(r.b);
    const detail::SupportOperand sa(pa);
    const detail::SupportOperand sb(pb);
    const detail::GjkCandidate guess = wrong_gjk_guess(rng, r.a, r.b);
    const DistanceResult d =
        detail::distance_from(sa, detail::exact_gjk_from(sa, sb, detail::GjkGoal::distance, nullptr, guess));
    ASSERT_EQ(test::check_distance(r.a, r.b, d, r.oracle), "") << "seed " << seed << ": " << r.description;
    const std::vector<detail::VertexPair> none;
    for (const std::vector<detail::VertexPair>& epa_guess : {none, wrong_epa_guess(rng, r.a, r.b)}) {
      const PenetrationResult p = penetration_with(r.a, r.b, guess, epa_guess);
      ASSERT_EQ(test::check_penetration(r.a, r.b, p, r.oracle), "") << "seed " << seed << ": " << r.description;
      ASSERT_EQ(same_answer(p, detail::penetration_by_sum(r.a, r.b)), "") << "seed " << seed << ": " << r.description;
    }
  }
}

TEST(ProximityWarmStart, IntersectionGoalWithWrongGuesses) {
  std::mt19937_64 rng(1718);
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const test::RandomPlacement r = test::random_placement(seed);
    const PlacedPolyhedron pa(r.a);
    const PlacedPolyhedron pb(r.b);
    const detail::SupportOperand sa(pa);
    const detail::SupportOperand sb(pb);
    const bool hit =
        detail::exact_gjk_from(sa, sb, detail::GjkGoal::intersection, nullptr, wrong_gjk_guess(rng, r.a, r.b))
            .intersect;
    ASSERT_EQ(hit, r.oracle.inside) << "seed " << seed << ": " << r.description;
  }
}

ConvexPolyhedron box(const Rational& x0, const Rational& x1, const Rational& s) {
  return shapes::box(Vec3{x0, 0, 0}, Vec3{x1, s, s});
}

void expect_exact(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  const test::OriginAndPolytope oracle = test::proximity_oracle(a, b);
  EXPECT_EQ(test::check_distance(a, b, squared_distance(a, b), oracle), "");
  EXPECT_EQ(test::check_penetration(a, b, penetration(a, b), oracle), "");
  EXPECT_EQ(intersects(a, b), oracle.inside);
}

// 10^400 overflows a double (infinite approximations, NaN in the double
// GJK); 10^-400 underflows (every approximation 0: a degenerate guess).
TEST(ProximityWarmStart, BeyondAndBelowTheDoubleRange) {
  for (const char* scale : {"1e400", "1e-400"}) {
    SCOPED_TRACE(scale);
    const Rational s = parse_rational(scale);
    const ConvexPolyhedron a = box(0, s, s);
    const Rational gap = s / 3;
    const ConvexPolyhedron apart = box(s + gap, 2 * s + gap, s);
    EXPECT_EQ(squared_distance(a, apart).squared_distance, gap * gap);
    expect_exact(a, apart);
    const ConvexPolyhedron over = box(s - gap, 2 * s - gap, s);
    const PenetrationResult p = penetration(a, over);
    EXPECT_EQ(p.squared_depth, gap * gap);
    EXPECT_EQ(p.direction, v3(1, 0, 0));
    expect_exact(a, over);
  }
}

// Two vertices of B at distances from the cube that differ by 1e-30: the
// doubles cannot tell them apart, the exact answer can.
TEST(ProximityWarmStart, TiesCloserThanADoubleCanTell) {
  const ConvexPolyhedron cube = shapes::box(v3(0, 0, 0), v3(1, 1, 1));
  const Rational e = parse_rational("1e-30");
  for (const Rational& shift : std::vector<Rational>{2, 1, 1 - e, Rational(1, 2)}) {
    SCOPED_TRACE(to_string(shift));
    const std::vector<Vec3> points{Vec3{shift + e, Rational(1, 4), Rational(1, 4)},
                                   Vec3{shift, Rational(3, 4), Rational(1, 4)},
                                   Vec3{shift + 2 * e, Rational(1, 2), Rational(3, 4)},
                                   Vec3{shift + 3, Rational(1, 2), Rational(1, 2)}};
    const ConvexPolyhedron b = convex_hull(points);
    expect_exact(cube, b);
  }
}

// Coplanar support points: the cube's faces against a cube turned by a
// hair about z, so that many support points of A + (-B) are coplanar in
// doubles but not exactly.
TEST(ProximityWarmStart, NearlyCoplanarSupportPoints) {
  const ConvexPolyhedron cube = shapes::box(v3(-1, -1, -1), v3(1, 1, 1));
  const Rational e = parse_rational("1e-20");
  std::vector<Vec3> turned;
  for (int x : {-1, 1})
    for (int y : {-1, 1})
      for (int z : {-1, 1}) turned.push_back(Vec3{x - e * y, y + e * x, Rational(z)} + Vec3{Rational(1, 2), 0, 0});
  const ConvexPolyhedron b = convex_hull(turned);
  expect_exact(cube, b);
  expect_exact(cube, b.translated(Vec3{Rational(3, 2), Rational(1, 3), 0}));
}

// A hull of random points of the grid {0..3}^3 around a tetrahedron (so it
// is solid): small integers, so that many support points of A + (-B) are
// exactly coplanar with faces of the EPA's polytope (the exact fallback of
// its visibility test) or repeated.
ConvexPolyhedron grid_solid(std::mt19937_64& rng) {
  std::vector<Vec3> points{v3(0, 0, 0), v3(3, 0, 0), v3(0, 3, 0), v3(0, 0, 3)};
  for (std::uint64_t i = rng() % 12; i > 0; --i)
    points.push_back(v3(static_cast<int>(rng() % 4), static_cast<int>(rng() % 4), static_cast<int>(rng() % 4)));
  return convex_hull(points);
}

// Many guessed points (up to 80, far more than the double EPA's tens):
// every vertex pair once, in a random order, with repeats, on grid solids
// moved by halves, so that the operands overlap or touch along faces.
TEST(ProximityWarmStart, ManyCoplanarAndRepeatedGuessedPoints) {
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    std::mt19937_64 rng(seed);
    const ConvexPolyhedron a = grid_solid(rng);
    const auto half = [&rng] { return Rational(static_cast<int>(rng() % 7) - 3, 2); };
    const ConvexPolyhedron b = grid_solid(rng).translated(Vec3{half(), half(), half()});
    std::vector<detail::VertexPair> guess;
    for (std::uint32_t i = 0; i < a.num_vertices(); ++i)
      for (std::uint32_t j = 0; j < b.num_vertices(); ++j) guess.emplace_back(VertexId(i), VertexId(j));
    std::shuffle(guess.begin(), guess.end(), rng);
    guess.resize(std::min<std::size_t>(guess.size(), 60));
    for (std::uint64_t i = rng() % 20; i > 0 && !guess.empty(); --i) guess.push_back(guess[rng() % guess.size()]);
    const test::OriginAndPolytope oracle = test::proximity_oracle(a, b);
    if (!oracle.inside) continue;
    const PenetrationResult p = penetration_with(a, b, detail::GjkCandidate{}, guess);
    ASSERT_EQ(test::check_penetration(a, b, p, oracle), "") << "seed " << seed;
    ASSERT_EQ(same_answer(p, detail::penetration_by_sum(a, b)), "") << "seed " << seed;
  }
}

}  // namespace
}  // namespace cvms
