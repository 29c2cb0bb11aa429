// SPDX-License-Identifier: MIT
// The union's boundary as fragments (boundary_fragments.hpp): each facet f
// of each piece P, minus the region C_Q that each other piece Q takes away
// from it (covering_region.hpp), each subtraction a split of convex
// polygons by Q's planes (plane_clip.hpp). Only pieces whose boxes meet
// f's box can take anything away, and the box hierarchy of the unions layer
// finds them. Before any cut the candidates' regions are gathered, and the
// first region that holds all of f ends the facet: most facets of a union
// of overlapping pieces are wholly inside one other piece, and a cut made
// before that piece is seen would be thrown away.
//
// A facet its caller proves to lie inside the set it is after (a facet
// mask) is no candidate: it gives no fragments, but its piece still covers
// the other facets as before.
//
// Threads: workers take pieces from one atomic counter and write each
// piece's fragments to its own slot; the regions of a facet are subtracted
// in piece order whatever order they were found in. The slots are then
// read in piece order, and the planes numbered in order of first use
// there, so the result is the same for every thread count.
#include "boundary_fragments.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <map>
#include <memory>
#include <numeric>
#include <string>
#include <utility>

#include "box_hierarchy.hpp"
#include "covering_region.hpp"
#include "cvms/error.hpp"
#include "piece_geometry.hpp"
#include "plane_clip.hpp"
#include "progress_reporter.hpp"
#include "worker.hpp"

namespace cvms::detail {
namespace {

// Estimated bytes of each corner a facet's clipping makes: its exact
// coordinates with their limbs, its approximation and its place in the
// polygons and the fragments. A bound on the memory and on the work.
constexpr std::uint64_t bytes_per_corner = 256;

// One facet's fragments, each as its corners.
struct FacetFragments {
  std::uint32_t facet = 0;
  std::vector<std::vector<Vec3>> polygons;
};

// The polygons' corners as exact points.
std::vector<std::vector<Vec3>> corner_lists(const ClipPoints& points, const std::vector<ClipPolygon>& polygons) {
  std::vector<std::vector<Vec3>> out;
  out.reserve(polygons.size());
  for (const ClipPolygon& polygon : polygons) {
    std::vector<Vec3>& corners = out.emplace_back();
    corners.reserve(polygon.size());
    for (const std::uint32_t corner : polygon) corners.push_back(points[corner].exact);
  }
  return out;
}

[[noreturn]] void beyond_budget(std::uint64_t budget) {
  throw Error(ErrorCategory::limit, "union_boundary_fragments: the fragments would need more than " +
                                        std::to_string(budget) + " bytes (SumLimits::max_memory_bytes, at " +
                                        std::to_string(bytes_per_corner) + " bytes per corner made)");
}

constexpr std::uint32_t no_cover = 0xffffffffU;

// What find_regions gathers for one facet, reused from facet to facet.
struct FacetScratch {
  std::vector<Sign> sides;
  SectionScratch section;
  std::vector<std::vector<ClipPlane>> regions;  // regions[0 .. used)
  std::vector<std::uint32_t> owners;            // the piece of each region
  std::size_t used = 0;
  // The pieces that last took all of a facet, the latest first:
  // neighbouring facets are often covered by the same pieces, so they are
  // tried first. Whether a facet is wholly covered does not depend on the
  // order of the tries, and the regions are put back in piece order, so
  // the result does not depend on it either.
  std::array<std::uint32_t, 4> recent_covers{no_cover, no_cover, no_cover, no_cover};
};

// Puts q first among the recent covers, keeping the others in order.
void remember_cover(FacetScratch& scratch, std::uint32_t q) {
  auto& recent = scratch.recent_covers;
  auto at = std::find(recent.begin(), recent.end(), q);
  if (at == recent.end()) at = recent.end() - 1;
  std::rotate(recent.begin(), at, at + 1);
  recent.front() = q;
}

// Sorts the regions found by their pieces.
void sort_regions(FacetScratch& scratch) {
  std::vector<std::size_t> order(scratch.used);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return scratch.owners[a] < scratch.owners[b]; });
  std::vector<std::vector<ClipPlane>> regions(scratch.used);
  std::vector<std::uint32_t> owners(scratch.used);
  for (std::size_t k = 0; k < scratch.used; ++k) {
    regions[k] = std::move(scratch.regions[order[k]]);
    owners[k] = scratch.owners[order[k]];
  }
  std::move(regions.begin(), regions.end(), scratch.regions.begin());
  std::copy(owners.begin(), owners.end(), scratch.owners.begin());
}

