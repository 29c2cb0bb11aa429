// SPDX-License-Identifier: MIT
// Exact convex decomposition of a solid.
//
// The method: an auto-partition (a binary space partition of the bounding
// box by the solid's own facet planes, auto_partition.cpp) gives convex
// inside cells whose union is the solid, then a greedy merge of cells whose
// union is convex (cell_merge.cpp) brings their number down. Why this and
// not notch cutting through reflex edges: the partition's cells are
// convex by construction and every cell vertex is the intersection of three
// input planes (exact numbers stay small, no exact polygon clipping of
// non-convex shapes), holes, cavities and several shells need no special
// case, and preferring the planes of facets on reflex edges makes the cuts
// the ones a notch cut would make on solids of boxes and prisms. Every sign
// is a predicate (side_of_plane, orient3d) or an exact rational comparison.
#include "cvms/decomposition.hpp"

#include <string>
#include <utility>
#include <vector>

#include "auto_partition.hpp"
#include "boundary_planes.hpp"
#include "cell_merge.hpp"
#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "progress_reporter.hpp"

namespace cvms {

ConvexUnion convex_decomposition(const Solid& solid, const DecompositionOptions& options) {
  if (solid.triangles().empty())
    throw Error(ErrorCategory::invalid_argument, "convex_decomposition: the solid is empty");
  decomposition::BoundaryPlanes planes = decomposition::boundary_planes(solid);
  std::vector<ConvexPolyhedron> pieces;
  if (planes.shells == 1 && planes.reflex_edges == 0) {
    std::vector<Vec3> points(solid.vertices().begin(), solid.vertices().end());
    pieces.push_back(convex_hull(points));
  } else {
    detail::ProgressReporter progress(detail::callback_of(options.progress));
    pieces = decomposition::merge_convex_cells(
        decomposition::inside_cells(solid, planes, options.limits, progress, options.progress), progress);
  }
  if (pieces.size() > options.limits.max_pieces)
    throw Error(ErrorCategory::limit, "convex_decomposition: " + std::to_string(pieces.size()) +
                                          " pieces, more than max_pieces = " +
                                          std::to_string(options.limits.max_pieces));
  return ConvexUnion(std::move(pieces));
}

}  // namespace cvms
