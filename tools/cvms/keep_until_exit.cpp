// SPDX-License-Identifier: MIT
// Where keep_until_exit parks what it is given (see keep_until_exit.hpp).
#include "keep_until_exit.hpp"

#include <vector>

namespace cvms::cli::detail {

void hold_until_exit(const void* object) {
  // Never freed, on purpose, and reachable until the end: not a leak.
  static auto* held = new std::vector<const void*>;
  held->push_back(object);
}

}  // namespace cvms::cli::detail
