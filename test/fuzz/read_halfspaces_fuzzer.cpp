// SPDX-License-Identifier: MIT
// libFuzzer harness: the cdd (.ine, .ext) and plain half-space readers on
// arbitrary text, their exact write/read round trips, and small accepted
// systems intersected against the brute-force oracle.
#include "fuzz_entry.hpp"

CVMS_FUZZ_ENTRY(read_halfspaces_target)
