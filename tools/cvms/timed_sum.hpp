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
};

/// minkowski_sum(a, b, options), timed without the operands' loading work.
Timed timed_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Options& options);

}  // namespace cvms::cli
