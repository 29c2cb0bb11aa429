// SPDX-License-Identifier: MIT
// CHMS, the convex-hull-based Minkowski sum (paper Section 6.2): the exact
// hull of all pairwise vertex sums. Slow but simple, it is the reference
// oracle for the other algorithms.
//
// The hull sees each sum through its double approximation (the rounded sum
// of the operands' cached approximations); the exact sum is only formed for
// the hull's vertices and the predicates the filters cannot decide, instead
// of for all |V_A| |V_B| sums.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "chms.hpp"
#include "cvms/error.hpp"
#include "cvms/minkowski.hpp"
#include "filtered_arithmetic.hpp"
#include "hull_soup.hpp"
#include "polyhedron_builder.hpp"

namespace cvms {
namespace {

// Both checked before allocating: the hull indexes points with 32 bits, and
// each pairwise sum costs about SumLimits::bytes_per_pairwise_sum (its
// double approximation, 24 bytes, and its entries in the conflict lists,
// 32 bytes each, in the pool and its compacted copy).
void check_pair_count(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const SumLimits& limits) {
  const std::uint64_t count = std::uint64_t{a.num_vertices()} * b.num_vertices();
  const std::string pairs =
      "chms: " + std::to_string(a.num_vertices()) + " x " + std::to_string(b.num_vertices()) + " pairwise vertex sums";
  if (count >= 0xffffffffu) throw Error(ErrorCategory::limit, pairs + " exceed the limit of 2^32 - 2 points");
  if (count > limits.max_memory_bytes / SumLimits::bytes_per_pairwise_sum)
    throw Error(ErrorCategory::limit, pairs + " need about " +
                                          std::to_string(count * SumLimits::bytes_per_pairwise_sum) + " bytes (" +
                                          std::to_string(SumLimits::bytes_per_pairwise_sum) +
                                          " per sum), beyond the limit of " + std::to_string(limits.max_memory_bytes) +
                                          " bytes (SumLimits::max_memory_bytes)");
}

}  // namespace

ConvexPolyhedron chms(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const SumLimits& limits) {
  return detail::chms(a, b, limits, {});
}

ConvexPolyhedron detail::chms(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const SumLimits& limits,
                              const ProgressCallback& progress) {
  check_pair_count(a, b, limits);
  const std::uint64_t count = std::uint64_t{a.num_vertices()} * b.num_vertices();
  const std::uint32_t nb = b.num_vertices();
  std::vector<std::array<double, 3>> approx;
  approx.reserve(count);
  // Each sum is the filtered sum of the operands' approximations, with its
  // bound (error_bounds.hpp, "The filtered sum"). NaN errors become infinite
  // (no filtering).
  double max_error = 0;
  for (std::uint32_t i = 0; i < a.num_vertices(); ++i) {
    const ApproxVec3& p = detail::vertex_approx(a, VertexId(i));
    for (std::uint32_t j = 0; j < nb; ++j) {
      const ApproxVec3& q = detail::vertex_approx(b, VertexId(j));
      const Approx s[3] = {filtered::add(p.x, q.x), filtered::add(p.y, q.y), filtered::add(p.z, q.z)};
      for (const Approx& c : s)
        max_error = c.error <= max_error ? max_error : (std::isnan(c.error) ? INFINITY : c.error);
      approx.push_back({s[0].value, s[1].value, s[2].value});
    }
  }
  const ApproximatePoints sums{approx, max_error, [&](std::uint32_t k) {
                                 return a.vertex(VertexId(k / nb)) + b.vertex(VertexId(k % nb));
                               }};
  // The soup already has maximal convex facets and only extreme vertices.
  detail::ProgressReporter reporter(detail::callback_of(progress));
  return detail::trusted_polyhedron(hull_soup(sums, nullptr, &reporter));
}

}  // namespace cvms
