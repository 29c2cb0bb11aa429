// SPDX-License-Identifier: MIT
// Planar Minkowski sum of two convex polygons by convolution (used by CVMS,
// paper Section 4, for the facet+facet and facet+edge sums).
//
// Both operands are walked counterclockwise from their lowest (min y, then
// min x) vertex. From there the edge directions of a convex polygon increase
// strictly in angle over [0, 2pi); the sum's edges are the two sequences
// merged by angle, with equal directions taken together (so parallel edges
// merge and no collinear vertex appears). A segment is the degenerate polygon
// with the two edges d and -d; a point has no edges. Angles are never
// computed: two directions are ordered by their half-turn ([0, pi) or
// [pi, 2pi), read off the exact signs of their components) and, within one
// half-turn, by sign_cross2.
#include "cvms/planar_sum.hpp"

#include <cstddef>
#include <limits>
#include <string>

#include "angular_order.hpp"
#include "cvms/error.hpp"
#include "filtered_predicates.hpp"

namespace cvms {
namespace {

// Sign of angle(a) - angle(b) with angles taken in [0, 2pi) from the x
// axis; a, b nonzero. Against the x axis, the signs of cross(r, d) and
// <r, d> are those of d.y and d.x (lib/predicates/angular_order.hpp).
Sign compare_angle(Vec2Ref a, Vec2Ref b) {
  auto half_turn = [](const Vec2& d) {
    return detail::half_turn(sign_of(sgn(d.y)), [&d] { return sign_of(sgn(d.x)); });
  };
  return detail::compare_angle(half_turn(a.exact), half_turn(b.exact), [&] { return sign_cross2(a, b); });
}

// One operand prepared for the merge: its lowest vertex and its edge vectors
// in counterclockwise order starting there, with their approximations
// computed once for the predicate filters.
struct Walk {
  std::uint32_t start = 0;
  std::vector<Vec2> edges;
  std::vector<ApproxVec2> approx;
  [[nodiscard]] Vec2Ref edge(std::size_t k) const { return {edges[k], approx[k]}; }
};

[[noreturn]] void fail(const char* operand, const std::string& what) {
  throw Error(ErrorCategory::invalid_argument, std::string("planar_sum: operand ") + operand + ": " + what);
}

// Finds the lowest vertex and the edge vectors, and checks the precondition
// where it costs nothing extra: edges nonzero and strictly increasing in angle
// over one turn. Together with closure (automatic: the edges are vertex
// differences) this is exactly "strictly convex and counterclockwise".
Walk prepare(std::span<const Vec2> poly, const char* operand) {
  if (poly.empty()) fail(operand, "empty");
  if (poly.size() > std::numeric_limits<std::uint32_t>::max()) fail(operand, "more than 2^32 - 1 vertices");
  const auto n = static_cast<std::uint32_t>(poly.size());
  Walk walk;
  for (std::uint32_t i = 1; i < n; ++i) {
    int c = cmp(poly[i].y, poly[walk.start].y);
    if (c < 0 || (c == 0 && poly[i].x < poly[walk.start].x)) walk.start = i;
  }
  if (n == 1) return walk;
  walk.edges.reserve(n);
  for (std::uint32_t k = 0; k < n; ++k) {
    std::uint32_t i = (walk.start + k) % n;
    std::uint32_t j = (i + 1) % n;
    walk.edges.push_back(poly[j] - poly[i]);
    if (sgn(walk.edges.back().x) == 0 && sgn(walk.edges.back().y) == 0)
      fail(operand, "vertices " + std::to_string(i) + " and " + std::to_string(j) + " coincide");
  }
  walk.approx.reserve(n);
  for (const Vec2& e : walk.edges) walk.approx.push_back(ApproxVec2::of(e));
  // A segment's two edges d, -d are ordered automatically (d starts at the
  // lowest point, so it lies in [0, pi)); only polygons need the check.
  if (n >= 3) {
    for (std::uint32_t k = 0; k + 1 < n; ++k) {
      if (compare_angle(walk.edge(k), walk.edge(k + 1)) != Sign::negative) {
        std::uint32_t v = (walk.start + k + 1) % n;
        fail(operand, "not strictly convex and counterclockwise at vertex " + std::to_string(v));
      }
    }
  }
  return walk;
}

}  // namespace

std::vector<IndexPair> planar_sum_indices(std::span<const Vec2> p, std::span<const Vec2> q) {
  const Walk wp = prepare(p, "p");
  const Walk wq = prepare(q, "q");
  const auto np = static_cast<std::uint32_t>(p.size());
  const auto nq = static_cast<std::uint32_t>(q.size());
  const std::size_t ep = wp.edges.size();
  const std::size_t eq = wq.edges.size();

  std::vector<IndexPair> out;
  out.reserve(ep + eq + 1);
  std::uint32_t i = wp.start;
  std::uint32_t j = wq.start;
  out.emplace_back(i, j);
  std::size_t a = 0;  // next edge of p
  std::size_t b = 0;  // next edge of q
  while (a < ep || b < eq) {
    Sign order = Sign::zero;
    if (a == ep)
      order = Sign::positive;  // only q's edges left
    else if (b == eq)
      order = Sign::negative;  // only p's edges left
    else
      order = compare_angle(wp.edge(a), wq.edge(b));
    if (order != Sign::positive) {
      i = (i + 1) % np;
      ++a;
    }
    if (order != Sign::negative) {
      j = (j + 1) % nq;
      ++b;
    }
    if (a == ep && b == eq) break;  // back at the start
    out.emplace_back(i, j);
  }
  return out;
}

std::vector<Vec2> planar_sum(std::span<const Vec2> p, std::span<const Vec2> q) {
  std::vector<IndexPair> pairs = planar_sum_indices(p, q);
  std::vector<Vec2> out;
  out.reserve(pairs.size());
  for (const IndexPair& pair : pairs) out.push_back(p[pair.first] + q[pair.second]);
  return out;
}

}  // namespace cvms
