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
//
// Operands whose coordinates share a small common denominator (short
// decimals, most dyadic inputs) are first scaled to machine integers
// (small_points.hpp) and merged in 64/128-bit arithmetic; the scaling keeps
// every decision, so both paths give the same pairs and the same errors.
#include "cvms/planar_sum.hpp"

#include <cstddef>
#include <limits>
#include <span>
#include <string>

#include "angular_order.hpp"
#include "cvms/error.hpp"
#include "filtered_predicates.hpp"
#include "small_points.hpp"

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

__extension__ using Int128 = __int128;

template <class Number>
Sign sign_of_number(Number x) noexcept {
  return x < 0 ? Sign::negative : (x > 0 ? Sign::positive : Sign::zero);
}

// compare_angle for edges of scaled points: |coordinates| < 2^63, so each
// product of the cross product is below 2^126 and their difference fits.
Sign compare_angle(const detail::SmallPoint2& a, const detail::SmallPoint2& b) {
  auto half_turn = [](const detail::SmallPoint2& d) {
    return detail::half_turn(sign_of_number(d.y), [&d] { return sign_of_number(d.x); });
  };
  return detail::compare_angle(half_turn(a), half_turn(b), [&] {
    return sign_of_number(static_cast<Int128>(a.x) * b.y - static_cast<Int128>(a.y) * b.x);
  });
}

bool is_lower(const Vec2& a, const Vec2& b) {
  const int c = cmp(a.y, b.y);
  return c < 0 || (c == 0 && a.x < b.x);
}

bool is_lower(const detail::SmallPoint2& a, const detail::SmallPoint2& b) {
  return a.y < b.y || (a.y == b.y && a.x < b.x);
}

// Edge vectors as exact rationals, with their approximations computed once
// for the predicate filters.
struct ExactEdges {
  std::vector<Vec2> exact;
  std::vector<ApproxVec2> approx;
  void reserve(std::size_t n) { exact.reserve(n); }
  // false if the edge is zero
  bool push(const Vec2& from, const Vec2& to) {
    exact.push_back(to - from);
    return sgn(exact.back().x) != 0 || sgn(exact.back().y) != 0;
  }
  void finish() {
    approx.reserve(exact.size());
    for (const Vec2& e : exact) approx.push_back(ApproxVec2::of(e));
  }
  [[nodiscard]] std::size_t size() const { return exact.size(); }
  [[nodiscard]] Sign compare(std::size_t k, const ExactEdges& other, std::size_t l) const {
    return compare_angle(Vec2Ref{exact[k], approx[k]}, Vec2Ref{other.exact[l], other.approx[l]});
  }
};

// Edge vectors of scaled points (|coordinates| < 2^62, so no difference
// overflows).
struct SmallEdges {
  std::vector<detail::SmallPoint2> vectors;
  void reserve(std::size_t n) { vectors.reserve(n); }
  bool push(const detail::SmallPoint2& from, const detail::SmallPoint2& to) {
    vectors.push_back({to.x - from.x, to.y - from.y});
    return vectors.back().x != 0 || vectors.back().y != 0;
  }
  void finish() {}
  [[nodiscard]] std::size_t size() const { return vectors.size(); }
  [[nodiscard]] Sign compare(std::size_t k, const SmallEdges& other, std::size_t l) const {
    return compare_angle(vectors[k], other.vectors[l]);
  }
};

template <class Point>
struct EdgesOf;
template <>
struct EdgesOf<Vec2> {
  using type = ExactEdges;
};
template <>
struct EdgesOf<detail::SmallPoint2> {
  using type = SmallEdges;
};

// One operand prepared for the merge: its lowest vertex and its edge vectors
// in counterclockwise order starting there.
template <class Point>
struct Walk {
  std::uint32_t start = 0;
  typename EdgesOf<Point>::type edges;
};

[[noreturn]] void fail(const char* operand, const std::string& what) {
  throw Error(ErrorCategory::invalid_argument, std::string("planar_sum: operand ") + operand + ": " + what);
}

// Finds the lowest vertex and the edge vectors, and checks the precondition
// where it costs nothing extra: edges nonzero and strictly increasing in angle
// over one turn. Together with closure (automatic: the edges are vertex
// differences) this is exactly "strictly convex and counterclockwise".
template <class Point>
Walk<Point> prepare(std::span<const Point> poly, const char* operand) {
  if (poly.empty()) fail(operand, "empty");
  if (poly.size() > std::numeric_limits<std::uint32_t>::max()) fail(operand, "more than 2^32 - 1 vertices");
  const auto n = static_cast<std::uint32_t>(poly.size());
  Walk<Point> walk;
  for (std::uint32_t i = 1; i < n; ++i) {
    if (is_lower(poly[i], poly[walk.start])) walk.start = i;
  }
  if (n == 1) return walk;
  walk.edges.reserve(n);
  for (std::uint32_t k = 0; k < n; ++k) {
    std::uint32_t i = (walk.start + k) % n;
    std::uint32_t j = (i + 1) % n;
    if (!walk.edges.push(poly[i], poly[j]))
      fail(operand, "vertices " + std::to_string(i) + " and " + std::to_string(j) + " coincide");
  }
  walk.edges.finish();
  // A segment's two edges d, -d are ordered automatically (d starts at the
  // lowest point, so it lies in [0, pi)); only polygons need the check.
  if (n >= 3) {
    for (std::uint32_t k = 0; k + 1 < n; ++k) {
      if (walk.edges.compare(k, walk.edges, k + 1) != Sign::negative) {
        std::uint32_t v = (walk.start + k + 1) % n;
        fail(operand, "not strictly convex and counterclockwise at vertex " + std::to_string(v));
      }
    }
  }
  return walk;
}

template <class Point>
std::vector<IndexPair> merge(std::span<const Point> p, std::span<const Point> q) {
  const Walk<Point> wp = prepare(p, "p");
  const Walk<Point> wq = prepare(q, "q");
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
      order = wp.edges.compare(a, wq.edges, b);
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

}  // namespace

std::vector<IndexPair> planar_sum_indices(std::span<const Vec2> p, std::span<const Vec2> q) {
  std::vector<detail::SmallPoint2> sp;
  std::vector<detail::SmallPoint2> sq;
  if (detail::scale_to_small_points(p, q, sp, sq))
    return merge(std::span<const detail::SmallPoint2>(sp), std::span<const detail::SmallPoint2>(sq));
  return merge(p, q);
}

std::vector<Vec2> planar_sum(std::span<const Vec2> p, std::span<const Vec2> q) {
  std::vector<IndexPair> pairs = planar_sum_indices(p, q);
  std::vector<Vec2> out;
  out.reserve(pairs.size());
  for (const IndexPair& pair : pairs) out.push_back(p[pair.first] + q[pair.second]);
  return out;
}

}  // namespace cvms
