// SPDX-License-Identifier: MIT
// CVMS: the Minkowski sum of two convex polyhedra by contributing vertices
// (paper Section 4, Algorithm 1 and Section 4.3), exact in every degenerate
// case.
//
// Summary. Every facet of S = A + B is one of
//  - a translated facet, parallel to a facet f_A of A: f_A + v, f_A + e_B or
//    f_A + f_B, where v, e_B, f_B is the face of B maximising <x, n(f_A)>,
//    i.e. the contributing vertices of f_A (one, two or >= 3 of them);
//  - a corner facet, parallel to a facet f_B of B that has no facet of A with
//    the same normal (Property 2): f_B + v or f_B + e_A;
//  - an edge facet e_A + e_B, for non-parallel edges whose Gaussian arcs
//    cross at a point interior to both arcs.
// On the Gaussian map, these are the vertices of the overlay of the maps of A
// and B: facet points of A (translated), facet points of B not on a facet
// point of A (corner; on an arc of A they give f_B + e_A), and proper arc
// crossings (edge facets). A facet point of B lying on an arc of A is a
// vertex of the overlay already, so it never yields an edge facet.
//
// No two output facets share a normal, so none are coplanar and the stitched
// result has maximal facets: normals of A's facets are pairwise distinct, the
// corner facets are exactly the facets of B whose normal is no normal of A,
// and an edge facet's normal is a point interior to an arc of A and to an arc
// of B; such a point lies on no other arc and on no facet point of A or of B
// (the arcs of one polyhedron meet only at their end points, the facet
// points), so it is the crossing of exactly one pair of arcs and differs from
// every facet normal of A and B.
#include "cvms_algorithm.hpp"

#include <algorithm>
#include <atomic>
#include <span>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "arc_trace.hpp"
#include "contributing_vertices.hpp"
#include "cvms/error.hpp"
#include "filtered_predicates.hpp"
#include "output_budget.hpp"
#include "polyhedron_builder.hpp"
#include "stitch.hpp"
#include "worker.hpp"

namespace cvms::detail {
namespace {

// The output budget of step 3: the edge facets the search may find after the
// translated and corner facets, which are counted before it starts. The
// search checks after each edge of A, so it holds at most one edge's facets
// (<= e_B) beyond the allowance when it stops; the count where it stops
// depends only on the input, so threaded and sequential runs stop alike.
struct EdgeFacetBudget {
  const OutputBudget& budget;
  std::uint64_t translated;
  std::uint64_t corner;

