// SPDX-License-Identifier: MIT
// Auto-partition of the bounding box by the solid's facet planes.
//
// Each node is a convex cell with the boundary fragments (parts of the
// solid's triangles) inside it. A node is split by the plane of one of its
// fragments: fragments on that plane are used up there, the others go to
// the side they lie on or are cut in two. A part with no fragment left holds
// no boundary in its interior, so it is wholly inside or wholly outside the
// solid; and it touches the chosen fragment, which lies in the whole cross
// section of the parent cell: behind that fragment (against its outward
// normal) the solid is inside, in front of it outside. So a fragment-free
// part behind the splitting fragment is an inside cell, in front an outside
// one. Every split uses up at least one fragment and a fragment is only cut
// by planes other than its own, so the partition is finite.
//
// Which plane: a plane holding a facet on a reflex edge when there is one
// (those are the cuts a convex decomposition cannot avoid), and among the
// candidates the one that cuts the fewest fragments (fewer fragments, fewer
// cells). At most kCandidates planes are scored per node, chosen evenly over
// the sorted candidates, each scored on at most kScored fragments, so the
// choice costs O(kCandidates * kScored) and the split O(fragments).
//
// Before any facet plane, a free plane (free_planes.hpp, no facet on it)
// that cuts none of the node's fragments and has some of them strictly on
// each side: the split then makes no new fragment, each fragment goes whole
// to one part, and both parts keep fragments, so neither is taken for an
// inside or outside cell here and the classification above stays as it is.
// Each part has fewer fragments than the node, and a plane cannot split a
// cell that lies on one side of it again, so the partition stays finite. A
// free plane with all of a node's fragments on one closed side is useless
// for the node's whole subtree (the parts' fragments lie in the node's) and
// is dropped from it.
//
// A node whose part of the solid is convex ends there as one inside cell
// (convex_part.hpp), instead of being peeled one facet plane at a time: on
// a solid that is convex away from a few reflex edges, the cells away from
// them end after a few splits, not after one split per facet. The test costs
// O(m log m) for a node of m fragment points, so it is tried only at nodes
// of at least kTestFrom fragments (a smaller node ends after a few splits
// anyway, cheaper than an exact hull), with no fragment on a reflex plane
// (there it would mostly fail), and after it fails at a node of m
// fragments, the node's subtree tries it again only at nodes of at most
// m / 2 fragments: along every path the tested sizes halve, so the tests
// cost O(log) times the work of the splits.
#include "auto_partition.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "convex_cell.hpp"
#include "convex_part.hpp"
#include "cvms/error.hpp"
#include "free_planes.hpp"

