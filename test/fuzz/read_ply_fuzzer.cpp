// SPDX-License-Identifier: MIT
// libFuzzer harness: read_ply (ASCII or binary of either byte order) on arbitrary bytes, then round trips.
#include "fuzz_entry.hpp"

CVMS_FUZZ_ENTRY(read_ply_target)
