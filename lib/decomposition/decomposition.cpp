// SPDX-License-Identifier: MIT
// Convex decomposition of a solid and the sums of solids built on it.
#include "cvms/decomposition.hpp"

namespace cvms {}  // namespace cvms