class FragmentWork {
 public:
  FragmentWork(std::span<const ConvexPolyhedron> pieces, const FacetMask& skip, std::uint64_t budget,
               ProgressReporter& progress)
      : pieces_(pieces),
        skip_(skip),
        progress_(progress),
        budget_(budget),
        geometry_(pieces.size()),
        slots_(pieces.size()) {}

  // The pieces' geometry (each made once, by whichever thread takes it),
  // their hierarchy, then the fragments.
  void run(unsigned threads) {
    std::atomic<std::size_t> next_geometry{0};
    run_on_threads(threads, [&](unsigned) {
      for (std::size_t p = next_geometry.fetch_add(1); p < pieces_.size(); p = next_geometry.fetch_add(1))
        geometry_[p] = piece_geometry(pieces_[p]);
    });
    std::vector<unions::OutwardBox> boxes;
    boxes.reserve(geometry_.size());
    for (const PieceGeometry& g : geometry_) boxes.push_back(g.box);
    hierarchy_ = std::make_unique<unions::BoxHierarchy>(boxes);
    run_on_threads(threads, [this](unsigned) { work(); });
  }

  // The fragments of piece p, facet by facet.
  [[nodiscard]] std::vector<FacetFragments>& slot(std::size_t p) { return slots_[p]; }
  [[nodiscard]] const PieceGeometry& geometry(std::size_t p) const { return geometry_[p]; }

 private:
  void work() {
    FacetScratch scratch;  // this thread's, kept from piece to piece
    scratch.section.start.assign(slots_.size(), 0);
    while (!stop_.load(std::memory_order_relaxed)) {
      const std::size_t p = next_.fetch_add(1);
      if (p >= slots_.size()) return;
      try {
        piece_fragments(p, scratch);
        progress_.advance(1);
      } catch (...) {
        stop_.store(true);
        throw;
      }
    }
  }

  void piece_fragments(std::size_t p, FacetScratch& scratch) {
    const PieceGeometry& g = geometry_[p];
    std::vector<std::uint32_t> near;  // pieces whose boxes meet p's
    hierarchy_->for_each_overlapping(g.box, [&](std::size_t q) {
      if (q != p) near.push_back(static_cast<std::uint32_t>(q));
      return false;
    });
    std::sort(near.begin(), near.end());
    scratch.recent_covers.fill(no_cover);
    const std::vector<char>* skip = skip_.empty() ? nullptr : &skip_[p];
    for (std::uint32_t f = 0; f < g.planes.size(); ++f) {
      if (skip != nullptr && (*skip)[f] != 0) continue;
      if (!find_regions(p, f, near, scratch)) continue;
      ClipPoints points;
      std::vector<ClipPolygon> polygons(1);
      for (std::uint32_t k = g.corner_start[f]; k < g.corner_start[f + 1]; ++k) {
        polygons[0].push_back(static_cast<std::uint32_t>(points.size()));
        points.push_back(clip_point(*g.piece, g.corners[k]));
      }
      count_corners(points.size());
      for (std::size_t r = 0; r < scratch.used && !polygons.empty(); ++r) {
        const std::size_t before = points.size();
        subtract_region(points, polygons, scratch.regions[r]);
        count_corners(points.size() - before);
      }
      if (!polygons.empty()) slots_[p].push_back({f, corner_lists(points, polygons)});
    }
  }


  // The regions that the pieces near p take away from p's facet f in part,
  // in piece order, into scratch; false if one of them takes all of it.
  // Deciding a whole cover before any polygon is cut spares the cuts that a
  // later cover would throw away.
  bool find_regions(std::size_t p, std::uint32_t f, const std::vector<std::uint32_t>& near, FacetScratch& scratch) {
    scratch.used = 0;
    const std::array<std::uint32_t, 4> recent = scratch.recent_covers;
    for (const std::uint32_t q : recent) {
      if (q != no_cover && try_piece(p, f, q, scratch) == FacetOverlap::all) {
        remember_cover(scratch, q);
        return false;
      }
    }
    for (const std::uint32_t q : near) {
      if (std::find(recent.begin(), recent.end(), q) != recent.end()) continue;
      if (try_piece(p, f, q, scratch) == FacetOverlap::all) {
        remember_cover(scratch, q);
        return false;
      }
    }
    sort_regions(scratch);
    return true;
  }

