// SPDX-License-Identifier: MIT
// The allocation-failure sweep: an operation run with its 1st, 2nd, 3rd ...
// call of operator new failing (failing_allocator.hpp) until a run
// completes without reaching the failure. Each failing run must end in a
// cvms::Error or std::bad_alloc (any other exception, a crash or a leak is
// a finding), the operands must be unchanged after it, and a run that
// completes despite a failure, and the last run, must give the result of a
// run made before the sweep. Results and operands are compared through
// fingerprints: exact text written here, not by the library's writers, so
// that a writer under test is not its own judge.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <streambuf>
#include <string>
#include <string_view>
#include <type_traits>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/convex_set.hpp"
#include "cvms/convex_union.hpp"
#include "cvms/error.hpp"
#include "cvms/halfspace_io.hpp"
#include "cvms/halfspaces.hpp"
#include "cvms/polygon_soup.hpp"
#include "cvms/proximity.hpp"
#include "cvms/solid.hpp"
#include "support/failing_allocator.hpp"

namespace cvms::test {

// Exact fingerprints: equal strings if and only if equal values, numbering
// and order included.
std::string fingerprint(const PolygonSoup& soup);
std::string fingerprint(const ConvexPolyhedron& p);
std::string fingerprint(const ConvexSet& s);
std::string fingerprint(const ConvexUnion& u);
std::string fingerprint(const Solid& s);
std::string fingerprint(const HalfspaceSystem& system);
std::string fingerprint(const std::vector<HalfspaceRow>& rows);
std::string fingerprint(const HalfspaceFile& file);
std::string fingerprint(const PointFile& file);
std::string fingerprint(const HalfspaceIntersection& intersection);
std::string fingerprint(const DistanceResult& d);
std::string fingerprint(const PenetrationResult& p);
std::string fingerprint(const std::vector<Vec3>& points);
inline std::string fingerprint(const std::string& text) { return text; }
inline std::string fingerprint(bool b) { return b ? "true" : "false"; }

/// A read-only stream buffer over text that outlives it: a reader's input
/// that takes no allocation of its own.
class TextBuffer : public std::streambuf {
 public:
  explicit TextBuffer(std::string_view text) {
    char* begin = const_cast<char*>(text.data());  // never written: get area only
    setg(begin, begin, begin + text.size());
  }
};

/// Under AddressSanitizer: runs LeakSanitizer's check now, which prints any
/// block that nothing reaches, and says whether there was one, so that a
/// leak is charged to the test that made it rather than found at the exit
/// of a process that ran many. Elsewhere: false. A check scans the whole
/// heap (a fraction of a second under ASan): once per test, not per sweep.
bool unreachable_blocks();

/// How a sweep fails its allocations.
struct SweepOptions {
  bool persistent = false;  ///< every call after the k-th fails too
  /// The fingerprint of the expected result, when the sweep must not make
  /// the reference run itself (an operation that builds a cache on its
  /// first call sweeps that first call); empty: a run before the sweep.
  std::string reference;
};

/// What a sweep saw.
struct SweepReport {
  std::uint64_t allocations = 0;   ///< calls of operator new in a complete run
  std::uint64_t failing_runs = 0;  ///< runs that reached the failure
  std::uint64_t bad_allocs = 0;    ///< runs that ended in std::bad_alloc
  std::uint64_t errors = 0;        ///< runs that ended in cvms::Error
  std::uint64_t completed = 0;     ///< runs that completed despite a failure (result checked)
  std::map<std::string, std::uint64_t> error_categories;  ///< cvms::Error runs by category
};

/// Runs the sweep of `run` (a callable returning a value that `fingerprint`
/// accepts); `operands` fingerprints the operation's inputs (called after
/// every run, with no failing allocation). Reports each
/// finding through gtest, with the k of the failing call, and stops at the
/// first. `name` labels the messages.
template <class Run>
SweepReport sweep_allocation_failures(std::string_view name, Run run,
                                      const std::function<std::string()>& operands,
                                      SweepOptions options = {}) {
  using Result = std::decay_t<decltype(run())>;
  SweepReport report;
  const std::string operands_before = operands();
  const std::string reference = options.reference.empty() ? fingerprint(run()) : options.reference;
  if (operands() != operands_before) {
    ADD_FAILURE() << name << ": the operands changed in a run with no failure";
    return report;
  }
  for (std::uint64_t k = 1;; ++k) {
    std::optional<Result> result;
    std::string caught;
    bool bad_alloc = false;
    bool reached = false;
    std::uint64_t mapped = 0;
    {
      const FailingAllocations failing(k, options.persistent);
      try {
        result.emplace(run());
      } catch (const Error& e) {
        caught = to_string(e.category());
      } catch (const std::bad_alloc&) {
        bad_alloc = true;
      } catch (const std::exception& e) {
        caught = std::string("unexpected exception: ") + e.what();
      } catch (...) {
        caught = "unexpected exception of an unknown type";
      }
      reached = FailingAllocations::failures() > 0;
      mapped = FailingAllocations::mapped_blocks();
      if (!reached) report.allocations = FailingAllocations::calls();
    }
    if (mapped != 0) {
      ADD_FAILURE() << name << ", k = " << k << ": " << mapped
                    << " block(s) mapped past operator new, which the sweep cannot fail: smaller inputs";
      return report;
    }
    if (caught.starts_with("unexpected")) {
      ADD_FAILURE() << name << ", k = " << k << ": " << caught;
      return report;
    }
    if (!reached && !result) {
      ADD_FAILURE() << name << ", k = " << k << ": failed (" << caught << ") with no failed allocation";
      return report;
    }
    if (reached) {
      ++report.failing_runs;
      if (bad_alloc) ++report.bad_allocs;
      if (!caught.empty()) {
        ++report.errors;
        ++report.error_categories[caught];
      }
    }
    if (result) {
      if (reached) ++report.completed;
      const std::string got = fingerprint(*result);
      if (got != reference) {
        ADD_FAILURE() << name << ", k = " << k << (reached ? ": completed despite the failure with" : ": ")
                      << " a result that differs from the reference run's\nreference:\n"
                      << reference << "\ngot:\n"
                      << got;
        return report;
      }
    }
    result.reset();
    const std::string operands_after = operands();
    if (operands_after != operands_before) {
      ADD_FAILURE() << name << ", k = " << k << ": the operands changed\nbefore:\n"
                    << operands_before << "\nafter:\n"
                    << operands_after;
      return report;
    }
    if (!reached) break;
  }
  return report;
}

/// The report in one line, for the test's log.
std::string summary(std::string_view name, const SweepReport& report);

}  // namespace cvms::test
