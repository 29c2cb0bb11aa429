// SPDX-License-Identifier: MIT
// Cancellation on the CVMS paths a small machine never takes by itself: the
// threaded trace in chunks (threads > 2, oversubscribed), the workers
// started at any size, and the paper's edge search. For every k up to the
// reports of a whole run, a callback that asks to stop at its k-th call gets
// Error(cancelled), and is never called again (the public suite,
// progress_test.cpp, checks the reports themselves and the identical output).
#include <gtest/gtest.h>

#include <cstddef>
#include <mutex>
#include <string>

#include "cvms/error.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/shapes.hpp"
#include "research_options.hpp"

namespace {

using cvms::Error;
using cvms::ErrorCategory;
using cvms::Options;
using cvms::Progress;

// Calls until the k-th (0: never stops); the mutex only lets
// ThreadSanitizer check that calls never overlap.
struct Counter {
  std::mutex mutex;
  std::size_t calls = 0;
  std::size_t stop_at = 0;
  bool operator()(const Progress&) {
    const std::lock_guard<std::mutex> lock(mutex);
    ++calls;
    return stop_at == 0 || calls < stop_at;
  }
};

// Sphere_k + rotated Sphere_k.
void expect_cancellable(const cvms::detail::ResearchOptions& research, unsigned threads, int k,
                        const std::string& name) {
  SCOPED_TRACE(name + ", threads " + std::to_string(threads));
  const cvms::ConvexPolyhedron a = cvms::shapes::geodesic_sphere(k);
  const cvms::ConvexPolyhedron b = cvms::shapes::rotated_geodesic_sphere(k);
  Options options;
  options.threads = threads;
  Counter whole;
  options.progress = [&whole](const Progress& p) { return whole(p); };
  const std::size_t facets = cvms::detail::minkowski_sum(a, b, options, research).polyhedron.num_facets();
  EXPECT_EQ(facets, cvms::minkowski_sum(a, b).polyhedron.num_facets());
  ASSERT_GE(whole.calls, 4u);
  for (std::size_t stop = 1; stop <= whole.calls; ++stop) {
    Counter counter;
    counter.stop_at = stop;
    options.progress = [&counter](const Progress& p) { return counter(p); };
    try {
      (void)cvms::detail::minkowski_sum(a, b, options, research);
      EXPECT_LT(counter.calls, stop) << "asked to stop at call " << stop << ", and finished";
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::cancelled) << e.what();
      EXPECT_EQ(counter.calls, stop) << "no call after the one that asked to stop";
    }
  }
}

TEST(ProgressInternal, ThreadedTraceAndWorkersStopWhenAsked) {
  cvms::detail::ResearchOptions research;
  research.worker_minimums = {0, 0, true};
  for (const unsigned threads : {2u, 4u, 8u}) expect_cancellable(research, threads, 4, "workers always");
}

TEST(ProgressInternal, PaperSearchStopsWhenAsked) {
  cvms::detail::ResearchOptions research;
  research.contributing_vertex_search = cvms::detail::ContributingVertexSearch::scan;
  research.edge_facet_search = cvms::detail::EdgeFacetSearch::paper;
  expect_cancellable(research, 1, 3, "paper");  // quadratic: a smaller pair
}

}  // namespace
