// SPDX-License-Identifier: MIT
/// \file
/// qhull's half-space intersection (qhalf) as a benchmark peer (bench only;
/// never linked into the library). Plain doubles in, counts out, so the
/// benchmark sources never see qhull's headers.
#pragma once

#include <array>
#include <cstddef>
#include <span>

namespace cvms_bench {

/// What qhull reports for one intersection.
struct QhalfResult {
  std::size_t vertices = 0;  ///< vertices of the intersection (qhull's dual facets)
  std::size_t rows = 0;      ///< irredundant half-spaces (qhull's dual vertices)
};

/// The intersection of the half-spaces a·x + c <= 0, given as a0 a1 a2 c per
/// row, about the strictly interior point `interior`: the reentrant qhull
/// library with options "qhull H<interior>" (qhalf's defaults: floating
/// point, not exact). Returns zero vertices if qhull reports an error.
QhalfResult qhull_halfspaces(std::span<const double> rows, const std::array<double, 3>& interior);

}  // namespace cvms_bench
