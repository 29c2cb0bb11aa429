// SPDX-License-Identifier: MIT
// libFuzzer harness: read_points (OFF, OBJ or x y z lines) on arbitrary bytes.
#include "fuzz_entry.hpp"

CVMS_FUZZ_ENTRY(read_points_target)
