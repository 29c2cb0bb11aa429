// SPDX-License-Identifier: MIT
// libFuzzer harness: read_obj on arbitrary bytes, then a write_obj/read_obj round trip.
#include "fuzz_entry.hpp"

CVMS_FUZZ_ENTRY(read_obj_target)