  void check(std::uint64_t edge_facets_found) const { budget.check(translated, corner, edge_facets_found); }
  [[nodiscard]] bool allows(std::uint64_t edge_facets_found) const {
    return saturating_sum(saturating_sum(translated, corner), edge_facets_found) <= budget.max_facets();
  }
};

// The halfedge of each edge of p that passes Property 1.
std::vector<HalfedgeId> edges_passing_property1(const ConvexPolyhedron& p, const ContributingVertices& cv) {
  std::vector<HalfedgeId> out;
  for (EdgeId e : p.mesh().edges()) {
    const HalfedgeId h = Mesh::halfedge(e);
    if (may_produce_edge_facets(p, cv, h)) out.push_back(h);
  }
  return out;
}

// Edges of A whose edge facets are searched between two progress reports:
// the walk costs a few microseconds an edge, the paper's search a scan of B.
constexpr std::size_t walk_edges_per_report = 256;
constexpr std::size_t paper_edges_per_report = 8;

// Step 3 with the paper's search (Section 4.3, Eqs. 4 and 5), decided exactly.
//
// Conventions (lib/minkowski/arc_crossing.hpp). For a halfedge h with
// d = to(h) - from(h), n1 the normal of face(h) and n2 that of
// face(twin(h)), the Gaussian arc of the edge runs from n1 to n2
// counterclockwise about d.
//
// The exact test. e_A + e_B is a facet of S iff the arcs cross at a point
// interior to both. The great circles of the arcs meet at +-n with
// n = cross(d_A, d_B) (n = 0: parallel edges, same great circle, no edge
// facet). By the reduction of Eq. 9 in arc_crossing.hpp (with e = d_A), n is
// strictly inside the arc of h_B iff face(h_B) is strictly visible from d_A
// (<n1_B, d_A> < 0) and face(twin(h_B)) strictly invisible (<n2_B, d_A> > 0,
// paper Eq. 4). Hence the candidates are exactly the horizon edges of B,
// oriented so that the invisible facet is on the right, with
// n = cross(d_A, d_B) as the candidate outward normal; the paper's
// normal-orientation criterion (Eq. 5, here det[n1_A, n, d_A] > 0 and
// det[n, n2_A, d_A] > 0; the paper writes "< 0" with e_A oriented as
// cross(n2_A, n1_A)) then decides whether n is strictly inside the arc
// of e_A. Both conditions strict <=> proper crossing <=> edge facet.
//
// Where the paper's criterion alone is wrong: the paper counts as horizon an
// edge between an invisible facet and a facet *parallel* to d_A (<n, d_A> =
// 0). Then the parallel facet f_B has its normal on the great circle of e_A
// and, if Eq. 5 holds, strictly inside the arc of e_A: the facet of S with
// that normal is the corner facet f_B + e_A (two contributing vertices), and
// the paper would add e_A + e_B, a coplanar piece of it, a second time.
// Property 1 does not always exclude this (the other facet of e_B can have
// contributing vertices far from e_A). We count such candidates in
// stats.edge_paper_rejections and reject them. (With n = 0 the edges are
// parallel: then both facets of e_B are parallel to d_A, so e_B is never a
// horizon edge and the is_parallel test is implied.)
void edge_facets_paper(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                       const std::vector<HalfedgeId>& edges_a, const std::vector<HalfedgeId>& edges_b,
                       const EdgeFacetBudget& budget, SumFacetBuilder& out, SumCounters& stats,
                       ProgressReporter& progress) {
  const Mesh& ma = a.mesh();
  const Mesh& mb = b.mesh();
  std::vector<Sign> visibility(b.num_facets());  // sign of <d_A, n(f_B)>: positive = invisible
  std::uint64_t found = 0;
  std::size_t searched = 0;
  for (HalfedgeId ha : edges_a) {
    budget.check(found);
    // Each edge scans all of B: a few of them are a report's worth.
    if (++searched % paper_edges_per_report == 0) progress.reach(Mesh::edge(ha).index());
    const Vec3 da = a.edge_vector(ha);
    const ApproxVec3 da_approx = ApproxVec3::of(da);
    const Vec3Ref da_ref{da, da_approx};
    for (FaceId fb : mb.faces()) visibility[fb.index()] = sign_dot(da_ref, detail::normal_ref(b, fb));
    const Vec3Ref n1 = detail::normal_ref(a, ma.face(ha));
    const Vec3Ref n2 = detail::normal_ref(a, ma.face(Mesh::twin(ha)));
    for (HalfedgeId hb : edges_b) {
      const Sign left = visibility[mb.face(hb).index()];
      const Sign right = visibility[mb.face(Mesh::twin(hb)).index()];
      if ((left == Sign::positive) == (right == Sign::positive)) continue;  // not a horizon edge
      // Orient e_B so that its invisible facet is on the right.
      const HalfedgeId g = (right == Sign::positive) ? hb : Mesh::twin(hb);
      const Sign other = (right == Sign::positive) ? left : right;
      ++stats.edge_candidates;
      const Vec3 n = cross(da, b.edge_vector(g));
      const ApproxVec3 n_approx = ApproxVec3::of(n);
      const Vec3Ref n_ref{n, n_approx};
      const bool normal_orientation = sign_triple(n1, n_ref, da_ref) == Sign::positive &&
                                      sign_triple(n_ref, n2, da_ref) == Sign::positive;  // Eq. 5
      if (!normal_orientation) continue;
      if (other == Sign::zero) {
        ++stats.edge_paper_rejections;
        continue;
      }
      out.add_edge_plus_edge(ha, g, Sign::positive);
      ++stats.edge_facets;
      ++found;
    }
  }
  budget.check(found);
}

}  // namespace

namespace {

// The edge facets of the edge of ha (which passes Property 1) by the arc
// walk, added to out; returns their number. The walk meets the edges of B in
// arc order; sorting them by edge index emits the facets in the paper
// search's order, so both modes build the identical polyhedron.
std::size_t add_traced_facets(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                              const ContributingVertices& cv_a, HalfedgeId ha, ArcTraceScratch& scratch,
                              SumFacetBuilder& out, std::uint64_t& steps) {
  const Mesh& ma = a.mesh();
  std::vector<HalfedgeId>& crossed = scratch.crossed;
  crossed.clear();
  trace_edge_facets(a, ha, b, cv_a.of(ma.face(ha)), cv_a.of(ma.face(Mesh::twin(ha))), scratch, steps);
  std::sort(crossed.begin(), crossed.end(),
            [](HalfedgeId x, HalfedgeId y) { return Mesh::edge(x) < Mesh::edge(y); });
  for (HalfedgeId g : crossed) out.add_edge_plus_edge(ha, g, Sign::positive);
  return crossed.size();
}

// Step 3 with the arc walk, for the edges of A that pass Property 1.
void edge_facets_walk(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const ContributingVertices& cv_a,
                      const EdgeFacetBudget& budget, SumFacetBuilder& out, SumCounters& stats,
                      ProgressReporter& progress) {
  ArcTraceScratch scratch;
  std::uint64_t found = 0;
  std::size_t traced = 0;
  for (HalfedgeId ha : edges_passing_property1(a, cv_a)) {
    budget.check(found);
    if (++traced % walk_edges_per_report == 0) progress.reach(Mesh::edge(ha).index());
    found += add_traced_facets(a, b, cv_a, ha, scratch, out, stats.edge_candidates);
  }
  stats.edge_facets += found;
  budget.check(found);
}

// Step 3 with the arc walk on several threads: the edges in chunks handed
// out in order by one atomic counter, each traced into the builder of the
// thread that takes it, and merged in chunk order, which is the order one
// thread gives.
//
// The chunks are of all edges of A, Property 1 tested by the thread that
// takes them, so that no serial pass precedes the threads. The budget. A
// thread takes no chunk once the facets found by all exceed the allowance,
// and finishes the chunk it has, so the chunks traced are always the first
// ones, in full: merge() replays one thread's checks on their per-edge
// counts and throws the identical error where one thread would (an edge that
// fails Property 1 adds nothing, so checking before it too repeats the
// previous check). At most one chunk per thread is traced beyond that point.
class ThreadedTrace {
 public:
  ThreadedTrace(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const ContributingVertices& cv_a,
                const EdgeFacetBudget& budget, unsigned threads, ProgressReporter& progress)
      : a_(a),
        b_(b),
        cv_a_(cv_a),
        budget_(budget),
        progress_(progress),
        facets_of_edge_(a.num_edges()),
        chunk_ends_((facets_of_edge_.size() + chunk_size - 1) / chunk_size) {
    // One thread per chunk at most, the caller included.
    const std::size_t lanes = std::min<std::size_t>(threads, chunk_ends_.size() + 1);
    lanes_.reserve(lanes);
    for (std::size_t i = 0; i < lanes; ++i) lanes_.emplace_back(a, b);
  }

