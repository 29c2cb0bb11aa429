// SPDX-License-Identifier: MIT
// CVMS_TEST_UNDER_SANITIZER, defined in a build with AddressSanitizer,
// ThreadSanitizer or MemorySanitizer (GCC or Clang): their runtimes reserve
// terabytes of address space, so tests that cap it (RLIMIT_AS) skip there.
#pragma once

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define CVMS_TEST_UNDER_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define CVMS_TEST_UNDER_SANITIZER 1
#endif
#endif
