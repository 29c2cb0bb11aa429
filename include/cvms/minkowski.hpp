// SPDX-License-Identifier: MIT
/// \file
/// The Minkowski sum of two convex polyhedra: one entry point, three algorithms.
#pragma once

#include <cstdint>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/diagnostics.hpp"
#include "cvms/progress.hpp"

namespace cvms {

/// Which algorithm minkowski_sum runs. All three compute the same exact
/// polyhedron (same vertex and facet sets; the numbering may differ); they
/// differ in speed.
enum class Algorithm {
  cvms,    ///< contributing vertices (paper Section 4)
  essdms,  ///< slope diagrams with contributing vertices (paper Section 5.2)
  chms,    ///< exact hull of all pairwise vertex sums (the reference oracle)
};

/// The algorithm's name as the cvms tool's --algorithm spells it: "cvms",
/// "essdms" or "chms" ("unknown" for a value outside the enum).
const char* to_string(Algorithm algorithm) noexcept;

/// Bounds on the work and memory of one Minkowski sum, checked from counts
/// the algorithm knows before it allocates the exact output: the output of
/// two convex polyhedra can have about f_A x f_B facets (two 10,000-gon
/// prisms with non-parallel axes, 3 MB of input, have 5 x 10^7, which would
/// need some 50 GB), so an unchecked sum of small files can exhaust the
/// machine. A sum beyond a limit throws Error(limit) naming the count, the
/// limit and the field to raise. CVMS and ESSDMS count their translated and
/// corner facets before building anything and stop the edge-facet search as
/// soon as its running count passes what is left, so a refused sum costs
/// the search up to the limit (about 0.5 microseconds and 48 bytes per
/// facet found), not the sum. The defaults admit every honest sum whose
/// output fits in about 4 GiB (Sphere8 + rotated Sphere8 has 1.0 x 10^6
/// facets) and refuse the prism attack above after about 2 s.
struct SumLimits {
  /// Estimated bytes of the exact output per output facet: normals, offsets,
  /// vertices (at most 2 per facet) and mesh of a ConvexPolyhedron, with the
  /// build's temporaries. At the peak: about 680 for Sphere8 +
  /// rotated Sphere8 (double coordinates), 1,140 for two 1,000-gon prisms
  /// with perpendicular axes (rationals with 40-bit denominators).
  static constexpr std::uint64_t bytes_per_output_facet = 1024;
  /// Estimated bytes CHMS needs per pairwise vertex sum: its double
  /// approximation and its entries in the hull's conflict lists (about
  /// 130), not counting the output hull.
  static constexpr std::uint64_t bytes_per_pairwise_sum = 128;

