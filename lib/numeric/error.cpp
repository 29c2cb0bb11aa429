// SPDX-License-Identifier: MIT
#include "cvms/error.hpp"

#include <cstring>

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
    case ErrorCategory::cancelled: return "cancelled";
  }
  return "unknown";
}

Error::Error(ErrorCategory category, const std::string& message)
    : std::runtime_error(std::string(to_string(category)) + ": " + message), category_(category) {}

// The message is not stored a second time: copying an Error stays a copy of
// runtime_error's one shared string, which cannot throw.
const char* Error::message() const noexcept { return what() + std::strlen(to_string(category_)) + 2; }

}  // namespace cvms
