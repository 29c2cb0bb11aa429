// SPDX-License-Identifier: MIT
/// \file
/// The one exception type the library throws. Every failure says what went
/// wrong and where (file and line or byte offset, or face/edge/vertex index).
#pragma once

#include <stdexcept>
#include <string>

namespace cvms {

/// What kind of failure an Error reports.
enum class ErrorCategory {
  parse,             ///< malformed text or binary input
  topology,          ///< not a closed, consistently oriented 2-manifold
  not_convex,        ///< a reflex edge, or a non-convex facet
  degenerate,        ///< flat, collinear or lower-dimensional input
  limit,             ///< a configured size limit was exceeded
  io,                ///< a file could not be opened, read or written
  invalid_argument,  ///< an API precondition was violated by the caller
  cancelled,         ///< a progress callback asked a long operation to stop
};

/// Name of a category as used in messages ("parse", "topology", ...).
const char* to_string(ErrorCategory category) noexcept;

/// Every exception thrown by cvms. what() is one line: "<category>: <message>".
class Error : public std::runtime_error {
 public:
  /// An error of `category`; what() becomes "<category>: <message>".
  Error(ErrorCategory category, const std::string& message);
  /// The kind of failure, for programs that react differently to each.
  [[nodiscard]] ErrorCategory category() const noexcept { return category_; }
  /// The message without the "<category>: " prefix of what(), for a caller
  /// that adds context in front of it (a file name) and keeps the category:
  /// `Error(e.category(), name + ": " + e.message())`. Valid as long as the
  /// Error is.
  [[nodiscard]] const char* message() const noexcept;

 private:
  ErrorCategory category_;
};

}  // namespace cvms
