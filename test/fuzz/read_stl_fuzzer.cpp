// SPDX-License-Identifier: MIT
// libFuzzer harness: read_stl (ASCII or binary) on arbitrary bytes, then a binary round trip.
#include "fuzz_entry.hpp"

CVMS_FUZZ_ENTRY(read_stl_target)
