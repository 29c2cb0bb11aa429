// SPDX-License-Identifier: MIT
// The body of the number-parser harness (parse_number_fuzzer.cpp), apart from
// the reader harnesses of test/support/fuzz_targets.hpp because it tests a
// private function: detail::parse_rational_into (lib/numeric/rational_text.hpp)
// and its caps. This header is public-API only, so the default suite replays
// the corpus through it (test/fuzz_corpus_test.cpp) without private headers.
#pragma once

#include <cstdint>
#include <span>

namespace cvms::fuzz {

/// The first byte picks the caps (bits 0-1: max_bits 64, 1075, 4096 or
/// GMP's maximum; bits 2-3: max_exponent 0, 10, 400 or 100,000); the rest is
/// the number's text. Throws FuzzFinding (support/fuzz_targets.hpp) when:
///  - the status disagrees with an independent reading of the syntax;
///  - a value is accepted that is not in lowest terms, breaks a cap, or
///    differs from the value built independently (digits times a power of
///    ten, for exponents up to 20,000);
///  - a refusal reports fewer bits than the cap, or more than the value has;
///  - printing an accepted value (cvms::to_string) and parsing it back does
///    not give the same value;
///  - try_parse_rational and parse_rational disagree with it, or
///    parse_rational throws anything but Error(parse).
void parse_number_target(std::span<const std::uint8_t> data);

}  // namespace cvms::fuzz
