// SPDX-License-Identifier: MIT
// See timed_sum.hpp.
#include "timed_sum.hpp"

#include <utility>

namespace cvms::cli {

// A loaded polyhedron makes its facet planes when they are first read
// (ConvexPolyhedron::normal), which is loading's work, so they are made
// before the clock starts, as an in-process caller's operands have them
// after their first use.
Timed timed_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Options& options) {
  const auto planes_start = std::chrono::steady_clock::now();
  for (const ConvexPolyhedron* p : {&a, &b})
    if (p->num_facets() > 0) (void)p->normal(FaceId(0));
  SumDiagnostics diagnostics;
  Options counted = options;
  counted.diagnostics = &diagnostics;
  auto start = std::chrono::steady_clock::now();
  MinkowskiResult result = minkowski_sum(a, b, counted);
  return {std::move(result), diagnostics, std::chrono::steady_clock::now() - start, start - planes_start};
}

}  // namespace cvms::cli
