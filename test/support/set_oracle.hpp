// SPDX-License-Identifier: MIT
// An independent oracle for convex sets of every dimension: the hull of a
// point set by brute force in the dimension it spans (exact rank, gift
// wrapping in a plane, quickhull only for full-dimensional sets), and
// order-free descriptions of ConvexSets that compare as exact rationals.
// Plain Rational arithmetic and the public API only; nothing of lib/sets/.
#pragma once

#include <set>
#include <span>
#include <string>
#include <vector>

#include "cvms/convex_set.hpp"
#include "cvms/minkowski.hpp"
#include "support/oracle.hpp"

namespace cvms::test {

/// Dimension, vertex set, and planes: for a polygon its plane (normal
/// primitive, first nonzero coordinate positive) and the lines of its edges
/// (each as the plane through the edge orthogonal to the polygon, outward);
/// for a polyhedron its facet planes.
struct SetShape {
  int dimension = -1;
  std::set<Vec3> vertices;
  std::set<Plane> planes;
  friend bool operator==(const SetShape& a, const SetShape& b) {
    return a.dimension == b.dimension && a.vertices == b.vertices && a.planes == b.planes;
  }
};

/// The exact hull of the points, computed independently (see the file comment).
SetShape hull_oracle(std::span<const Vec3> points);

/// The oracle of a + b: hull_oracle of all pairwise vertex sums.
SetShape sum_oracle(const ConvexSet& a, const ConvexSet& b);

/// The description of a set from its vertices (planes recomputed here).
SetShape describe_set(const ConvexSet& s);

/// "" if the set's representation is valid and canonical (cvms/convex_set.hpp):
/// a segment's endpoints distinct and ordered; a polygon planar, strictly
/// convex, counterclockwise from its primitive canonical normal, starting at
/// its smallest vertex; a polyhedron's invariants (check_invariants).
std::string check_set_invariants(const ConvexSet& s);

/// "" or what is wrong with minkowski_sum(a, b, options) and (b, a):
/// check_set_invariants of each, and each against sum_oracle(a, b).
std::string check_set_sum(const ConvexSet& a, const ConvexSet& b, const Options& options = {});

/// Human-readable difference (for failure messages).
std::string difference(const SetShape& expected, const SetShape& actual);

}  // namespace cvms::test
