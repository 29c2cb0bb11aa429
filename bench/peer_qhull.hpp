// SPDX-License-Identifier: MIT
/// \file
/// qhull as a benchmark peer (bench only; never linked into the library).
/// Neutral interface: plain doubles in, counts out, so the benchmark sources
/// never see qhull's headers.
#pragma once

#include <cstddef>
#include <span>

namespace cvms_bench {

/// What qhull reports for one hull.
struct QhullHull {
  std::size_t facets = 0;    ///< qhull's facets after its default merging of coplanar facets
  std::size_t vertices = 0;  ///< hull vertices
  /// qhull's own peak heap use for this run (it allocates with malloc, which
  /// the benchmarks' heap counter does not see): its peak of long memory plus
  /// its short-memory buffers, as kept by qhull's memory statistics.
  std::size_t peak_bytes = 0;
};

/// The 3D convex hull of `xyz` (x0 y0 z0 x1 y1 z1 ...), computed by the
/// reentrant qhull library with its default options for a hull ("qhull";
/// in 3D that merges coplanar facets, floating point, not exact).
/// Returns zero facets if qhull reports an error (e.g. a flat input).
QhullHull qhull_hull(std::span<const double> xyz);

}  // namespace cvms_bench
