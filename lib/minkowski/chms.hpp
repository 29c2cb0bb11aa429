// SPDX-License-Identifier: MIT
// Private entry point of CHMS (paper Section 6.2) for minkowski_sum, with the
// progress callback of its Options (the public cvms::chms takes none).
#pragma once

#include "cvms/minkowski.hpp"

namespace cvms::detail {

/// cvms::chms(a, b, limits), reporting its hull's stage "hull" to
/// `progress` (cvms/progress.hpp). \throw Error(cancelled) if it asks to stop.
ConvexPolyhedron chms(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const SumLimits& limits,
                      const ProgressCallback& progress);

}  // namespace cvms::detail