  [[nodiscard]] unsigned threads() const noexcept { return static_cast<unsigned>(lanes_.size()); }

  // Traces chunks until none is left or the budget is spent. \pre thread < threads.
  void run(unsigned thread) {
    Lane& lane = lanes_[thread];
    for (;;) {
      if (!budget_.allows(found_.load(std::memory_order_relaxed))) return;
      const std::size_t c = next_chunk_.fetch_add(1, std::memory_order_relaxed);
      if (c >= chunk_ends_.size()) return;
      if (c % chunks_per_report == 0) progress_.reach(c * chunk_size);
      std::uint64_t found = 0;
      for (std::size_t e = c * chunk_size; e < std::min((c + 1) * chunk_size, facets_of_edge_.size()); ++e) {
        const HalfedgeId ha = Mesh::halfedge(EdgeId(static_cast<std::uint32_t>(e)));
        if (!may_produce_edge_facets(a_, cv_a_, ha)) continue;
        facets_of_edge_[e] = add_traced_facets(a_, b_, cv_a_, ha, lane.scratch, lane.out, lane.steps);
        found += facets_of_edge_[e];
      }
      chunk_ends_[c] = {thread, lane.out.num_facets()};
      found_.fetch_add(found, std::memory_order_relaxed);
    }
  }

