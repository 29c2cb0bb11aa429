// SPDX-License-Identifier: MIT
// libFuzzer harness: read_solid, OFF text validated as a solid, on arbitrary bytes (fuzz_targets.hpp says what it checks).
#include "fuzz_entry.hpp"

CVMS_FUZZ_ENTRY(read_solid_target)
