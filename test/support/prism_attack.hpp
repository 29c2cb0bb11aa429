// SPDX-License-Identifier: MIT
// An input whose sum's output size is quadratic in the input, made at test
// time: two n-gon prisms with perpendicular axes, whose sum has
// about n^2 / 2 facets (n = 10,000: 3 MB as OFF, 5 x 10^7 output facets).
#pragma once

#include "cvms/convex_polyhedron.hpp"

namespace cvms::test {

struct PrismPair {
  ConvexPolyhedron a;  ///< shapes::prism(n, 2), axis z
  ConvexPolyhedron b;  ///< shapes::prism(n, 3) turned exactly so that its axis is y
};

/// The attack pair for n-gon prisms. \throw Error as shapes::prism does.
PrismPair prism_attack(int n);

}  // namespace cvms::test