  // After every run() returned: the facets into out, in one thread's order,
  // and the counts into stats. \throw Error(limit) as edge_facets_walk.
  void merge(SumFacetBuilder& out, SumCounters& stats) const {
    std::uint64_t found = 0;
    for (const std::size_t n : facets_of_edge_) {
      budget_.check(found);
      found += n;
    }
    budget_.check(found);
    std::vector<std::size_t> merged(lanes_.size(), 0);  // facets of each lane merged so far
    for (const ChunkEnd& end : chunk_ends_) {
      out.append(lanes_[end.thread].out, merged[end.thread], end.facets);
      merged[end.thread] = end.facets;
    }
    for (const Lane& lane : lanes_) stats.edge_candidates += lane.steps;
    stats.edge_facets += found;
  }

 private:
  static constexpr std::size_t chunk_size = 64;
  static constexpr std::size_t chunks_per_report = walk_edges_per_report / chunk_size;
  struct Lane {
    Lane(const ConvexPolyhedron& a, const ConvexPolyhedron& b) : out(a, b) {}
    SumFacetBuilder out;
    std::uint64_t steps = 0;
    ArcTraceScratch scratch;
  };
  // Where a chunk's facets end in the builder of the thread that traced it
  // (they start where that thread's previous chunk ended).
  struct ChunkEnd {
    unsigned thread = 0;
    std::size_t facets = 0;
  };

