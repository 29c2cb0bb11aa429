// SPDX-License-Identifier: MIT
// The text several commands print about what they read and made: sizes,
// kinds of sets, the algorithm's statistics, times.
#pragma once

#include <chrono>
#include <iosfwd>
#include <string>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/convex_set.hpp"
#include "cvms/diagnostics.hpp"
#include "cvms/minkowski.hpp"

namespace cvms::cli {

/// "V 8 E 12 F 6".
std::string counts(const ConvexPolyhedron& p);

/// "empty set", "point", "segment", "convex polygon" or "convex polyhedron".
const char* kind(const ConvexSet& s);

/// "dimension 3, V 8 E 12 F 6"; below dimension 3, the dimension and V only.
std::string size_text(const ConvexSet& s);

/// The set's kind and size_text, and a polygon's plane, under `name` (check, diff).
void report_set(const std::string& name, const ConvexSet& set, std::ostream& report);

/// The sum's facet kinds, contributing-vertex ties and predicate counts (--stats, demo).
void print_stats(std::ostream& report, const Stats& s, const SumDiagnostics& d);

/// "12.345 ms".
std::string milliseconds(std::chrono::steady_clock::duration d);

}  // namespace cvms::cli
