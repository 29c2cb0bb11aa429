// SPDX-License-Identifier: MIT
#include "cvms/error.hpp"

namespace cvms {

const char* to_string(ErrorCategory category) noexcept {
  switch (category) {
    case ErrorCategory::parse: return "parse";
    case ErrorCategory::topology: return "topology";
    case ErrorCategory::not_convex: return "not_convex";
    case ErrorCategory::degenerate: return "degenerate";
    case ErrorCategory::limit: return "limit";
    case ErrorCategory::io: return "io";
    case ErrorCategory::invalid_argument: return "invalid_argument";
    case ErrorCategory::not_implemented: return "not_implemented";
  }
  return "unknown";
}

Error::Error(ErrorCategory category, const std::string& message)
    : std::runtime_error(std::string(to_string(category)) + ": " + message), category_(category) {}

}  // namespace cvms
