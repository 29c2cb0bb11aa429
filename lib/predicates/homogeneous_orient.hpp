// SPDX-License-Identifier: MIT
// Exact orient3d of points given in homogeneous integer coordinates
// (X, Y, Z, w), w > 0, standing for (X/w, Y/w, Z/w): the exact fallback of
// from_halfspaces' dual hull, whose points a/(b − a·x0) have a different
// large denominator each, so that the rational evaluation pays a gcd for
// every product. Here no rational is ever built. Private to the library.
#pragma once

#include <gmpxx.h>

#include "cvms/sign.hpp"

namespace cvms {

/// The point (x/w, y/w, z/w); w > 0.
struct HomogeneousPoint {
  mpz_class x, y, z, w;
};

/// The exact sign of orient3d(a, b, c, d) (predicates.hpp: det[b − a, c − a,
/// d − a]) of the points a, b, c, d stand for. Counted as an exact
/// evaluation.
/// \pre a.w, b.w, c.w, d.w > 0.
Sign homogeneous_orient3d(const HomogeneousPoint& a, const HomogeneousPoint& b, const HomogeneousPoint& c,
                          const HomogeneousPoint& d);

/// The exact sign of orient3d(a, b, c, p) − orient3d(a, b, c, q), the
/// values and not their signs, of the points these stand for: the sign of
/// compare_dot(p, q, cross(b − a, c − a)), by which the quickhull picks the
/// farther of two points above a triangle. With Δ_x = det of the rows a, b,
/// c, x (homogeneous_orient.cpp), orient3d(a, b, c, x) = −Δ_x / (a.w b.w c.w
/// x.w), so the difference is −(Δ_p q.w − Δ_q p.w) / (a.w b.w c.w p.w q.w),
/// whose denominator is positive. Counted as an exact evaluation.
/// \pre a.w, b.w, c.w, p.w, q.w > 0.
Sign homogeneous_compare_orient3d(const HomogeneousPoint& a, const HomogeneousPoint& b, const HomogeneousPoint& c,
                                  const HomogeneousPoint& p, const HomogeneousPoint& q);

}  // namespace cvms
