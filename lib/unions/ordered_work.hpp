// SPDX-License-Identifier: MIT
// n independent computations (the pairwise sums of two unions, the sums of
// a solid's faces with a convex set) spread over threads so that the outcome
// is the one a single thread gives: the result in index order, or the same
// first failure.
//
// Threads take indices k from one atomic counter, in increasing order, and
// write each outcome to its own slot. A failure (an exception), or a
// running total of the results' sizes beyond the budget, makes every thread
// stop taking indices; those already taken finish, so the indices taken are
// exactly 0..K-1 for some K. Reading the slots in order then finds the first
// failing index, or the first index at which the prefix of sizes passes the
// budget; one thread stops at that same index, so the error is the same for
// every thread count, and so is the result.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <tuple>
#include <utility>
#include <vector>

#include "worker.hpp"

namespace cvms::detail {

template <class T>
class OrderedWork {
 public:
  /// n computations whose sizes may total `budget`.
  OrderedWork(std::size_t n, std::uint64_t budget) : outcomes_(n), budget_(budget) {}

  /// make(k) for every k < n, returning (value, size), on up to `threads`
  /// threads (no more than the machine's cores or n); stops taking indices
  /// after an exception or once the sizes made pass the budget.
  template <class Make>
  void run(unsigned threads, const Make& make) {
    // Each call shares the indices through the counter, so any number of
    // threads started gives the same outcome.
    run_on_threads(thread_count(threads, outcomes_.size()), [&](unsigned) { work(make); });
  }

  /// The values in index order. Before that, in index order: failed(k,
  /// error) for a computation that threw, beyond(k, total) at the first
  /// prefix of sizes beyond the budget; each of them must throw.
  template <class Failed, class Beyond>
  std::vector<T> take(const Failed& failed, const Beyond& beyond) {
    std::uint64_t total = 0;
    const std::size_t taken = std::min(next_.load(), outcomes_.size());
    for (std::size_t k = 0; k < taken; ++k) {
      if (outcomes_[k].error) failed(k, outcomes_[k].error);
      total += outcomes_[k].size;
      if (total > budget_) beyond(k, total);
    }
    std::vector<T> values;
    values.reserve(outcomes_.size());
    for (Outcome& outcome : outcomes_) values.push_back(std::move(outcome.value));
    return values;
  }

 private:
  struct Outcome {
    T value;
    std::uint64_t size = 0;
    std::exception_ptr error;
  };

  template <class Make>
  void work(const Make& make) {
    while (!stop_.load(std::memory_order_relaxed)) {
      const std::size_t k = next_.fetch_add(1);
      if (k >= outcomes_.size()) return;
      Outcome& outcome = outcomes_[k];
      try {
        std::tie(outcome.value, outcome.size) = make(k);
      } catch (...) {
        outcome.error = std::current_exception();
        stop_.store(true);
        return;
      }
      if (total_.fetch_add(outcome.size) + outcome.size > budget_) stop_.store(true);
    }
  }

  std::vector<Outcome> outcomes_;
  std::uint64_t budget_;
  std::atomic<std::size_t> next_{0};
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> total_{0};
};

}  // namespace cvms::detail
