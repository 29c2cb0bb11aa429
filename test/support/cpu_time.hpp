// SPDX-License-Identifier: MIT
// The clock of the tests' time bounds (hostile input must end quickly):
// process CPU time, all threads. A bound on it says the work is small; wall
// time would also count the other jobs of a loaded machine (a parallel
// ctest, a build beside it), which made such bounds fail on honest runs.
#pragma once

#include <ctime>

namespace cvms::test {

/// CPU seconds used by this process so far (differences are what matter).
inline double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace cvms::test
