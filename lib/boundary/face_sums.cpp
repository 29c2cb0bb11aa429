// SPDX-License-Identifier: MIT
// See face_sums.hpp. Work sharing as in the sum of two unions
// (lib/unions/union_sum.cpp): threads take polygon indices from one atomic
// counter in increasing order and write each outcome to its own slot; a
// failure, or a running total of facets beyond the budget, stops every
// thread from taking more, so the polygons taken are exactly 0..K-1 for
// some K. Reading the slots in order then finds the same first failure, or
// the same prefix passing the budget, as one thread would: the result and
// the error do not depend on the thread count.
#include "face_sums.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <string>
#include <thread>

#include "cvms/convex_set.hpp"
#include "cvms/error.hpp"
#include "cvms/set_sum.hpp"
#include "progress_reporter.hpp"
#include "worker.hpp"

namespace cvms::detail {
namespace {

// Facets every convex polyhedron has at least.
constexpr std::uint64_t min_piece_facets = 4;

std::uint64_t facet_budget(const SumLimits& limits) {
  return std::min(limits.max_output_facets, limits.max_memory_bytes / SumLimits::bytes_per_output_facet);
}

std::string limit_name(const SumLimits& limits) {
  if (limits.max_memory_bytes / SumLimits::bytes_per_output_facet < limits.max_output_facets)
    return std::to_string(limits.max_memory_bytes) + " bytes (SumLimits::max_memory_bytes, at " +
           std::to_string(SumLimits::bytes_per_output_facet) + " bytes per facet)";
  return std::to_string(limits.max_output_facets) + " facets (SumLimits::max_output_facets)";
}

[[noreturn]] void beyond_budget(const std::string& what, const SumLimits& limits) {
  throw Error(ErrorCategory::limit,
              "minkowski_sum of solids: " + what + ", beyond the limit of " + limit_name(limits));
}

struct FaceOutcome {
  ConvexPolyhedron sum;
  std::exception_ptr error;
};

class FaceSums {
 public:
  FaceSums(std::span<const std::vector<Vec3>> polygons, const ConvexPolyhedron& b, const Options& options,
           ProgressReporter& progress)
      : polygons_(polygons),
        b_(b),
        options_(options),
        progress_(progress),
        budget_(facet_budget(options.limits)),
        outcomes_(polygons.size()) {}

  void run() {
    const unsigned cores = std::thread::hardware_concurrency();
    unsigned threads = std::max(1U, options_.threads);
    if (cores != 0) threads = std::min(threads, cores);
    if (threads > outcomes_.size()) threads = static_cast<unsigned>(std::max<std::size_t>(1, outcomes_.size()));
    run_on_threads(threads, [this](unsigned) { work(); });
  }

  std::vector<ConvexPolyhedron> take() {
    std::uint64_t facets = 0;
    const std::size_t taken = std::min(next_.load(), outcomes_.size());
    for (std::size_t k = 0; k < taken; ++k) {
      if (outcomes_[k].error) rethrow_named(outcomes_[k].error, k);
      facets += outcomes_[k].sum.num_facets();
      if (facets > budget_)
        beyond_budget("the sums of B with A's faces up to face polygon " + std::to_string(k) + " have " +
                          std::to_string(facets) + " facets in all",
                      options_.limits);
    }
    std::vector<ConvexPolyhedron> sums;
    sums.reserve(outcomes_.size());
    for (FaceOutcome& outcome : outcomes_) sums.push_back(std::move(outcome.sum));
    return sums;
  }

 private:
  void work() {
    while (!stop_.load(std::memory_order_relaxed)) {
      const std::size_t k = next_.fetch_add(1);
      if (k >= outcomes_.size()) return;
      if (!sum_face(k)) stop_.store(true);
    }
  }

  // Computes polygon k + B into its slot; false if the sums must stop.
  bool sum_face(std::size_t k) {
    FaceOutcome& outcome = outcomes_[k];
    Options face_options;
    face_options.limits = options_.limits;
    try {
      outcome.sum = minkowski_sum(ConvexSet::polygon(polygons_[k]), b_, face_options).polyhedron();
      progress_.advance(1);
    } catch (...) {
      outcome.error = std::current_exception();
      return false;
    }
    return total_facets_.fetch_add(outcome.sum.num_facets()) + outcome.sum.num_facets() <= budget_;
  }

  [[noreturn]] static void rethrow_named(const std::exception_ptr& error, std::size_t k) {
    try {
      std::rethrow_exception(error);
    } catch (const Error& e) {
      if (e.category() == ErrorCategory::cancelled) throw;
      throw Error(e.category(),
                  "minkowski_sum of solids: face polygon " + std::to_string(k) + " + B: " + e.message());
    }
  }

  std::span<const std::vector<Vec3>> polygons_;
  const ConvexPolyhedron& b_;
  const Options& options_;
  ProgressReporter& progress_;
  std::uint64_t budget_;
  std::vector<FaceOutcome> outcomes_;
  std::atomic<std::size_t> next_{0};
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> total_facets_{0};
};

}  // namespace

std::vector<ConvexPolyhedron> face_sums(std::span<const std::vector<Vec3>> polygons, const ConvexPolyhedron& b,
                                        const Options& options) {
  const std::uint64_t budget = facet_budget(options.limits);
  if (polygons.size() > budget / min_piece_facets)
    beyond_budget(std::to_string(polygons.size()) + " face polygons of A summed with B would have at least " +
                      std::to_string(min_piece_facets) + " facets each",
                  options.limits);
  ProgressReporter progress(callback_of(options.progress));
  progress.begin("solid sum: faces", polygons.size());
  FaceSums sums(polygons, b, options, progress);
  sums.run();
  std::vector<ConvexPolyhedron> result = sums.take();
  progress.end();
  return result;
}

}  // namespace cvms::detail
