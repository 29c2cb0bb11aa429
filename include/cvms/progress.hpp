// SPDX-License-Identifier: MIT
/// \file
/// Progress reports and cancellation for the long operations: the sums of
/// two and of many sets, the convex hull, from_halfspaces and the Pontryagin
/// difference take an optional callback that hears how far they are and may
/// ask them to stop.
#pragma once

#include <cstdint>
#include <functional>

namespace cvms {

/// How far a long operation is in one of its stages.
///
/// An operation runs through named stages ("sum: facets", "sum: output",
/// "hull", ...), some of them several times in one call (a sum of many runs
/// the stages of a sum of two once per pair). Each run of a stage is reported
/// as a sequence that starts with done = 0, in which done never decreases and
/// total never changes, and that ends with done = total, unless the call is
/// cancelled or fails before.
struct Progress {
  /// The stage's name, a string literal (valid for the program's lifetime).
  const char* stage = "";
  /// Units of the stage's work done so far, at most total.
  std::uint64_t done = 0;
  /// Units of the stage's work in all; the unit is the stage's own (edges,
  /// facets, points, pairs), so only done / total compares across stages.
  std::uint64_t total = 0;
};

/// Called by a long operation at coarse intervals (chunks of work of about a
/// millisecond on a current machine, a few milliseconds at most, between
/// two calls, and at the start and the end of each stage); returning false
/// asks the operation to stop, which it does at its next check, throwing
/// Error(cancelled) and leaving nothing behind (no partial result, every
/// worker thread joined, every allocation freed). With Options::threads > 1
/// the callback may be called from any thread of the call, but never by two
/// threads at once. An empty callback (the default) costs nothing. A
/// std::stop_token becomes a callback as
/// `[token](const Progress&) { return !token.stop_requested(); }`.
/// An exception the callback throws propagates out of the operation, which
/// leaves nothing behind then either.
using ProgressCallback = std::function<bool(const Progress&)>;

}  // namespace cvms
