// SPDX-License-Identifier: MIT
/// \file
/// Minkowski sums of convex sets of every dimension, of two operands or of
/// many, and zonotopes. Exact; the result is a ConvexSet in the dimension it
/// has (two segments in a plane give a polygon, a square and a perpendicular
/// segment a box, two parallel segments a segment).
#pragma once

#include <span>

#include "cvms/convex_set.hpp"
#include "cvms/minkowski.hpp"

namespace cvms {

/// A + B for convex sets of any dimension. Empty + anything is empty; a point
/// translates; two polyhedra go through minkowski_sum(ConvexPolyhedron,
/// ConvexPolyhedron, options) (the only case where `options` matters); the
/// others are built directly (lib/sets/): segment + segment and the sums of
/// polygons in parallel planes by the planar convolution in the plane's
/// exact chart, segment + polygon as a prism, segment + polyhedron from the
/// polyhedron's facets split by the segment's direction and its silhouette,
/// polygon + polyhedron directly from the two Gaussian maps (the polygon's
/// is its two normals and one meridian per edge), and polygon + polygon in
/// non-parallel planes as polygon + (the other's prism), whose sweep is then
/// undone exactly.
/// \throw Error(invalid_argument) for an unknown option value when both are
///   polyhedra (the other cases do not read the options).
/// Complexity: output-sensitive, no hull of pairwise sums: O(size of the
///   operands and the result) predicates (times log of the polygon's size
///   for a polygon and a polyhedron); for two polyhedra that of
///   minkowski_sum.
ConvexSet minkowski_sum(const ConvexSet& a, const ConvexSet& b, const Options& options = {});

/// The sum of all operands; the point at the origin (the neutral element) for
/// an empty list, the empty set if any operand is empty. The result does not
/// depend on the order. Points are added as one translation; the others are
/// summed two at a time, always the two with the fewest vertices, which
/// keeps intermediate sums small (for n segments: a balanced tree of zonotopes).
/// \throw Error(invalid_argument) as the sum of two (when two polyhedra meet).
ConvexSet minkowski_sum(std::span<const ConvexSet> operands, const Options& options = {});

/// The zonotope center + sum of the segments [-g, g] over the generators g
/// (zero generators are ignored). n generators in general position give
/// n^2 - n + 2 vertices, 2 n (n - 1) edges and n (n - 1) facets; parallel
/// generators merge into one zone; coplanar ones give a polygon (a zonogon),
/// collinear ones a segment, none the point `center`.
/// Complexity: as minkowski_sum of the segments.
ConvexSet zonotope(const Vec3& center, std::span<const Vec3> generators);

}  // namespace cvms
