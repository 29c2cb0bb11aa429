// SPDX-License-Identifier: MIT
// See face_sums.hpp. The polygons are shared out over the threads as the
// pairs of a sum of two unions are (ordered_work.hpp): each outcome in its
// own slot, the first failure or the first prefix beyond the budget in
// polygon order reported, so the result and the error do not depend on the
// thread count.
#include "face_sums.hpp"

#include <cstdint>
#include <exception>
#include <string>
#include <utility>

#include "cvms/convex_set.hpp"
#include "cvms/error.hpp"
#include "facet_budget.hpp"
#include "ordered_work.hpp"
#include "output_budget.hpp"
#include "progress_reporter.hpp"
#include "set_sum_parts.hpp"

namespace cvms::detail {
namespace {

// Facets every convex polyhedron has at least.
constexpr std::uint64_t min_piece_facets = 4;

[[noreturn]] void beyond_budget(const std::string& what, const SumLimits& limits) {
  throw Error(ErrorCategory::limit,
              "minkowski_sum of solids: " + what + ", beyond the limit of " + facet_limit_text(limits));
}

[[noreturn]] void rethrow_named(std::size_t k, const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const Error& e) {
    if (e.category() == ErrorCategory::cancelled) throw;
    throw Error(e.category(),
                "minkowski_sum of solids: face polygon " + std::to_string(k) + " + B: " + e.message());
  }
}

}  // namespace

std::vector<ConvexPolyhedron> face_sums(std::span<const std::vector<Vec3>> polygons,
                                        const ConvexPolyhedron& b, const Options& options) {
  const std::uint64_t budget = facet_budget(options.limits);
  if (polygons.size() > budget / min_piece_facets)
    beyond_budget(std::to_string(polygons.size()) + " face polygons of A summed with B would have at least " +
                      std::to_string(min_piece_facets) + " facets each",
                  options.limits);
  ProgressReporter progress(callback_of(options.progress));
  progress.begin("solid sum: faces", polygons.size());
  // Each sum is minkowski_sum(polygon, B) with only the limits, taken
  // straight from the sets layer's polygon + polyhedron, which reports no
  // progress, runs on its calling thread and hands over the polyhedron (a
  // ConvexSet's would be copied, B converted to one copied too).
  const OutputBudget sum_budget(options.limits, "sets");
  OrderedWork<ConvexPolyhedron> work(polygons.size(), budget);
  work.run(options.threads, [&](std::size_t k) {
    ConvexPolyhedron sum =
        polygon_polyhedron_sum(ConvexSet::polygon(polygons[k]), b, sum_budget, "polygon + polyhedron");
    progress.advance(1);
    const std::uint64_t facets = sum.num_facets();
    return std::pair{std::move(sum), facets};
  });
  std::vector<ConvexPolyhedron> sums = work.take(rethrow_named, [&](std::size_t k, std::uint64_t facets) {
    beyond_budget("the sums of B with A's face polygons up to " + std::to_string(k) + " have " +
                      std::to_string(facets) + " facets in all",
                  options.limits);
  });
  progress.end();
  return sums;
}

}  // namespace cvms::detail
