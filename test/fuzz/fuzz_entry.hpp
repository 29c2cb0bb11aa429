// SPDX-License-Identifier: MIT
// The libFuzzer entry point shared by the harnesses: runs one target of
// test/support/fuzz_targets.hpp and turns a FuzzFinding (a broken invariant or
// a disagreement) into a crash libFuzzer records. Other exceptions escape on
// purpose: anything but cvms::Error leaving the library is a finding, and the
// targets only swallow Error where rejecting the input is legitimate.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <span>

#include "support/fuzz_targets.hpp"

#define CVMS_FUZZ_ENTRY(target)                                                       \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { \
    try {                                                                             \
      ::cvms::fuzz::target(std::span<const std::uint8_t>(data, size));                \
    } catch (const ::cvms::fuzz::FuzzFinding& finding) {                              \
      std::fprintf(stderr, "FUZZ FINDING (%s): %s\n", #target, finding.what());       \
      __builtin_trap();                                                               \
    }                                                                                 \
    return 0;                                                                         \
  }
