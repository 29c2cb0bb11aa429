// SPDX-License-Identifier: MIT
// The Minkowski sum of two unions of convex pieces as the union of the
// pairwise sums: x is in (u Ai) + (u Bj) iff x = a + b with a in some Ai and
// b in some Bj, iff x is in some Ai + Bj. Each pair is one convex sum
// (minkowski_sum, cvms/minkowski.hpp), on one thread; the pairs are spread
// over Options::threads threads (detail::run_on_threads, which counts the
// workers' predicate evaluations as the caller's).
//
// Work sharing: threads take pair indices k = i m + j from one atomic
// counter, in increasing order, and write each outcome to its own slot. A
// failure (an exception from a pair, or a running total of output facets
// beyond the limits) makes every thread stop taking pairs; the pairs already
// taken finish, so the pairs taken are exactly 0..K-1 for some K. The
// outcome is then read in pair order: the first failing pair, or the first
// pair at which the prefix of facet counts passes the limit, is the one
// reported. A single thread stops at that same pair, so the error is the
// same for every thread count, and so is the result (its pieces in pair
// order).
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <string>
#include <thread>
#include <vector>

#include "cvms/convex_union.hpp"
#include "cvms/error.hpp"
#include "cvms/minkowski.hpp"
#include "progress_reporter.hpp"
#include "worker.hpp"

namespace cvms {
namespace {

// Facets every convex polyhedron has at least: what n m pieces must have.
constexpr std::uint64_t min_piece_facets = 4;

struct PairOutcome {
  ConvexPolyhedron sum;
  SumDiagnostics diagnostics;
  std::exception_ptr error;
};

std::string pair_name(std::size_t k, std::size_t m) {
  return "pair (" + std::to_string(k / m) + ", " + std::to_string(k % m) + ")";
}

// The most output facets the whole union may have: the facet limit, and
// the memory limit at SumLimits::bytes_per_output_facet.
std::uint64_t facet_budget(const SumLimits& limits) {
  return std::min(limits.max_output_facets, limits.max_memory_bytes / SumLimits::bytes_per_output_facet);
}

[[noreturn]] void beyond_budget(std::uint64_t facets, const std::string& where, const SumLimits& limits) {
  const bool by_memory =
      limits.max_memory_bytes / SumLimits::bytes_per_output_facet < limits.max_output_facets;
  const std::string limit =
      by_memory ? std::to_string(limits.max_memory_bytes) + " bytes (SumLimits::max_memory_bytes, at " +
                      std::to_string(SumLimits::bytes_per_output_facet) + " bytes per facet)"
                : std::to_string(limits.max_output_facets) + " facets (SumLimits::max_output_facets)";
  throw Error(ErrorCategory::limit, "minkowski_sum of unions: " + where + " has " + std::to_string(facets) +
                                        " facets in all, beyond the limit of " + limit);
}

// Refuses before any work a pair count whose pieces alone would pass the
// budget, or whose count does not fit the arithmetic.
void check_pair_count(std::size_t n, std::size_t m, const SumLimits& limits) {
  const std::uint64_t budget = facet_budget(limits);
  if (n > budget / min_piece_facets / m) {
    throw Error(ErrorCategory::limit, "minkowski_sum of unions: " + std::to_string(n) + " x " +
                                          std::to_string(m) + " pieces would have at least " +
                                          std::to_string(min_piece_facets) +
                                          " facets each, beyond the limits (SumLimits::max_output_facets, "
                                          "max_memory_bytes)");
  }
}

class PairSums {
 public:
  PairSums(std::span<const ConvexPolyhedron> a, std::span<const ConvexPolyhedron> b, const Options& options,
           detail::ProgressReporter& progress)
      : a_(a),
        b_(b),
        options_(options),
        progress_(progress),
        budget_(facet_budget(options.limits)),
        outcomes_(a.size() * b.size()) {}

  void run() {
    const unsigned cores = std::thread::hardware_concurrency();
    unsigned threads = std::max(1U, options_.threads);
    if (cores != 0) threads = std::min(threads, cores);
    if (threads > outcomes_.size()) threads = static_cast<unsigned>(outcomes_.size());
    // Each call shares the pairs through the counter, so any number of
    // threads started gives the same outcome.
    detail::run_on_threads(threads, [this](unsigned) { work(); });
  }

