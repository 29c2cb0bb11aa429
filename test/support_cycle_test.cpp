// SPDX-License-Identifier: MIT
// The support operand's climb along a polygon's vertex cycle
// (lib/proximity/support_operand.hpp; pontryagin_difference's h_B of a
// polygon, segment or point, warm-started at the last answer) against a scan: max over all vertices of <v, u> in plain
// Rational arithmetic. Directions include the ties the climb must get
// through: u orthogonal to an edge at the top and at the bottom, u
// orthogonal to the plane (every vertex ties). Seeded; the seed
// is printed on failure.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "cvms/convex_set.hpp"
#include "cvms/shapes.hpp"
#include "filtered_predicates.hpp"
#include "support_operand.hpp"
#include "support/oracle.hpp"
#include "support/random_sets.hpp"

namespace cvms {
namespace {

using Rng = std::mt19937_64;

Rational scan_maximum(const std::vector<Vec3>& vertices, const Vec3& u) {
  Rational best = dot(vertices.front(), u);
  for (const Vec3& v : vertices) best = std::max(best, dot(v, u));
  return best;
}

// Directions for a set: random grid vectors and, for a polygon, each edge's
// in-plane normal both ways (the top or the bottom of <x, u> is that edge),
// tilted out of the plane by a random multiple of the plane normal.
std::vector<Vec3> directions(Rng& rng, const ConvexSet& s) {
  std::uniform_int_distribution<int> small(-3, 3);
  std::vector<Vec3> out;
  while (out.size() < 8) {
    Vec3 u{small(rng), small(rng), small(rng)};
    if (!is_zero(u)) out.push_back(std::move(u));
  }
  if (s.dimension() != 2) return out;
  out.push_back(s.normal());
  for (const Vec3& e : s.edge_normals()) {
    const Vec3 tilt = Rational(small(rng)) * s.normal();
    out.push_back(e + tilt);
    out.push_back(tilt - e);
  }
  std::shuffle(out.begin(), out.end(), rng);
  return out;
}

// Queries in a row, each climb starting at the previous answer, as
// pontryagin_difference asks them.
class WarmClimb {
 public:
  explicit WarmClimb(const ConvexSet& s) : operand_(s) {}
  std::size_t maximiser(const Vec3& u) {
    const ApproxVec3 approx = ApproxVec3::of(u);
    last_ = operand_.support(Vec3Ref{u, approx}, Sign::positive, last_);
    return last_.index();
  }

 private:
  detail::SupportOperand operand_;
  VertexId last_ = VertexId(0);
};

TEST(CycleSupport, RandomSetsMatchTheScanWithTies) {
  for (std::uint64_t seed = 0; seed < 600; ++seed) {
    Rng rng(seed);
    const int dim = seed % 4 == 3 ? 2 : static_cast<int>(seed % 4);  // polygons half the time
    const ConvexSet s = test::random_set(rng, dim, Vec3{Rational(1, 3), 2, -1}, 3, 12);
    const std::vector<Vec3> vertices = s.vertices();
    WarmClimb climb(s);
    for (const Vec3& u : directions(rng, s)) {
      const std::size_t i = climb.maximiser(u);
      ASSERT_LT(i, vertices.size()) << "seed " << seed;
      EXPECT_EQ(dot(vertices[i], u), scan_maximum(vertices, u)) << "seed " << seed << ", u " << test::to_text(u);
    }
  }
}

// A 2,000-gon in the tilted plane z = x + 2y (no coordinate plane helps).
std::vector<Vec3> tilted_circle(int n) {
  std::vector<Vec3> cycle;
  for (const Vec2& p : shapes::circle_polygon(n)) cycle.push_back(Vec3{p.x, p.y, p.x + Rational(2) * p.y});
  return cycle;
}

TEST(CycleSupport, SweepingTheEdgeNormalsInOrderIsOutputSensitive) {
  const ConvexSet s = ConvexSet::polygon(tilted_circle(2000));
  const std::vector<Vec3> vertices = s.vertices();
  const std::vector<Vec3> normals = s.edge_normals();
  WarmClimb climb(s);
  const std::uint64_t before = predicate_counters().filtered + predicate_counters().exact;
  for (std::size_t k = 0; k < normals.size(); ++k) {
    const std::size_t i = climb.maximiser(normals[k]);
    // The scan on every 40th direction only: the whole sweep would cost n^2.
    if (k % 40 == 0) {
      EXPECT_EQ(dot(vertices[i], normals[k]), scan_maximum(vertices, normals[k])) << k;
    }
  }
  // About one turn around the cycle: a comparison or two per step and per
  // query (a scan per direction would be n^2 = 4,000,000 comparisons).
  const std::uint64_t comparisons = predicate_counters().filtered + predicate_counters().exact - before;
  EXPECT_LE(comparisons, 8 * vertices.size());
}

TEST(CycleSupport, RandomOrderOnABigPolygonStillMatches) {
  const ConvexSet s = ConvexSet::polygon(tilted_circle(500));
  const std::vector<Vec3> vertices = s.vertices();
  Rng rng(7);
  WarmClimb climb(s);
  for (const Vec3& u : directions(rng, s)) {
    EXPECT_EQ(dot(vertices[climb.maximiser(u)], u), scan_maximum(vertices, u)) << test::to_text(u);
  }
}

}  // namespace
}  // namespace cvms
