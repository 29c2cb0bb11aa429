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
///   polyhedra (the other cases read only options.limits and take time
///   linear in the output, so they report no progress).
/// \throw Error(cancelled) if options.progress returns false (polyhedra).
/// \throw Error(limit) if the sum is beyond options.limits (SumLimits:
///   max_output_facets, max_memory_bytes), decided before the output is
///   built: the direct constructions count their output facets first
///   (exactly for polygon + polyhedron; for segment + polyhedron before
///   coplanar facets merge; polygon + polygon counts polygon + the other's
///   prism, which has at most the polygons' vertex counts more).
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
/// options.progress (cvms/progress.hpp) hears the stage "sums", in sums of
/// two made, and between its reports the stages of each sum of two.
/// \throw Error(invalid_argument) as the sum of two (when two polyhedra meet).
/// \throw Error(cancelled) if options.progress returns false.
/// \throw Error(limit) if a sum of two on the way is beyond options.limits
///   (then so is the whole: a sum has at least the facets of a partial
///   sum); when all operands are segments and points, also if the bound of
///   the zonotope, d (d - 1) facets for d distinct directions, is, before
///   any sum is made.
ConvexSet minkowski_sum(std::span<const ConvexSet> operands, const Options& options = {});

/// The zonotope center + sum of the segments [-g, g] over the generators g
/// (zero generators are ignored). n generators in general position give
/// n^2 - n + 2 vertices, 2 n (n - 1) edges and n (n - 1) facets; parallel
/// generators merge into one zone; coplanar ones give a polygon (a zonogon),
/// collinear ones a segment, none the point `center`.
/// Complexity: as minkowski_sum of the segments.
/// \throw Error(limit) if n (n - 1), for n distinct generator directions, is
///   beyond `limits` (checked first: the CLI's 100,000 generators are
///   refused at once).
ConvexSet zonotope(const Vec3& center, std::span<const Vec3> generators, const SumLimits& limits = {});

}  // namespace cvms
