// SPDX-License-Identifier: MIT
/// \file
/// The exact boundary of a union of convex polyhedra as one closed solid, and
/// the Minkowski sum of solids that need not be convex written as that solid:
/// the union step of the paper's non-convex pipeline ("convex decomposition,
/// pairwise Minkowski sums and union").
///
/// The result is the regularised union (the closure of its interior): every
/// facet a maximal planar region of the boundary, every vertex a true corner
/// of it (no vertex inside a straight edge or a flat region). Where two parts
/// of the set touch only along an edge or at a point, the boundary is not a
/// 2-manifold there; the solid then holds that edge's or point's vertices
/// once per part (equal coordinates, different indices), so that every shell
/// is a closed 2-manifold, as mesh formats and tools expect.
#pragma once

#include "cvms/convex_union.hpp"
#include "cvms/decomposition.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/solid.hpp"

namespace cvms {

/// The regularised union of the pieces as a solid, exactly.
/// options.threads spreads the work over that many threads; the result is
/// the same for every thread count. options.progress hears the stages of the
/// union.
/// \throw Error(invalid_argument) for an empty union;
/// \throw Error(cancelled) if options.progress returns false.
Solid union_solid(const ConvexUnion& pieces, const Options& options = {});

/// The way minkowski_sum of two solids computes A + B.
enum class SolidSumRoad {
  convex,             ///< both operands convex: their convex sum
  faces_with_convex,  ///< one operand convex: the other's faces summed with it, united
  pieces,             ///< neither convex: pairwise sums of both decompositions' pieces, united
};

/// The road minkowski_sum(a, b) takes (it decides by this function), so
/// that a caller can report it without deciding it again.
[[nodiscard]] SolidSumRoad solid_sum_road(const Solid& a, const Solid& b) noexcept;

/// A + B for solids that need not be convex, as one solid, exactly. When
/// one operand is convex the other is not decomposed: A + B is the union of
/// A + b (b a point inside B) and of the sums of A's boundary faces with B.
/// Otherwise both are decomposed (convex_decomposition) and the pairwise sums
/// of the pieces are united. Two convex operands give their convex sum.
/// options.threads spreads the sums and the union over that many threads;
/// the result is the same for every thread count. options.limits bounds each
/// convex sum and all of them together, as minkowski_sum of two unions does
/// (cvms/convex_union.hpp). options.progress hears "solid sum: faces" (A's
/// face polygons summed with B) and "solid sum: fragments" (the union's
/// fragments tested against A + b, one unit per group of fragments joined
/// by shared corners) when one operand is convex, the stages of the
/// decompositions (when decomposition.progress is empty), of the sums and
/// of the union.
/// \throw Error(invalid_argument) for an empty operand;
/// \throw Error(limit) naming the limit (SumLimits, DecompositionLimits);
/// \throw as convex_decomposition, minkowski_sum and union_solid.
Solid minkowski_sum(const Solid& a, const Solid& b, const Options& options = {},
                    const DecompositionOptions& decomposition = {});

}  // namespace cvms
