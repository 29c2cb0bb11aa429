// SPDX-License-Identifier: MIT
// libFuzzer harness: read_off on arbitrary bytes, then a write_off/read_off round trip.
#include "fuzz_entry.hpp"

CVMS_FUZZ_ENTRY(read_off_target)