namespace cvms::decomposition {
namespace {

constexpr std::size_t kCandidates = 12;
constexpr std::size_t kScored = 256;
constexpr std::size_t kTestFrom = 64;
// A rough size of one exact point in a cell or a fragment: three small
// rationals with their limbs and the bookkeeping beside them.
constexpr std::uint64_t kPointBytes = 256;

struct Node {
  Cell cell;
  std::vector<Fragment> fragments;
  std::vector<std::uint32_t> free;  // table indices of the free planes still worth trying
  std::size_t test_at = SIZE_MAX;   // try convex_part at no more fragments than this
};

std::uint64_t node_bytes(const Node& node) {
  std::uint64_t points = node.cell.vertices.size();
  for (const Fragment& f : node.fragments) points += f.points.size();
  return points * kPointBytes + node.fragments.size() * sizeof(Fragment) + sizeof(Node);
}

struct Splitter {
  std::uint32_t plane = 0;
  int side = 1;
};

// The fragments a plane cuts, among at most kScored of them spread evenly
// over the node's list (the score only ranks candidates; the split itself
// tests every fragment).
std::size_t count_cuts(const std::vector<Fragment>& fragments, const Plane& plane) {
  std::size_t cuts = 0;
  const std::size_t scored = std::min(fragments.size(), kScored);
  for (std::size_t k = 0; k < scored; ++k) {
    const Fragment& f = fragments[k * fragments.size() / scored];
    bool back = false, front = false;
    for (const Vec3& p : f.points) {
      int s = oriented_side(plane, 1, p);
      back = back || s < 0;
      front = front || s > 0;
      if (back && front) break;
    }
    if (back && front) ++cuts;
  }
  return cuts;
}

Splitter choose_splitter(const std::vector<Fragment>& fragments, const BoundaryPlanes& planes) {
  std::vector<std::uint32_t> all;
  all.reserve(fragments.size());
  for (const Fragment& f : fragments) all.push_back(f.plane);
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  std::vector<std::uint32_t> reflex;
  for (std::uint32_t p : all)
    if (planes.reflex_plane[p] != 0) reflex.push_back(p);
  const std::vector<std::uint32_t>& pool = reflex.empty() ? all : reflex;
  std::size_t count = std::min(pool.size(), kCandidates);
  std::uint32_t best = pool[0];
  std::size_t best_cuts = static_cast<std::size_t>(-1);
  for (std::size_t k = 0; k < count; ++k) {
    std::uint32_t candidate = pool[k * pool.size() / count];
    std::size_t cuts = count_cuts(fragments, planes.planes[candidate]);
    if (cuts < best_cuts) {
      best_cuts = cuts;
      best = candidate;
    }
  }
  for (const Fragment& f : fragments)
    if (f.plane == best) return Splitter{best, f.side};
  return Splitter{best, 1};
}

// Which closed sides of `plane` a fragment has points strictly on.
struct Sides {
  bool back = false;
  bool front = false;
};

Sides fragment_sides(const Fragment& fragment, const Plane& plane) {
  Sides sides;
  for (const Vec3& p : fragment.points) {
    const int s = oriented_side(plane, 1, p);
    sides.back = sides.back || s < 0;
    sides.front = sides.front || s > 0;
    if (sides.back && sides.front) break;
  }
  return sides;
}

// The first of node.free that cuts no fragment and has fragments strictly
// on both sides, or UINT32_MAX; the planes with every fragment on one side
// are dropped from node.free on the way.
std::uint32_t free_cut(Node& node, const std::vector<Plane>& planes) {
  std::size_t kept = 0;
  std::uint32_t chosen = UINT32_MAX;
  for (std::size_t k = 0; k < node.free.size(); ++k) {
    const std::uint32_t candidate = node.free[k];
    if (chosen == UINT32_MAX) {
      Sides all;
      bool cuts = false;
      for (const Fragment& f : node.fragments) {
        const Sides sides = fragment_sides(f, planes[candidate]);
        cuts = sides.back && sides.front;
        if (cuts) break;
        all.back = all.back || sides.back;
        all.front = all.front || sides.front;
      }
      if (!cuts && !(all.back && all.front)) continue;  // useless below this node
      if (!cuts) {
        chosen = candidate;
        continue;  // used here: no part needs it again
      }
    }
    node.free[kept++] = candidate;
  }
  node.free.resize(kept);
  return chosen;
}

[[noreturn]] void memory_limit(std::uint64_t needed, std::uint64_t limit) {
  throw Error(ErrorCategory::limit,
              "convex_decomposition: the partition would need about " + std::to_string(needed) +
                  " bytes of working memory, more than max_memory_bytes = " + std::to_string(limit));
}

bool on_reflex_plane(const std::vector<Fragment>& fragments, const BoundaryPlanes& planes) {
  return std::any_of(fragments.begin(), fragments.end(),
                     [&](const Fragment& f) { return planes.reflex_plane[f.plane] != 0; });
}

// The node's part of the solid as one inside cell, when convex_part finds it
// convex and the node is due for the test; else nothing, and the node's
// subtree is due again at half its fragments.
std::optional<std::vector<Vec3>> finished_cell(Node& node, const BoundaryPlanes& planes,
                                              const ProgressCallback& callback) {
  const std::size_t m = node.fragments.size();
  if (m < kTestFrom || m > node.test_at || on_reflex_plane(node.fragments, planes)) return std::nullopt;
  std::optional<std::vector<Vec3>> part = convex_part(node.cell, node.fragments, planes.planes, callback);
  if (!part) node.test_at = node.fragments.size() / 2;
  return part;
}

Node root_node(const Solid& solid, BoundaryPlanes& planes, const std::vector<Plane>& free) {
  auto vertices = solid.vertices();
  auto triangles = solid.triangles();
  Vec3 lo = vertices[triangles[0][0]], hi = lo;
  for (const auto& tri : triangles)
    for (std::uint32_t v : tri)
      for (int axis = 0; axis < 3; ++axis) {
        if (vertices[v][axis] < lo[axis]) lo[axis] = vertices[v][axis];
        if (hi[axis] < vertices[v][axis]) hi[axis] = vertices[v][axis];
      }
  Node root;
  auto sorted = static_cast<std::uint32_t>(planes.planes.size());
  root.cell = box_cell(lo, hi, planes.planes, sorted);
  for (const Plane& plane : free) root.free.push_back(plane_index(planes.planes, sorted, plane));
  planes.reflex_plane.resize(planes.planes.size(), 0);
  root.fragments.reserve(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    Fragment f;
    for (std::uint32_t v : triangles[t]) f.points.push_back(vertices[v]);
    f.plane = planes.triangle_plane[t];
    f.side = planes.triangle_side[t];
    root.fragments.push_back(std::move(f));
  }
  return root;
}

}  // namespace

std::vector<std::vector<Vec3>> inside_cells(const Solid& solid, BoundaryPlanes& planes,
                                            const DecompositionLimits& limits,
                                            detail::ProgressReporter& progress, const ProgressCallback& callback) {
  const std::uint64_t root_estimate =
      (std::uint64_t{8} + 3 * std::uint64_t{solid.triangles().size()}) * kPointBytes +
      solid.triangles().size() * sizeof(Fragment);
  if (root_estimate > limits.max_memory_bytes) memory_limit(root_estimate, limits.max_memory_bytes);

  progress.begin("decomposition: partition", 1);
  std::vector<std::vector<Vec3>> inside;
  std::vector<Node> stack;
  stack.push_back(root_node(solid, planes, free_planes(solid, planes)));
  std::uint64_t live = node_bytes(stack.back());
  while (!stack.empty()) {
    progress.advance(0);
    Node node = std::move(stack.back());
    stack.pop_back();
    live -= std::min(live, node_bytes(node));
    if (std::optional<std::vector<Vec3>> part = finished_cell(node, planes, callback)) {
      live += part->size() * kPointBytes;
      inside.push_back(std::move(*part));
      continue;
    }
    const std::uint32_t free = free_cut(node, planes.planes);
    const Splitter s = free != UINT32_MAX ? Splitter{free, 1} : choose_splitter(node.fragments, planes);
    const Plane& plane = planes.planes[s.plane];

    Node back, front;
    for (Fragment& f : node.fragments) {
      if (f.plane == s.plane) continue;  // on the splitting plane: used up here
      FragmentSplit parts = split_fragment(std::move(f), plane, s.side);
      if (parts.has_back) back.fragments.push_back(std::move(parts.back));
      if (parts.has_front) front.fragments.push_back(std::move(parts.front));
    }
    CellSplit cells = split_cell(std::move(node.cell), planes.planes, s.plane, s.side);
    back.cell = std::move(cells.back);
    front.cell = std::move(cells.front);
    back.free = node.free;
    front.free = std::move(node.free);
    back.test_at = front.test_at = node.test_at;
    node = Node{};

    std::uint64_t added = node_bytes(back) + node_bytes(front);
    if (live + added > limits.max_memory_bytes) memory_limit(live + added, limits.max_memory_bytes);
    // Push front first so that the back part is taken next (depth first,
    // back before front: a fixed order, so the output is deterministic).
    if (!front.cell.vertices.empty() && !front.fragments.empty()) {
      live += node_bytes(front);
      stack.push_back(std::move(front));
    }
    if (!back.cell.vertices.empty()) {
      if (back.fragments.empty()) {
        std::vector<Vec3> points;
        points.reserve(back.cell.vertices.size());
        for (CellVertex& v : back.cell.vertices) points.push_back(std::move(v.point));
        live += points.size() * kPointBytes;
        inside.push_back(std::move(points));
      } else {
        live += node_bytes(back);
        stack.push_back(std::move(back));
      }
    }
  }
  progress.end();
  return inside;
}

}  // namespace cvms::decomposition
