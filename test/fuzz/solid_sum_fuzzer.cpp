// SPDX-License-Identifier: MIT
// libFuzzer harness: solid_sum, polycube sums against the voxel oracle (fuzz_targets.hpp says what it checks).
#include "fuzz_entry.hpp"

CVMS_FUZZ_ENTRY(solid_sum_target)
