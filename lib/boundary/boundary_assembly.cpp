// SPDX-License-Identifier: MIT
// The stages of boundary_assembly.hpp, each in a file of its own:
//  1. per plane, the region's boundary as maximal segments
//     (plane_region_boundary.hpp);
//  2. the true vertices (the segments' ends), and every segment split at the
//     true vertices inside it (true_vertices.hpp);
//  3. per plane, the edges traced into loops and regions
//     (region_loops.hpp), each region triangulated without new vertices
//     (region_triangulation.hpp);
//  4. non-manifold edges and vertices split (manifold_split.hpp);
//  5. the solid's facets, shells and volume derived (SolidAccess).
// Stages 1 and 3 run over the planes on options.threads threads; each
// plane's result goes to its own slot and the slots are joined in plane
// order, so the output is the same for any number of threads.
#include "boundary_assembly.hpp"

#include <algorithm>
#include <atomic>
#include <string>

#include "cvms/error.hpp"
#include "manifold_split.hpp"
#include "plane_chart.hpp"
#include "plane_region_boundary.hpp"
#include "progress_reporter.hpp"
#include "region_loops.hpp"
#include "region_triangulation.hpp"
#include "solid_access.hpp"
#include "true_vertices.hpp"
#include "worker.hpp"

namespace cvms::detail {

namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

std::vector<std::vector<std::uint32_t>> fragments_by_plane(const BoundaryFragments& fragments) {
  std::vector<std::vector<std::uint32_t>> by_plane(fragments.planes.size());
  for (std::size_t p = 0; p < fragments.planes.size(); ++p)
    if (is_zero(fragments.planes[p].normal))
      throw Error(ErrorCategory::invalid_argument, "assemble_boundary: plane " + std::to_string(p) + " has a zero normal");
  for (std::uint32_t f = 0; f < fragments.fragments.size(); ++f) {
    const BoundaryFragment& fragment = fragments.fragments[f];
    if (fragment.plane >= fragments.planes.size() || fragment.corners.size() < 3)
      throw Error(ErrorCategory::invalid_argument,
                  "assemble_boundary: fragment " + std::to_string(f) +
                      (fragment.corners.size() < 3 ? " has fewer than three corners" : " names no plane"));
    by_plane[fragment.plane].push_back(f);
  }
  return by_plane;
}

// Calls f(i) for every i < n, on up to `threads` threads taking indices in
// turn; each call counts one unit of progress.
template <class F>
void for_each_plane(unsigned threads, std::size_t n, ProgressReporter& progress, F f) {
  std::atomic<std::size_t> next{0};
  run_on_threads(thread_count(threads, n), [&](unsigned) {
    for (std::size_t i = next++; i < n; i = next++) {
      f(i);
      progress.advance(1);
    }
  });
}

// Stage 3 for one plane: its edges, numbered locally, in the plane's chart.
Triangles triangulate_plane(const std::vector<DirectedSegment>& segments, const SegmentSplitter& splitter,
                            const std::vector<Vec3>& vertices, const Vec3& normal) {
  std::vector<std::array<std::uint32_t, 2>> edges;
  for (const DirectedSegment& s : segments) splitter.split(s, edges);
  std::vector<std::uint32_t> ids;
  ids.reserve(edges.size() * 2);
  for (const auto& e : edges) ids.insert(ids.end(), e.begin(), e.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  const auto local = [&](std::uint32_t id) {
    return static_cast<std::uint32_t>(std::lower_bound(ids.begin(), ids.end(), id) - ids.begin());
  };
  for (auto& e : edges) e = {local(e[0]), local(e[1])};
  const PlaneChart chart(normal);
  std::vector<Vec2> points;
  points.reserve(ids.size());
  for (std::uint32_t id : ids) points.push_back(chart(vertices[id]));
  Triangles triangles;
  for (const RegionLoops& region : region_loops(points, edges)) triangulate_region(points, region, triangles);
  for (auto& t : triangles)
    for (auto& c : t) c = ids[c];
  return triangles;
}

}  // namespace

Solid assemble_boundary(const BoundaryFragments& fragments, const Options& options) {
  const auto by_plane = fragments_by_plane(fragments);
  const std::size_t planes = by_plane.size();
  ProgressReporter progress(callback_of(options.progress));
  progress.begin("union: assembly", 2 * static_cast<std::uint64_t>(planes));
  std::vector<std::vector<DirectedSegment>> segments(planes);
  for_each_plane(options.threads, planes, progress, [&](std::size_t p) {
    if (!by_plane[p].empty())
      segments[p] = plane_region_boundary(fragments, by_plane[p], fragments.planes[p].normal);
  });
  std::vector<Vec3> vertices = true_vertices(segments);
  const SegmentSplitter splitter(vertices);
  std::vector<Triangles> per_plane(planes);
  for_each_plane(options.threads, planes, progress, [&](std::size_t p) {
    if (!segments[p].empty())
      per_plane[p] = triangulate_plane(segments[p], splitter, vertices, fragments.planes[p].normal);
  });
  progress.end();
  Triangles triangles;
  for (const Triangles& t : per_plane) triangles.insert(triangles.end(), t.begin(), t.end());
  if (triangles.empty()) return {};
  split_non_manifold(vertices, triangles);
  return SolidAccess::assume_valid(std::move(vertices), std::move(triangles));
}

}  // namespace cvms::detail
