// SPDX-License-Identifier: MIT
// Progress reports and cancellation of the long operations
// (cvms/progress.hpp): each run of a stage starts at 0, never goes back and
// ends at its total; a callback that never asks to stop changes no byte of
// the result; a callback that asks to stop after its k-th call, for every k
// a whole run reaches, gets Error(cancelled) at once (no further call, the
// call returns within a bound), and leaves nothing behind (the suite runs
// under AddressSanitizer's leak check and, label threads, under
// ThreadSanitizer for the threaded sums).
#include "cvms/progress.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/convex_union.hpp"
#include "cvms/error.hpp"
#include "cvms/halfspaces.hpp"
#include "cvms/io.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/set_sum.hpp"
#include "cvms/shapes.hpp"

namespace {

using cvms::Algorithm;
using cvms::ConvexPolyhedron;
using cvms::ConvexSet;
using cvms::Error;
using cvms::ErrorCategory;
using cvms::Options;
using cvms::Progress;
using cvms::ProgressCallback;
using Clock = std::chrono::steady_clock;
namespace shapes = cvms::shapes;

// What a callback heard, and the call after which it asks to stop (0: never).
// The library never calls it on two threads at once; the mutex only makes
// that claim checkable by ThreadSanitizer, not true.
struct Log {
  std::mutex mutex;
  std::vector<Progress> reports;
  std::size_t stop_after = 0;
  Clock::time_point stopped_at;
  std::size_t calls_after_stop = 0;

  ProgressCallback callback() {
    return [this](const Progress& p) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (stop_after != 0 && reports.size() >= stop_after) {
        ++calls_after_stop;
        return false;
      }
      reports.push_back(p);
      if (stop_after != 0 && reports.size() == stop_after) {
        stopped_at = Clock::now();
        return false;
      }
      return true;
    };
  }
};

// Every run of a stage: starts at done = 0, keeps its total, never
// decreases, and (for a finished call) ends at done = total. Runs of one
// stage follow each other; other stages may report in between (nesting).
void expect_well_formed(const std::vector<Progress>& reports) {
  std::map<std::string, Progress> open;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    const Progress& p = reports[i];
    SCOPED_TRACE("report " + std::to_string(i) + ": " + p.stage + " " + std::to_string(p.done) + "/" +
                 std::to_string(p.total));
    EXPECT_LE(p.done, p.total);
    const auto it = open.find(p.stage);
    if (it == open.end()) {
      EXPECT_EQ(p.done, 0u) << "a run of a stage starts at 0";
      if (p.done < p.total) open.emplace(p.stage, p);
      continue;
    }
    EXPECT_EQ(p.total, it->second.total) << "the total of a run never changes";
    EXPECT_GE(p.done, it->second.done) << "done never decreases";
    if (p.done == p.total)
      open.erase(it);
    else
      it->second = p;
  }
  for (const auto& [stage, last] : open)
    ADD_FAILURE() << "stage " << stage << " ended at " << last.done << "/" << last.total;
}

std::string off_text(const ConvexPolyhedron& p) {
  std::ostringstream out;
  cvms::write(out, p, cvms::FileFormat::off);
  return out.str();
}

std::string off_text(const ConvexSet& s) {
  if (s.dimension() == 3) return off_text(s.polyhedron());
  std::ostringstream out;
  for (const cvms::Vec3& v : s.vertices())
    out << cvms::to_string(v.x) << ' ' << cvms::to_string(v.y) << ' ' << cvms::to_string(v.z) << '\n';
  return out.str();
}

std::string off_text(const cvms::ConvexUnion& u) {
  std::string text;
  for (const ConvexPolyhedron& piece : u.pieces()) text += off_text(piece);
  return text;
}

// One long operation: its result as text, run with the given callback.
using Operation = std::function<std::string(const ProgressCallback&)>;

// The properties every operation must have: well-formed reports and the
// same bytes with a callback as without; then a stop after the k-th call
// for every k of the whole run throws Error(cancelled) at once.
void expect_reports_and_cancellation(const Operation& run, const std::string& name) {
  SCOPED_TRACE(name);
  const std::string plain = run(ProgressCallback());
  Log full;
  EXPECT_EQ(run(full.callback()), plain) << "a callback that never stops changes no byte";
  expect_well_formed(full.reports);
  ASSERT_GE(full.reports.size(), 2u) << "at least the start and the end of a stage";
  for (std::size_t k = 1; k <= full.reports.size(); ++k) {
    SCOPED_TRACE("stop after call " + std::to_string(k));
    Log log;
    log.stop_after = k;
    try {
      (void)run(log.callback());
      // With threads the calls may be fewer than in the full run.
      EXPECT_LT(log.reports.size(), k) << "the callback asked to stop, and the call finished";
      continue;
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::cancelled) << e.what();
    }
    const auto latency = Clock::now() - log.stopped_at;
    EXPECT_EQ(log.reports.size(), k);
    EXPECT_EQ(log.calls_after_stop, 0u) << "no call after the one that asked to stop";
    EXPECT_LT(std::chrono::duration<double>(latency).count(), 2.0) << "stopped promptly";
  }
}

