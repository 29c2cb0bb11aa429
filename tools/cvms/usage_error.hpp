// SPDX-License-Identifier: MIT
// The error of a command line that parses but does not make sense: main
// prints it with a hint to --help and exits with the usage code (2), as for
// a line CLI11 rejects.
#pragma once

#include <stdexcept>

namespace cvms::cli {

/// A command line that parsed but does not make sense (exit code 2).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace cvms::cli