  // How piece q's covering region meets p's facet f; a region that takes a
  // part is kept in scratch.
  FacetOverlap try_piece(std::size_t p, std::uint32_t f, std::uint32_t q, FacetScratch& scratch) {
    const PieceGeometry& g = geometry_[p];
    if (q == p || !unions::overlaps(g.facet_boxes[f], geometry_[q].box)) return FacetOverlap::none;
    if (scratch.used == scratch.regions.size()) {
      scratch.regions.emplace_back();
      scratch.owners.push_back(0);
    }
    std::vector<ClipPlane>& region = scratch.regions[scratch.used];
    if (!covering_region(geometry_[q], q, q < p, g.planes[f], scratch.sides, scratch.section, region))
      return FacetOverlap::none;
    const FacetOverlap overlap = facet_overlap(region, g, f);
    if (overlap == FacetOverlap::part) scratch.owners[scratch.used++] = q;
    return overlap;
  }

  // Adds corners made to the running total, which is the same sum for any
  // order of the pieces: the total passes the budget on some thread iff it
  // does on one, so the error is the same for every thread count.
  void count_corners(std::size_t corners) {
    const std::uint64_t bytes = static_cast<std::uint64_t>(corners) * bytes_per_corner;
    if (bytes_.fetch_add(bytes, std::memory_order_relaxed) + bytes > budget_) beyond_budget(budget_);
  }

  std::span<const ConvexPolyhedron> pieces_;
  const FacetMask& skip_;
  ProgressReporter& progress_;
  std::uint64_t budget_;
  std::atomic<std::uint64_t> bytes_{0};
  std::vector<PieceGeometry> geometry_;
  std::unique_ptr<unions::BoxHierarchy> hierarchy_;
  std::vector<std::vector<FacetFragments>> slots_;
  std::atomic<std::size_t> next_{0};
  std::atomic<bool> stop_{false};
};

// Orders the planes of facets by normal, then offset, without copying them.
struct PlaneLess {
  bool operator()(const ClipPlane* a, const ClipPlane* b) const {
    if (*a->normal != *b->normal) return *a->normal < *b->normal;
    return *a->offset < *b->offset;
  }
};

// The slots, in piece order, as fragments on numbered planes.
BoundaryFragments collect(FragmentWork& work, std::size_t pieces) {
  BoundaryFragments out;
  std::map<const ClipPlane*, std::uint32_t, PlaneLess> numbers;
  for (std::size_t p = 0; p < pieces; ++p) {
    const PieceGeometry& g = work.geometry(p);
    for (FacetFragments& facet : work.slot(p)) {
      const ClipPlane& plane = g.planes[facet.facet];
      const auto [it, inserted] = numbers.try_emplace(&plane, static_cast<std::uint32_t>(out.planes.size()));
      if (inserted) out.planes.push_back({*plane.normal, *plane.offset});
      for (std::vector<Vec3>& corners : facet.polygons) out.fragments.push_back({it->second, std::move(corners)});
    }
    work.slot(p).clear();
    work.slot(p).shrink_to_fit();
  }
  return out;
}

// A mask that does not fit the pieces is a caller's error, named here
// rather than read out of bounds.
void check_mask(std::span<const ConvexPolyhedron> pieces, const FacetMask& skip) {
  bool fits = skip.size() == pieces.size();
  for (std::size_t p = 0; fits && p < pieces.size(); ++p) fits = skip[p].size() == pieces[p].num_facets();
  if (!fits)
    throw Error(ErrorCategory::invalid_argument,
                "union_boundary_fragments: the facet mask does not have one entry per facet of each piece");
}

}  // namespace

BoundaryFragments union_boundary_fragments(std::span<const ConvexPolyhedron> pieces, const Options& options,
                                           const FacetMask& skip) {
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    if (pieces[p].num_vertices() == 0)
      throw Error(ErrorCategory::invalid_argument,
                  "union_boundary_fragments: piece " + std::to_string(p) + " is empty");
  }
  if (!skip.empty()) check_mask(pieces, skip);
  ProgressReporter progress(callback_of(options.progress));
  progress.begin("union: boundary", pieces.size());
  FragmentWork work(pieces, skip, options.limits.max_memory_bytes, progress);
  work.run(thread_count(options.threads, pieces.size()));
  BoundaryFragments out = collect(work, pieces.size());
  progress.end();
  return out;
}

}  // namespace cvms::detail