Operation sum_of(const ConvexPolyhedron& a, const ConvexPolyhedron& b, Algorithm algorithm,
                 unsigned threads) {
  return [a, b, algorithm, threads](const ProgressCallback& progress) {
    Options options;
    options.algorithm = algorithm;
    options.threads = threads;
    options.progress = progress;
    return off_text(cvms::minkowski_sum(a, b, options).polyhedron);
  };
}

TEST(Progress, CvmsSumOnOneThread) {
  expect_reports_and_cancellation(
      sum_of(shapes::geodesic_sphere(4), shapes::rotated_geodesic_sphere(4), Algorithm::cvms, 1),
      "sphere4 + rotated");
}

TEST(Progress, CvmsSumOnSeveralThreads) {
  // Large enough for the workers (the trace and the output's build).
  for (const unsigned threads : {2u, 4u}) {
    expect_reports_and_cancellation(
        sum_of(shapes::geodesic_sphere(4), shapes::rotated_geodesic_sphere(4), Algorithm::cvms, threads),
        "threads " + std::to_string(threads));
  }
}

TEST(Progress, EssdmsAndChmsSums) {
  expect_reports_and_cancellation(
      sum_of(shapes::geodesic_sphere(2), shapes::rotated_geodesic_sphere(2), Algorithm::essdms, 1), "essdms");
  expect_reports_and_cancellation(
      sum_of(shapes::geodesic_sphere(2), shapes::rotated_geodesic_sphere(2), Algorithm::chms, 1), "chms");
}

TEST(Progress, SumOfManyReportsEachSumOfTwo) {
  const std::vector<ConvexSet> operands = {
      ConvexSet(shapes::geodesic_sphere(3)), ConvexSet::segment({0, 0, 0}, {1, 2, 3}),
      ConvexSet(shapes::rotated_geodesic_sphere(3)), ConvexSet::point({1, 1, 1})};
  const Operation run = [&](const ProgressCallback& progress) {
    Options options;
    options.progress = progress;
    return off_text(cvms::minkowski_sum(operands, options));
  };
  expect_reports_and_cancellation(run, "sum of many");
  Log log;
  (void)run(log.callback());
  std::size_t sums = 0;
  for (const Progress& p : log.reports) sums += std::string(p.stage) == "sums";
  EXPECT_EQ(sums, 2u + 2u) << "start, two sums of two (the point is a translation), end";
}

TEST(Progress, ConvexHull) {
  const std::vector<cvms::Vec3> points = shapes::random_points(7, 20000);
  expect_reports_and_cancellation(
      [&](const ProgressCallback& progress) { return off_text(cvms::convex_hull(points, progress)); },
      "hull");
  expect_reports_and_cancellation(
      [&](const ProgressCallback& progress) { return off_text(cvms::convex_hull_set(points, progress)); },
      "hull set");
}

TEST(Progress, FromHalfspacesAndDifference) {
  const ConvexSet a(shapes::geodesic_sphere(4));
  // A short segment: the difference is a polyhedron, made from its rows.
  const ConvexSet b =
      ConvexSet::segment({cvms::Rational(-1, 10), 0, 0}, {cvms::Rational(1, 10), cvms::Rational(1, 10), 0});
  const cvms::HalfspaceSystem rows = cvms::to_halfspaces(a);
  expect_reports_and_cancellation(
      [&](const ProgressCallback& progress) { return off_text(cvms::from_halfspaces(rows, progress)); },
      "from_halfspaces");
  expect_reports_and_cancellation(
      [&](const ProgressCallback& progress) { return off_text(cvms::pontryagin_difference(a, b, progress)); },
      "pontryagin_difference");
}

TEST(Progress, UnionSumOnSeveralThreads) {
  const cvms::ConvexUnion a({shapes::geodesic_sphere(2), shapes::box({0, 0, 0}, {1, 1, 1})});
  const cvms::ConvexUnion b({shapes::rotated_geodesic_sphere(2), shapes::cube(), shapes::octahedron()});
  for (const unsigned threads : {1u, 3u}) {
    expect_reports_and_cancellation(
        [&](const ProgressCallback& progress) {
          Options options;
          options.threads = threads;
          options.progress = progress;
          return off_text(cvms::minkowski_sum(a, b, options));
        },
        "union, threads " + std::to_string(threads));
  }
}

TEST(Progress, StopTokenAsCallback) {
  std::stop_source source;
  Options options;
  options.progress = [token = source.get_token()](const Progress&) { return !token.stop_requested(); };
  source.request_stop();
  try {
    (void)cvms::minkowski_sum(shapes::geodesic_sphere(2), shapes::cube(), options);
    FAIL() << "a stop requested before the call stops it at its first report";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::cancelled);
    EXPECT_STREQ(e.what(), "cancelled: stopped by the progress callback");
  }
}

TEST(Progress, ExceptionOfTheCallbackPropagates) {
  for (const unsigned threads : {1u, 2u}) {
    Options options;
    options.threads = threads;
    int calls = 0;
    options.progress = [&calls](const Progress&) -> bool {
      if (++calls == 3) throw std::runtime_error("from the callback");
      return true;
    };
    EXPECT_THROW(
        (void)cvms::minkowski_sum(shapes::geodesic_sphere(4), shapes::rotated_geodesic_sphere(4), options),
        std::runtime_error);
  }
}

TEST(Progress, CategoryName) { EXPECT_STREQ(cvms::to_string(ErrorCategory::cancelled), "cancelled"); }

}  // namespace
