// SPDX-License-Identifier: MIT
// libFuzzer harness: minkowski_sum of two small convex sets of every
// dimension, with every algorithm, against the hull of the pairwise vertex
// sums.
#include "fuzz_entry.hpp"

CVMS_FUZZ_ENTRY(sets_target)