  /// Most facets the sum may have (CVMS, ESSDMS). The default, 2^26 =
  /// 67,108,864, is beyond what the default memory limit allows: it matters
  /// only when max_memory_bytes is raised.
  std::uint64_t max_output_facets = std::uint64_t{1} << 26;
  /// Most bytes the output may be estimated to need: facets times
  /// bytes_per_output_facet (CVMS, ESSDMS), pairwise sums times
  /// bytes_per_pairwise_sum (CHMS). The default, 4 GiB (2^22 = 4,194,304
  /// output facets, 2^25 = 33,554,432 pairwise sums), fits a machine with
  /// 8 GB.
  std::uint64_t max_memory_bytes = std::uint64_t{4} << 30;
  /// ESSDMS only: most (facet, facet), (facet, arc), (facet, vertex) and
  /// (arc, arc) pairs its quadratic loops may test: f_A f_B + f_A e_B +
  /// f_B e_A + f_A v_B + f_B v_A before they start, plus e_A' e_B' (the arcs
  /// that pass the pre-check) before the last one. The default, 2^34 (about
  /// 1.7 x 10^10 pairs, 1.5 minutes at 5 ns a pair), admits Sphere6 +
  /// rotated Sphere6 (2 x 10^9 pairs).
  std::uint64_t max_pair_tests = std::uint64_t{1} << 34;
};

/// How minkowski_sum computes the sum. The default is CVMS with the
/// output-sensitive searches (contributing vertices by hill-climbing, edge
/// facets by tracing Gaussian arcs) on the calling thread.
struct Options {
  Algorithm algorithm = Algorithm::cvms;  ///< which algorithm
  /// CVMS only: 1 (the default) computes everything on the calling thread;
  /// N > 1 also uses worker threads inside the call, never more threads in
  /// all than the machine has cores. The edge facets (arc walk) are traced
  /// while the calling thread finds the corner facets: by one worker for two
  /// threads, in chunks of edges shared by all N (the caller once it is done)
  /// for more. Then one worker computes the output's facet planes while the
  /// calling thread builds the vertices and the mesh and then helps with the
  /// planes. Small sums stay on the calling thread, where starting threads
  /// would cost more than it saves. The result (numbering included), Stats
  /// and the diagnostics are identical for every N.
  unsigned threads = 1;
  /// Bounds on the sum's output size, memory and (ESSDMS) work.
  SumLimits limits;
  /// When not null, the sum writes its diagnostic counters there
  /// (cvms/diagnostics.hpp); null (the default) skips nothing and costs
  /// nothing: the counters are kept either way.
  SumDiagnostics* diagnostics = nullptr;
  /// When not empty, hears the sum's progress and may stop it
  /// (cvms/progress.hpp): CVMS reports the stages "sum: facets" (edges of A
  /// searched) and "sum: output" (facet planes made), ESSDMS "sum: pairs"
  /// (facets of A tested against B), CHMS "hull" (points settled). The
  /// result does not depend on it. Empty (the default) costs nothing.
  ProgressCallback progress;
};

/// What an algorithm did: the output's facets by kind. For CVMS and
/// ESSDMS, translated + corner + edge facets equals the number of facets of
/// the result. The search's own counters are diagnostics
/// (Options::diagnostics, cvms/diagnostics.hpp).
// The deprecated fields' own initializers would warn in every
// default-constructed Stats; only reading them should.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
struct Stats {
  std::uint64_t translated_facets = 0;  ///< facets parallel to a facet of A
  std::uint64_t corner_facets = 0;      ///< facets parallel to a facet of B only
  std::uint64_t edge_facets = 0;        ///< edge(A) + edge(B) facets
  /// SumDiagnostics::contributing_ties, kept for source compatibility.
  [[deprecated("read SumDiagnostics::contributing_ties through Options::diagnostics")]]
  std::uint64_t contributing_ties = 0;
  /// SumDiagnostics::edge_candidates, kept for source compatibility.
  [[deprecated("read SumDiagnostics::edge_candidates through Options::diagnostics")]]
  std::uint64_t edge_candidates = 0;
  /// SumDiagnostics::edge_paper_rejections, kept for source compatibility.
  [[deprecated("read SumDiagnostics::edge_paper_rejections through Options::diagnostics")]]
  std::uint64_t edge_paper_rejections = 0;
  /// SumDiagnostics::predicate_filtered, kept for source compatibility.
  [[deprecated("read SumDiagnostics::predicate_filtered through Options::diagnostics")]]
  std::uint64_t predicate_filtered = 0;
  /// SumDiagnostics::predicate_exact, kept for source compatibility.
  [[deprecated("read SumDiagnostics::predicate_exact through Options::diagnostics")]]
  std::uint64_t predicate_exact = 0;
};
#pragma GCC diagnostic pop

/// The sum and how it was computed.
struct MinkowskiResult {
  ConvexPolyhedron polyhedron;  ///< A + B, with maximal facets and extreme vertices
  Stats stats;                  ///< counters of the algorithm that ran
};

/// A + B = {a + b : a in A, b in B}. Exact. Thread-safe (no shared state).
/// CVMS costs O(f_A + f_B + e_A' + k) predicates times the vertex degrees met
/// (k = the output facets, e_A' the edges of A that pass Property 1), plus the
/// climbs between neighbouring facets' answers (short for operands of
/// similar resolution; O(v) in the worst case), plus the output;
/// ESSDMS costs O(f_A f_B + f_A e_B + f_B e_A + e_A' e_B' + f_A v_B + f_B v_A).
/// \throw Error(invalid_argument) for an empty (default-constructed) operand
///   or an unknown option value.
/// \throw Error(limit) if the sum is beyond options.limits (SumLimits),
///   before the exact output is built.
/// \throw Error(cancelled) if options.progress returns false.
MinkowskiResult minkowski_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                              const Options& options = {});

/// CHMS: the exact convex hull of all v_A * v_B pairwise vertex sums.
/// Complexity: O(v_A v_B log(v_A v_B)) expected.
/// \throw Error(limit) if v_A v_B >= 2^32 - 1 (the hull's 32-bit indices), or
///   if v_A v_B x SumLimits::bytes_per_pairwise_sum exceeds
///   limits.max_memory_bytes; checked before the sums are allocated.
ConvexPolyhedron chms(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const SumLimits& limits = {});

}  // namespace cvms
