// SPDX-License-Identifier: MIT
// libFuzzer harness: intersect_halfspaces, to_halfspaces and
// pontryagin_difference on small decoded systems (redundant, opposed,
// scaled, zero and nearly degenerate rows) against brute-force oracles.
#include "fuzz_entry.hpp"

CVMS_FUZZ_ENTRY(halfspaces_target)
