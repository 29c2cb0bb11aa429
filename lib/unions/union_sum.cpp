// SPDX-License-Identifier: MIT
// The Minkowski sum of two unions of convex pieces as the union of the
// pairwise sums: x is in (u Ai) + (u Bj) iff x = a + b with a in some Ai and
// b in some Bj, iff x is in some Ai + Bj. Each pair is one convex sum
// (minkowski_sum, cvms/minkowski.hpp), on one thread; the pairs are spread
// over Options::threads threads (detail::run_on_threads, which counts the
// workers' predicate evaluations as the caller's).
//
// Work sharing (ordered_work.hpp): the pairs in order k = i m + j, taken by
// the threads from one counter, the first failure in pair order reported,
// so the error and the result (its pieces in pair order) are the same for
// every thread count.
#include <algorithm>
#include <cstdint>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "cvms/convex_union.hpp"
#include "cvms/error.hpp"
#include "cvms/minkowski.hpp"
#include "facet_budget.hpp"
#include "ordered_work.hpp"
#include "progress_reporter.hpp"

namespace cvms {
namespace {

// Facets every convex polyhedron has at least: what n m pieces must have.
constexpr std::uint64_t min_piece_facets = 4;

std::string pair_name(std::size_t k, std::size_t m) {
  return "pair (" + std::to_string(k / m) + ", " + std::to_string(k % m) + ")";
}

[[noreturn]] void beyond_budget(std::uint64_t facets, const std::string& where, const SumLimits& limits) {
  throw Error(ErrorCategory::limit, "minkowski_sum of unions: " + where + " has " + std::to_string(facets) +
                                        " facets in all, beyond the limit of " +
                                        detail::facet_limit_text(limits));
}

// Refuses before any work a pair count whose pieces alone would pass the
// budget, or whose count does not fit the arithmetic.
void check_pair_count(std::size_t n, std::size_t m, const SumLimits& limits) {
  const std::uint64_t budget = detail::facet_budget(limits);
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
        diagnostics_(a.size() * b.size()),
        work_(a.size() * b.size(), detail::facet_budget(options.limits)) {}

  void run() {
    work_.run(options_.threads, [this](std::size_t k) { return sum_pair(k); });
  }

  // The pieces in pair order, or the first failure in pair order.
  std::vector<ConvexPolyhedron> take() {
    std::vector<ConvexPolyhedron> pieces =
        work_.take([this](std::size_t k, const std::exception_ptr& error) { rethrow_named(error, k); },
                   [this](std::size_t k, std::uint64_t facets) {
                     beyond_budget(facets, "the union up to " + pair_name(k, b_.size()), options_.limits);
                   });
    if (options_.diagnostics != nullptr) *options_.diagnostics = summed_diagnostics();
    return pieces;
  }

 private:
  // Pair k's sum and its facet count.
  std::pair<ConvexPolyhedron, std::uint64_t> sum_pair(std::size_t k) {
    Options pair_options = options_;
    pair_options.threads = 1;
    pair_options.diagnostics = &diagnostics_[k];
    // The pairs run on several threads at once: they only hear whether the
    // union's callback has asked to stop, which it hears once per pair.
    if (progress_.active()) pair_options.progress = [this](const Progress&) { return !progress_.stopped(); };
    ConvexPolyhedron sum = minkowski_sum(a_[k / b_.size()], b_[k % b_.size()], pair_options).polyhedron;
    progress_.advance(1);
    const std::uint64_t facets = sum.num_facets();
    return {std::move(sum), facets};
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
    for (const SumDiagnostics& d : diagnostics_) {
      total.contributing_ties += d.contributing_ties;
      total.edge_candidates += d.edge_candidates;
      total.edge_paper_rejections += d.edge_paper_rejections;
      total.predicate_filtered += d.predicate_filtered;
      total.predicate_exact += d.predicate_exact;
    }
    return total;
  }

  std::span<const ConvexPolyhedron> a_, b_;
  const Options& options_;
  detail::ProgressReporter& progress_;
  std::vector<SumDiagnostics> diagnostics_;
  detail::OrderedWork<ConvexPolyhedron> work_;
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
