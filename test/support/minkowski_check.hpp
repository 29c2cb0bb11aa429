// SPDX-License-Identifier: MIT
// Checks shared by the Minkowski-sum tests: a result against an exact oracle
// (CHMS or brute force, compared as rational vertex sets and facet planes),
// the polyhedron invariants, and the invariants specific to A + B. Plain
// rational arithmetic, independent of the code under test.
#pragma once

#include <functional>
#include <string>

#include "cvms/minkowski.hpp"
#include "support/oracle.hpp"

namespace cvms::test {

/// "" if every facet plane of `sum` has a normal that is a facet normal of a
/// or of b, or is perpendicular to a non-parallel pair (edge of a, edge of b),
/// i.e. parallel to their cross product; else the first offending plane.
std::string check_facet_origins(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Shape& sum);

/// Runs `options.algorithm` on a + b and on b + a and checks: the invariants
/// of both results, equality with `expected` and between the two orders
/// (commutativity), F <= f_A + f_B + e_A e_B, the facet origins, and for CVMS
/// and ESSDMS that the stats add up to F, that translated facets = f_A and
/// that corner facets = the facets of B whose normal no facet of A has. Returns ""
/// or a message. \p check_origins can be switched off for big inputs.
/// How check_sum computes a sum; empty: minkowski_sum(x, y, options). Tests
/// of internals pass one that sets CVMS's research switches.
using SumFunction = std::function<MinkowskiResult(const ConvexPolyhedron&, const ConvexPolyhedron&)>;

std::string check_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Shape& expected,
                      const Options& options = {}, bool check_origins = true, const SumFunction& sum = {});

/// The oracle: describe(CHMS(a, b)).
Shape chms_shape(const ConvexPolyhedron& a, const ConvexPolyhedron& b);

}  // namespace cvms::test
