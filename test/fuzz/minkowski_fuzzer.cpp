// SPDX-License-Identifier: MIT
// libFuzzer harness: differential: CVMS (both operand orders), CHMS and ESSDMS on
// hulls of two small point clouds decoded from bytes must agree exactly.
#include "fuzz_entry.hpp"

CVMS_FUZZ_ENTRY(minkowski_target)
