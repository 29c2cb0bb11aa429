// SPDX-License-Identifier: MIT
// minkowski_sum: checks its operands, dispatches to the chosen algorithm and
// measures the predicate counters around it, hands out Stats and the
// diagnostics; the algorithms' names.
#include "cvms/minkowski.hpp"

#include "chms.hpp"
#include "cvms_algorithm.hpp"
#include "cvms/error.hpp"
#include "filtered_predicates.hpp"
#include "essdms.hpp"

namespace cvms {

const char* to_string(Algorithm algorithm) noexcept {
  switch (algorithm) {
    case Algorithm::cvms:
      return "cvms";
    case Algorithm::essdms:
      return "essdms";
    case Algorithm::chms:
      return "chms";
  }
  return "unknown";
}

MinkowskiResult minkowski_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Options& options) {
  return detail::minkowski_sum(a, b, options, {});
}

MinkowskiResult detail::minkowski_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Options& options,
                                      const ResearchOptions& research) {
  if (a.num_facets() == 0 || b.num_facets() == 0) {
    throw Error(ErrorCategory::invalid_argument, std::string("minkowski_sum: operand ") +
                                                     (a.num_facets() == 0 ? "A" : "B") +
                                                     " is an empty (default-constructed) polyhedron");
  }
  // The counters are per thread, so the difference is this call's share.
  const PredicateCounters before = predicate_counters();
  MinkowskiResult result;
  SumCounters counters;
  switch (options.algorithm) {
    case Algorithm::cvms:
      result.polyhedron = cvms_sum(a, b, options, research, counters);
      break;
    case Algorithm::chms:
      result.polyhedron = detail::chms(a, b, options.limits, options.progress);
      break;
    case Algorithm::essdms:
      result.polyhedron = essdms_sum(a, b, options.limits, counters, options.progress);
      break;
    default:
      throw Error(ErrorCategory::invalid_argument,
                  "minkowski_sum: unknown algorithm " + std::to_string(static_cast<int>(options.algorithm)));
  }
  const PredicateCounters& after = predicate_counters();
  counters.predicate_filtered = after.filtered - before.filtered;
  counters.predicate_exact = after.exact - before.exact;
  result.stats = counters.stats();
  if (options.diagnostics != nullptr) *options.diagnostics = counters;
  return result;
}

}  // namespace cvms
