// SPDX-License-Identifier: MIT
// The exact point where a segment crosses a plane with an integer normal,
// computed on integers with one canonicalisation per coordinate.
//
// With a = A / d_a and b = B / d_b (A, B integer vectors, d_a, d_b > 0 the
// lcms of each point's denominators) and the plane dot(n, x) = o_n / o_d
// (n an integer vector, o_d > 0), the plane's values at the ends are
//   s_a = S_A / (d_a o_d),  S_A = o_d dot(n, A) - o_n d_a,
//   s_b = S_B / (d_b o_d),  S_B = o_d dot(n, B) - o_n d_b,
// and the crossing point a + t (b - a), t = s_a / (s_a - s_b), is
//   (s_a b - s_b a) / (s_a - s_b) = (S_A B - S_B A) / (S_A d_b - S_B d_a),
// where the common factor d_a d_b o_d cancels. Every intermediate is an
// integer: the rational form of the same formula canonicalises each of
// about twenty intermediate values (a gcd each), which dominated the cost
// of cutting the union's facets; here the only gcds are the lcms of the
// ends' denominators (none when a point's coordinates share a denominator)
// and the three final canonicalisations.
#pragma once

#include "cvms/rational.hpp"
#include "cvms/vec.hpp"

namespace cvms::detail {

/// Sets `out` to the point where the segment [a, b] meets the plane
/// dot(n, x) = offset.
/// \pre n has integer coordinates; dot(n, a) - offset and dot(n, b) - offset
///      are nonzero and of opposite signs (so the point is unique and lies
///      strictly inside the segment).
void plane_crossing(const Vec3& a, const Vec3& b, const Vec3& n, const Rational& offset, Vec3& out);

}  // namespace cvms::detail
