// SPDX-License-Identifier: MIT
// convex_hull_set: the hull in the dimension the points span.
//
// The dimension comes from the first point, the first point different from
// it, the first point off their line and the first point off their plane
// (one predicate per point and stage). Collinear points: the two extremes
// along the line. Coplanar points: Andrew's monotone chain in the plane's
// chart (plane_chart.hpp, an exact affine bijection), with orient2d; the
// chain keeps only strict left turns, so the cycle has no collinear or
// repeated vertices. Otherwise the 3D quickhull.
#include <algorithm>
#include <cmath>
#include <string>
#include <cstdint>
#include <numeric>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "affine_dimension.hpp"
#include "cvms/predicates.hpp"
#include "plane_chart.hpp"

namespace cvms {

namespace {

constexpr std::size_t none = static_cast<std::size_t>(-1);

template <class Test>
std::size_t first_where(std::span<const Vec3> points, Test test) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (test(points[i])) return i;
  return none;
}

ConvexSet collinear_hull(std::span<const Vec3> points, const Vec3& direction) {
  std::size_t lo = 0, hi = 0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (compare_dot(points[i], points[lo], direction) == Sign::negative) lo = i;
    if (compare_dot(points[i], points[hi], direction) == Sign::positive) hi = i;
  }
  return ConvexSet::segment(points[lo], points[hi]);
}

// One monotone chain over the sorted indices; `chain` holds the hull so far.
void extend_chain(std::vector<std::size_t>& chain, std::size_t floor, std::size_t i,
                  const std::vector<Vec2>& flat) {
  while (chain.size() >= floor + 2 &&
         orient2d(flat[chain[chain.size() - 2]], flat[chain.back()], flat[i]) != Sign::positive)
    chain.pop_back();
  chain.push_back(i);
}

ConvexSet coplanar_hull(std::span<const Vec3> points, const Vec3& normal) {
  const detail::PlaneChart chart(normal);
  std::vector<Vec2> flat;
  flat.reserve(points.size());
  for (const Vec3& p : points) flat.push_back(chart(p));
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return flat[a] < flat[b]; });
  std::vector<std::size_t> chain;
  for (std::size_t i : order) extend_chain(chain, 0, i, flat);  // lower chain, left to right
  const std::size_t lower = chain.size() - 1;
  for (auto it = order.rbegin() + 1; it != order.rend(); ++it) extend_chain(chain, lower, *it, flat);
  chain.pop_back();  // the first point again
  std::vector<Vec3> cycle;
  cycle.reserve(chain.size());
  for (std::size_t i : chain) cycle.push_back(points[i]);
  return ConvexSet::polygon(cycle);
}

}  // namespace

detail::AffineSpan detail::affine_span(std::span<const Vec3> points) {
  AffineSpan span;
  if (points.empty()) return span;
  std::array<std::size_t, 4>& w = span.witness;
  span.dimension = 0;
  w[0] = 0;
  const Vec3& p0 = points[0];
  w[1] = first_where(points, [&](const Vec3& p) { return p != p0; });
  if (w[1] == none) return span;
  span.dimension = 1;
  const Vec3 d = points[w[1]] - p0;
  w[2] = first_where(points, [&](const Vec3& p) { return !is_parallel(p - p0, d); });
  if (w[2] == none) return span;
  span.dimension = 2;
  const Vec3& p1 = points[w[1]];
  const Vec3& p2 = points[w[2]];
  w[3] = first_where(points, [&](const Vec3& p) { return orient3d(p0, p1, p2, p) != Sign::zero; });
  if (w[3] != none) span.dimension = 3;
  return span;
}

ConvexSet convex_hull_set(std::span<const Vec3> points) {
  return convex_hull_set(points, ProgressCallback());
}

ConvexSet convex_hull_set(std::span<const Vec3> points, const ProgressCallback& progress) {
  const detail::AffineSpan span = detail::affine_span(points);
  const auto& w = span.witness;
  switch (span.dimension) {
    case -1:
      return {};
    case 0:
      return ConvexSet::point(points[0]);
    case 1:
      return collinear_hull(points, points[w[1]] - points[0]);
    case 2:
      return coplanar_hull(points, cross(points[w[1]] - points[0], points[w[2]] - points[0]));
    default:
      return ConvexSet(convex_hull(points, progress));
  }
}

ConvexSet convex_hull_set(std::span<const std::array<double, 3>> points) {
  std::vector<Vec3> exact;
  exact.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(points[i][k]))
        throw Error(ErrorCategory::invalid_argument, "convex hull: point " + std::to_string(i) + " has a " +
                                                         (std::isnan(points[i][k]) ? "NaN" : "infinite") +
                                                         " coordinate " + std::string(1, "xyz"[k]));
    exact.push_back({Rational(points[i][0]), Rational(points[i][1]), Rational(points[i][2])});
  }
  return convex_hull_set(exact);
}

}  // namespace cvms
