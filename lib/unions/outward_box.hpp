// SPDX-License-Identifier: MIT
// Axis-aligned boxes in doubles that contain an exact set: every bound is
// rounded outward (a lower bound down, an upper bound up) and checked by an
// exact comparison, so the double box contains the exact box and the tests
// on double boxes below are conservative:
//  - overlaps(a, b) false  => the exact boxes, hence the sets, are disjoint;
//  - lower_squared_distance(a, b) <= the squared distance of the exact
//    boxes <= the squared distance of the sets.
// A query only skips work on these answers, so rounding changes how much is
// pruned, never a result.
#pragma once

#include <array>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/convex_set.hpp"
#include "cvms/proximity.hpp"
#include "cvms/rational.hpp"
#include "cvms/vec.hpp"

namespace cvms::unions {

/// The box [lo[0], hi[0]] x [lo[1], hi[1]] x [lo[2], hi[2]]; a bound may be
/// infinite for a coordinate beyond the doubles' range.
struct OutwardBox {
  std::array<double, 3> lo{};
  std::array<double, 3> hi{};
};

/// The greatest double <= q (-infinity below -DBL_MAX).
double round_down(const Rational& q);
/// The least double >= q (+infinity above DBL_MAX).
double round_up(const Rational& q);

/// The box of a point: its coordinates rounded outward.
OutwardBox point_box(const Vec3& p);
/// The box of a non-empty polyhedron, from its six axis supports.
OutwardBox polyhedron_box(const ConvexPolyhedron& p);
/// The box of a placed polyhedron: the supports of the unmoved polyhedron in
/// the rows of the linear part, plus the translation (a zero row pins that
/// coordinate to the translation's).
OutwardBox placed_box(const PlacedPolyhedron& p);
/// The box of a non-empty convex set, from its six axis supports.
OutwardBox set_box(const ConvexSet& s);

/// The smallest box containing both.
OutwardBox merged(const OutwardBox& a, const OutwardBox& b);

/// False only if the boxes are disjoint (closed boxes: touching overlaps).
bool overlaps(const OutwardBox& a, const OutwardBox& b);

/// A double <= the squared Euclidean distance between the boxes (0 when
/// they overlap). Each operation is rounded to nearest and then stepped one
/// double down: a correctly rounded result r of an exact value x has x
/// between r's neighbours, so the double below r is <= x; gaps and squares
/// are clamped at 0, which keeps them lower bounds of non-negative values.
/// Infinite bounds give no NaN: a lower bound is never +infinity and an
/// upper bound never -infinity, so no difference is infinity - infinity.
double lower_squared_distance(const OutwardBox& a, const OutwardBox& b);

}  // namespace cvms::unions
