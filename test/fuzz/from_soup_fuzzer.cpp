// SPDX-License-Identifier: MIT
// libFuzzer harness: ConvexPolyhedron::from_soup on soups decoded from bytes, checked
// against the exact hull of their points.
#include "fuzz_entry.hpp"

CVMS_FUZZ_ENTRY(from_soup_target)
