// SPDX-License-Identifier: MIT
// How many exact piece tests (a convex contains, intersects or distance
// query on one piece or one pair of pieces) the union queries of the calling
// thread have run: what the box hierarchy saves is what this does not count.
// Per thread, so concurrent queries do not mix their counts; read by the
// unions tests to show that a query far from most pieces visits few.
#pragma once

#include <cstdint>

namespace cvms::unions {

/// The calling thread's count, since it started; callers compare two reads.
inline std::uint64_t& exact_piece_tests() noexcept {
  thread_local std::uint64_t count = 0;
  return count;
}

}  // namespace cvms::unions
