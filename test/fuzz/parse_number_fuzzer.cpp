// SPDX-License-Identifier: MIT
// libFuzzer harness: the exact number parser alone (detail::parse_rational_into
// and its caps) against an independent reading; run with -dict=numbers.dict.
#include "fuzz_entry.hpp"
#include "parse_number_target.hpp"

CVMS_FUZZ_ENTRY(parse_number_target)