  const ConvexPolyhedron& a_;
  const ConvexPolyhedron& b_;
  const ContributingVertices& cv_a_;
  const EdgeFacetBudget& budget_;
  ProgressReporter& progress_;
  std::vector<std::size_t> facets_of_edge_;  // by edge of A, each written by the thread tracing it
  std::vector<ChunkEnd> chunk_ends_;         // each written by the thread tracing the chunk
  std::vector<Lane> lanes_;
  std::atomic<std::size_t> next_chunk_{0};
  std::atomic<std::uint64_t> found_{0};
};

// Options::threads, but no more threads than cores unless the research
// options ask (WorkerMinimums::oversubscribe).
unsigned usable_threads(const Options& options, const ResearchOptions& research) {
  const unsigned cores = core_count();
  if (research.worker_minimums.oversubscribe || cores == 0) return options.threads;
  return std::min(options.threads, cores);
}

// The search modes are plain enums a caller may set to anything.
void check_search_modes(const ResearchOptions& research) {
  if (research.contributing_vertex_search != ContributingVertexSearch::walk &&
      research.contributing_vertex_search != ContributingVertexSearch::scan) {
    throw Error(ErrorCategory::invalid_argument,
                "minkowski_sum: unknown contributing vertex search " +
                    std::to_string(static_cast<int>(research.contributing_vertex_search)));
  }
  if (research.edge_facet_search != EdgeFacetSearch::paper &&
      research.edge_facet_search != EdgeFacetSearch::walk) {
    throw Error(ErrorCategory::invalid_argument,
                "minkowski_sum: unknown edge facet search " +
                    std::to_string(static_cast<int>(research.edge_facet_search)));
  }
}

// The contributing vertices of every facet of p in q, by walking (in the
// pieces of `split`) or by the paper's scan. partner[f], if partner is
// non-empty and it is valid, is the facet of q with f's normal: its vertices
// are the list, with no search.
ContributingVertices find_contributing_vertices(const ConvexPolyhedron& p, const ConvexPolyhedron& q,
                                                std::span<const FaceId> partner, bool walk, WalkSplit split) {
  ContributingVertices cv(p.num_facets());
  if (walk) {
    contributing_vertices_walk(p, q, partner, cv, split);
    return cv;
  }
  std::vector<VertexId> list;
  for (FaceId f : p.mesh().faces()) {
    const FaceId g = partner.empty() ? FaceId() : partner[f.index()];
    if (g.is_valid()) {
      sorted_facet_vertices(q, g, list);
    } else {
      maximising_vertices(q, detail::normal_ref(p, f), list);
    }
    cv.append(list);
  }
  return cv;
}

// Step 1: translated facets. Returns partner: partner[f_B] is the facet of A
// with the same normal, if any (then f_B contributes with it, Property 2).
std::vector<FaceId> add_translated_facets(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                                          const ContributingVertices& cv_a, SumFacetBuilder& out,
                                          SumCounters& stats) {
  std::vector<FaceId> partner(b.num_facets());
  for (FaceId fa : a.mesh().faces()) {
    const std::span<const VertexId> c = cv_a.of(fa);
    if (c.size() == 1) {
      out.add_facet_plus_vertex(Operand::a, fa, c[0]);
    } else if (c.size() == 2) {
      out.add_facet_plus_edge(Operand::a, fa, c[0], c[1]);
      ++stats.contributing_ties;
    } else {
      // Three or more maximisers span the facet of B supporting B in the
      // direction of n(fa) (an edge has only two vertices, all being
      // extreme): its primitive normal is n(fa), and it is incident to c[0].
      const FaceId fb = facet_with_normal(b, c[0], detail::normal_ref(a, fa));
      partner[fb.index()] = fa;
      out.add_facet_plus_facet(fa, fb);
      ++stats.contributing_ties;
    }
    ++stats.translated_facets;
  }
  return partner;
}

// The number of corner facets step 2 will add: the facets of B without a
// partner.
std::uint64_t count_corner_facets(std::span<const FaceId> partner) {
  return static_cast<std::uint64_t>(
      std::count_if(partner.begin(), partner.end(), [](FaceId f) { return !f.is_valid(); }));
}

// Step 2: corner facets, from the facets of B without a partner.
void add_corner_facets(const ConvexPolyhedron& b, const ContributingVertices& cv_b,
                       std::span<const FaceId> partner, SumFacetBuilder& out, SumCounters& stats) {
  for (FaceId fb : b.mesh().faces()) {
    if (partner[fb.index()].is_valid()) {
      ++stats.contributing_ties;
      continue;
    }
    // One or two contributing vertices: three or more would mean a facet of
    // A with the same (primitive) normal, which step 1 paired with fb.
    const std::span<const VertexId> c = cv_b.of(fb);
    if (c.size() == 1) {
      out.add_facet_plus_vertex(Operand::b, fb, c[0]);
    } else {
      out.add_facet_plus_edge(Operand::b, fb, c[0], c[1]);
      ++stats.contributing_ties;
    }
    ++stats.corner_facets;
  }
}

SumFacetBuilder cvms_facets_reported(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                                     const Options& options, const ResearchOptions& research,
                                     SumCounters& stats, ProgressReporter& progress) {
  check_search_modes(research);
  const bool walk_vertices = research.contributing_vertex_search == ContributingVertexSearch::walk;
  SumFacetBuilder out(a, b);

  // A's walk is the one step before the threads part ways: its pieces share
  // them. B's walk overlaps step 3 on one thread, in one piece.
  const unsigned threads = usable_threads(options, research);
  const bool large = std::min<std::size_t>(a.num_edges(), b.num_facets()) >= research.worker_minimums.trace;
  const WalkSplit split_a{walk_pieces(a.num_facets(), research.walk_piece_facets), large ? threads : 1};
  const WalkSplit split_b{1, 1};
  const ContributingVertices cv_a = find_contributing_vertices(a, b, {}, walk_vertices, split_a);
  const std::vector<FaceId> partner = add_translated_facets(a, b, cv_a, out, stats);

  // The translated and corner facets are known now, before any of step 2
  // and 3's output exists: checked at once, and step 3 stops once its
  // running count passes what is left (output_budget.hpp).
  const OutputBudget output_budget(options.limits, "cvms");
  const EdgeFacetBudget budget{output_budget, a.num_facets(), count_corner_facets(partner)};
  budget.check(0);

  // Step 2. The contributing vertices of a facet of B that has a partner are
  // the vertices of the partner (the face of A supporting A in that
  // direction); we record them for Property 1 without a search.
  auto corner_facets = [&] {
    const ContributingVertices cv_b = find_contributing_vertices(b, a, partner, walk_vertices, split_b);
    add_corner_facets(b, cv_b, partner, out, stats);
    return cv_b;
  };

  // Step 3: edge facets, from the edges that pass Property 1 on both sides.
  // The arc walk needs only the contributing vertices of A's facets: with
  // threads > 1, workers trace the edge facets while this thread does step 2,
  // and they are appended after step 2's facets in the order one thread
  // gives. Two threads: one worker traces every edge into a builder of its
  // own. More: all trace chunks of edges after step 2 (ThreadedTrace), which
  // on two cores is no faster, and in some runs slower (its workers'
  // malloc arenas: docs/performance.md), hence only with more cores.
  if (threads > 1 && research.edge_facet_search == EdgeFacetSearch::walk && large) {
    if (threads == 2) {
      SumFacetBuilder tracer_out(a, b);
      SumCounters tracer_stats;
      Worker tracer;  // after what it writes: destroyed (joined) first
      bool refused = false;
      try {
        tracer.start([&] { edge_facets_walk(a, b, cv_a, budget, tracer_out, tracer_stats, progress); });
      } catch (const std::system_error&) {
        refused = true;  // no thread to be had now: this one traces after step 2, the same facets
      }
      corner_facets();
      if (refused) {
        edge_facets_walk(a, b, cv_a, budget, tracer_out, tracer_stats, progress);
      } else {
        tracer.join();  // its predicates count as this thread's
      }
      out.append(tracer_out, 0, tracer_out.num_facets());
      stats.edge_candidates += tracer_stats.edge_candidates;
      stats.edge_facets += tracer_stats.edge_facets;
      return out;
    }
    ThreadedTrace trace(a, b, cv_a, budget, threads, progress);
    run_on_threads(trace.threads(), [&](unsigned thread) {
      if (thread == 0) corner_facets();
      trace.run(thread);
    });
    trace.merge(out, stats);
    return out;
  }
  const ContributingVertices cv_b = corner_facets();
  if (research.edge_facet_search == EdgeFacetSearch::paper) {
    const std::vector<HalfedgeId> edges_a = edges_passing_property1(a, cv_a);
    const std::vector<HalfedgeId> edges_b = edges_passing_property1(b, cv_b);
    edge_facets_paper(a, b, edges_a, edges_b, budget, out, stats, progress);
  } else {
    edge_facets_walk(a, b, cv_a, budget, out, stats, progress);
  }
  return out;
}

}  // namespace

ConvexPolyhedron cvms_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Options& options,
                          const ResearchOptions& research, SumCounters& stats) {
  ProgressReporter progress(callback_of(options.progress));
  const SumFacetBuilder facets = cvms_facets(a, b, options, research, stats, &progress);
  const bool large = facets.num_facets() >= research.worker_minimums.output_facets;
  return facets.build(large ? usable_threads(options, research) : 1, &progress);
}

SumFacetBuilder cvms_facets(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Options& options,
                            const ResearchOptions& research, SumCounters& stats, ProgressReporter* reporter) {
  ProgressReporter silent(nullptr);
  ProgressReporter& progress = reporter != nullptr ? *reporter : silent;
  progress.begin("sum: facets", a.num_edges());
  SumFacetBuilder out = cvms_facets_reported(a, b, options, research, stats, progress);
  progress.end();
  return out;
}

}  // namespace cvms::detail
