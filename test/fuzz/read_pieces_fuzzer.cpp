// SPDX-License-Identifier: MIT
// libFuzzer harness: read_pieces on arbitrary bytes, then a write_pieces/read_pieces round trip.
#include "fuzz_entry.hpp"

CVMS_FUZZ_ENTRY(read_pieces_target)
