// SPDX-License-Identifier: MIT
// Example: progress reports and cancellation of a long sum.
//
// An interactive program (an editor, a planner with a time budget) cannot
// freeze while an exact sum of fine meshes runs for seconds: it wants to
// show how far the sum is and to stop it when the user or a deadline says
// so. Options::progress takes a callback that hears each stage's progress
// and returns false to stop; the sum then throws cvms::Error with the
// category `cancelled` and leaves nothing behind. A std::stop_token (or any
// flag another thread sets) fits in the callback as below.
//
// Usage: progress_cancel [DEADLINE_MS]. Sums Sphere_5 and a rotated
// Sphere_5, printing each stage's end; with a deadline, the sum stops at the
// first report after it.
#include <cvms/error.hpp>
#include <cvms/minkowski.hpp>
#include <cvms/progress.hpp>
#include <cvms/shapes.hpp>
#include <chrono>
#include <iostream>
#include <stop_token>
#include <string>

int main(int argc, char** argv) {
  using Clock = std::chrono::steady_clock;
  const cvms::ConvexPolyhedron a = cvms::shapes::geodesic_sphere(5);
  const cvms::ConvexPolyhedron b = cvms::shapes::rotated_geodesic_sphere(5);

  // Another thread (a Cancel button, a watchdog) would call request_stop().
  std::stop_source cancel;
  const bool has_deadline = argc > 1;
  const auto deadline = Clock::now() + std::chrono::milliseconds(has_deadline ? std::stoll(argv[1]) : 0);

  cvms::Options options;
  options.threads = 2;  // the callback may then run on a worker, never on two threads at once
  options.progress = [&, token = cancel.get_token()](const cvms::Progress& p) {
    if (p.done == p.total) std::cout << p.stage << ": " << p.done << " of " << p.total << " done\n";
    if (has_deadline && Clock::now() >= deadline) cancel.request_stop();
    return !token.stop_requested();
  };
  try {
    const cvms::MinkowskiResult sum = cvms::minkowski_sum(a, b, options);
    std::cout << "sum: " << sum.polyhedron.num_vertices() << " vertices, " << sum.polyhedron.num_facets()
              << " facets\n";
  } catch (const cvms::Error& e) {
    if (e.category() != cvms::ErrorCategory::cancelled) throw;
    std::cout << "sum cancelled (" << e.what() << ")\n";
  }
  return 0;
}