  // The pieces in pair order, or the first failure in pair order.
  std::vector<ConvexPolyhedron> take() {
    std::uint64_t facets = 0;
    const std::size_t taken = std::min(next_.load(), outcomes_.size());
    for (std::size_t k = 0; k < taken; ++k) {
      if (outcomes_[k].error) rethrow_named(outcomes_[k].error, k);
      facets += outcomes_[k].sum.num_facets();
      if (facets > budget_)
        beyond_budget(facets, "the union up to " + pair_name(k, b_.size()), options_.limits);
    }
    if (options_.diagnostics != nullptr) *options_.diagnostics = summed_diagnostics();
    std::vector<ConvexPolyhedron> pieces;
    pieces.reserve(outcomes_.size());
    for (PairOutcome& outcome : outcomes_) pieces.push_back(std::move(outcome.sum));
    return pieces;
  }

 private:
  void work() {
    while (!stop_.load(std::memory_order_relaxed)) {
      const std::size_t k = next_.fetch_add(1);
      if (k >= outcomes_.size()) return;
      if (!sum_pair(k)) stop_.store(true);
    }
  }

  // Computes pair k into its slot; false if the union must stop.
  bool sum_pair(std::size_t k) {
    PairOutcome& outcome = outcomes_[k];
    Options pair_options = options_;
    pair_options.threads = 1;
    pair_options.diagnostics = &outcome.diagnostics;
    // The pairs run on several threads at once: they only hear whether the
    // union's callback has asked to stop, which it hears once per pair.
    if (progress_.active()) pair_options.progress = [this](const Progress&) { return !progress_.stopped(); };
    try {
      outcome.sum = minkowski_sum(a_[k / b_.size()], b_[k % b_.size()], pair_options).polyhedron;
      progress_.advance(1);
    } catch (...) {
      outcome.error = std::current_exception();
      return false;
    }
    return total_facets_.fetch_add(outcome.sum.num_facets()) + outcome.sum.num_facets() <= budget_;
  }

  [[noreturn]] void rethrow_named(const std::exception_ptr& error, std::size_t k) const {
    try {
      std::rethrow_exception(error);
    } catch (const Error& e) {
      throw Error(e.category(), "minkowski_sum of unions: " + pair_name(k, b_.size()) + ": " + e.message());
    }
  }

  [[nodiscard]] SumDiagnostics summed_diagnostics() const {
    SumDiagnostics total;
    for (const PairOutcome& outcome : outcomes_) {
      total.contributing_ties += outcome.diagnostics.contributing_ties;
      total.edge_candidates += outcome.diagnostics.edge_candidates;
      total.edge_paper_rejections += outcome.diagnostics.edge_paper_rejections;
      total.predicate_filtered += outcome.diagnostics.predicate_filtered;
      total.predicate_exact += outcome.diagnostics.predicate_exact;
    }
    return total;
  }

  std::span<const ConvexPolyhedron> a_, b_;
  const Options& options_;
  detail::ProgressReporter& progress_;
  std::uint64_t budget_;
  std::vector<PairOutcome> outcomes_;
  std::atomic<std::size_t> next_{0};
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> total_facets_{0};
};

}  // namespace

ConvexUnion minkowski_sum(const ConvexUnion& a, const ConvexUnion& b, const Options& options) {
  if (a.empty())
    throw Error(ErrorCategory::invalid_argument, "minkowski_sum of unions: operand A has no pieces");
  if (b.empty())
    throw Error(ErrorCategory::invalid_argument, "minkowski_sum of unions: operand B has no pieces");
  check_pair_count(a.size(), b.size(), options.limits);
  detail::ProgressReporter progress(detail::callback_of(options.progress));
  progress.begin("union: pairs", a.size() * b.size());
  PairSums sums(a.pieces(), b.pieces(), options, progress);
  sums.run();
  ConvexUnion sum(sums.take());
  progress.end();
  return sum;
}

}  // namespace cvms
