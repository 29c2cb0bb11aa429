// SPDX-License-Identifier: MIT
// One step of an algorithm run on a second thread on the caller's behalf, so
// that the parallel step behaves like the sequential one: join() waits for
// it, rethrows what it threw, and counts its predicate evaluations as the
// joining thread's. The counters are per thread (filtered_predicates.hpp),
// and minkowski_sum reports the difference of its own thread's over the call,
// so without the merge a threaded run would report fewer predicates than the
// same run on one thread.
//
// A worker nobody joined (the caller is leaving by an exception of its own)
// is joined by the destructor, and what it threw is dropped: the caller's
// exception is the one that leaves. Declare the worker after everything its
// callable writes, so that it is joined before those are destroyed.
//
// run_on_threads is the N-thread form: the caller is one of the N, so that
// N = 1 starts nothing and N = 2 starts one worker.
#pragma once

#include <algorithm>
#include <cstddef>
#include <exception>
#include <memory>
#include <system_error>
#include <thread>
#include <utility>

#include "filtered_predicates.hpp"

namespace cvms::detail {

class Worker {
 public:
  Worker() = default;
  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;
  ~Worker() = default;  // the jthread joins

  /// Runs f() on a new thread. \pre not started yet.
  template <class F>
  void start(F f) {
    thread_ = std::jthread([this, f = std::move(f)]() mutable { run(f); });
  }

  /// True from start() until join().
  [[nodiscard]] bool joinable() const noexcept { return thread_.joinable(); }

  /// Waits for f, adds its predicate counts to this thread's counters and
  /// rethrows its exception, if any. \pre joinable().
  void join() {
    thread_.join();
    PredicateCounters& counters = predicate_counters();
    counters.filtered += counted_.filtered;
    counters.exact += counted_.exact;
    if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
  }

 private:
  template <class F>
  void run(F& f) noexcept {
    const PredicateCounters before = predicate_counters();
    try {
      f();
    } catch (...) {
      failure_ = std::current_exception();
    }
    const PredicateCounters& after = predicate_counters();
    counted_ = {after.filtered - before.filtered, after.exact - before.exact};
  }

  PredicateCounters counted_;
  std::exception_ptr failure_;
  std::jthread thread_;  // last: destroyed (joined) first
};

/// Calls f(0) on this thread and f(1), ..., f(k - 1) on workers, k <= n,
/// and returns when all have returned. Their predicate counts are this
/// thread's; f(0)'s exception leaves first, else the workers' in index
/// order. k < n only if the system refused to start another thread: the
/// calls must share their work so that any k gives the same result (and
/// may wait for f(0), which always runs). Returns k.
template <class F>
unsigned run_on_threads(unsigned n, F&& f) {
  if (n <= 1) {
    f(0u);
    return 1;
  }
  const auto workers = std::make_unique<Worker[]>(n - 1);
  unsigned started = 1;
  try {
    for (; started < n; ++started) workers[started - 1].start([&f, i = started] { f(i); });
  } catch (const std::system_error&) {
    // No more threads now: the ones started and this one do the work.
  }
  f(0u);
  for (unsigned i = 1; i < started; ++i) workers[i - 1].join();
  return started;
}

/// The machine's cores as std::thread::hardware_concurrency() gives them (0
/// when unknown), asked once: the C library reads them from the system on
/// every call, a cost of microseconds that small sums would pay per call.
inline unsigned core_count() {
  static const unsigned cores = std::thread::hardware_concurrency();
  return cores;
}

/// How many threads to share `items` independent items on: `requested` (at
/// least one), but no more than the machine's cores, when it says, and no
/// more than the items (at least one). More threads than either would only
/// wait.
inline unsigned thread_count(unsigned requested, std::size_t items) {
  const unsigned cores = core_count();
  unsigned threads = std::max(1U, requested);
  if (cores != 0) threads = std::min(threads, cores);
  if (threads > items) threads = static_cast<unsigned>(std::max<std::size_t>(items, 1));
  return threads;
}

}  // namespace cvms::detail
