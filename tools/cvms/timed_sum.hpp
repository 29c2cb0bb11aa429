// SPDX-License-Identifier: MIT
// A sum of two polyhedra with the wall time of the sum alone (sum --stats, demo).
#pragma once

#include <chrono>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/diagnostics.hpp"
#include "cvms/minkowski.hpp"

namespace cvms::cli {

struct Timed {
  MinkowskiResult result;
  SumDiagnostics diagnostics;  // what the search did, for --stats
  std::chrono::steady_clock::duration time;
  /// Making the operands' facet planes first (loading's work, see the .cpp).
  std::chrono::steady_clock::duration planes_time;
};

/// minkowski_sum(a, b, options), timed without the operands' loading work,
/// which is timed apart (planes_time).
Timed timed_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Options& options);

}  // namespace cvms::cli
