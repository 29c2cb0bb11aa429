// SPDX-License-Identifier: MIT
// ProgressReporter (progress_reporter.hpp): the stage's counter is atomic so
// that worker threads count without a lock; the report takes the mutex, reads
// the counter under it and never reports less than it did, so the callback
// sees a non-decreasing done even when two threads race to report.
#include "progress_reporter.hpp"

#include <algorithm>

#include "cvms/error.hpp"

namespace cvms::detail {

void ProgressReporter::throw_cancelled() {
  throw Error(ErrorCategory::cancelled, "stopped by the progress callback");
}

void ProgressReporter::begin(const char* stage, std::uint64_t total) {
  if (callback_ == nullptr) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  stage_ = stage;
  total_ = total;
  reported_ = 0;
  done_.store(0, std::memory_order_relaxed);
  if (!(*callback_)(Progress{stage_, 0, total_})) stopped_ = true;
  if (stopped_) throw_cancelled();
}

void ProgressReporter::end() {
  if (callback_ == nullptr) return;
  if (stopped_) throw_cancelled();
  const std::lock_guard<std::mutex> lock(mutex_);
  reported_ = total_;
  if (!(*callback_)(Progress{stage_, total_, total_})) stopped_ = true;
  if (stopped_) throw_cancelled();
}

void ProgressReporter::count(std::uint64_t n) {
  if (stopped_.load(std::memory_order_relaxed)) throw_cancelled();
  const std::uint64_t done = done_.fetch_add(n, std::memory_order_relaxed) + n;
  const std::lock_guard<std::mutex> lock(mutex_);
  report_locked(done);
}

void ProgressReporter::count_to(std::uint64_t done) {
  if (stopped_.load(std::memory_order_relaxed)) throw_cancelled();
  std::uint64_t seen = done_.load(std::memory_order_relaxed);
  while (seen < done && !done_.compare_exchange_weak(seen, done, std::memory_order_relaxed)) {
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  report_locked(done);
}

void ProgressReporter::report_locked(std::uint64_t done) {
  if (stopped_) throw_cancelled();  // another thread's callback asked already
  // Below total: the stage's last report is end()'s.
  const std::uint64_t shown = std::max(reported_, std::min(done, total_ == 0 ? 0 : total_ - 1));
  reported_ = shown;
  if (!(*callback_)(Progress{stage_, shown, total_})) stopped_ = true;
  if (stopped_) throw_cancelled();
}

}  // namespace cvms::detail
