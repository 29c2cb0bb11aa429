// SPDX-License-Identifier: MIT
// The library's side of a ProgressCallback (cvms/progress.hpp): one stage at
// a time, its units counted by any thread of the call, reported under a
// mutex so that the callback never runs on two threads at once and sees done
// grow. Every thread that counts units checks for a stop and throws
// Error(cancelled) there: a worker's exception is rethrown where it is
// joined, and the caller's leaves after its workers are joined (worker.hpp),
// so a cancelled call leaves as any failed one does, by unwinding.
//
// Absent callback: active() is false and advance() returns at its first
// test, so the algorithms call it once per chunk of work (dozens of edges or
// points, a few microseconds) at no measurable cost.
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>

#include "cvms/progress.hpp"

namespace cvms::detail {

class ProgressReporter {
 public:
  /// Reports to `callback`; null or an empty callback reports nothing.
  explicit ProgressReporter(const ProgressCallback* callback) noexcept
      : callback_(callback != nullptr && *callback ? callback : nullptr) {}
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;
  ~ProgressReporter() = default;

  /// True if a callback listens.
  [[nodiscard]] bool active() const noexcept { return callback_ != nullptr; }

  /// Starts a stage of `total` units and reports done = 0. Called by the
  /// thread that runs the call, with no other thread counting units.
  /// \throw Error(cancelled) if the callback asks to stop.
  void begin(const char* stage, std::uint64_t total);

  /// Counts n more units of the current stage done and reports them; any
  /// thread. \throw Error(cancelled) if the callback asks to stop, now or
  /// on another thread before.
  void advance(std::uint64_t n) {
    if (callback_ != nullptr) count(n);
  }

  /// Sets the units done to `done` if that is more than so far, and
  /// reports; any thread. \throw Error(cancelled) as advance.
  void reach(std::uint64_t done) {
    if (callback_ != nullptr) count_to(done);
  }

  /// Reports done = total, ending the stage. \throw Error(cancelled) as begin.
  void end();

  /// True once the callback has asked to stop: for work that runs under a
  /// callback of its own (the pairs of a union's sum, on several threads)
  /// and stops when this one does.
  [[nodiscard]] bool stopped() const noexcept { return stopped_.load(std::memory_order_relaxed); }

 private:
  void count(std::uint64_t n);
  void count_to(std::uint64_t done);
  void report_locked(std::uint64_t done);  // \pre mutex_ held
  [[noreturn]] static void throw_cancelled();

  const ProgressCallback* callback_;
  std::mutex mutex_;
  const char* stage_ = "";
  std::uint64_t total_ = 0;
  std::uint64_t reported_ = 0;  // under mutex_
  std::atomic<std::uint64_t> done_{0};
  std::atomic<bool> stopped_{false};
};

/// A reporter for a callback that may be empty or absent (nullptr).
inline const ProgressCallback* callback_of(const ProgressCallback& callback) noexcept {
  return callback ? &callback : nullptr;
}

}  // namespace cvms::detail
