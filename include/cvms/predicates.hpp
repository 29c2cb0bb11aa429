// SPDX-License-Identifier: MIT
/// \file
/// Exact geometric predicates: every sign decision of the library is one of
/// these. Each first evaluates its polynomial in double with a running error
/// bound (each operation adds its rounding and a term for underflow), answers
/// when |value| > bound, and otherwise falls back to exact rational
/// evaluation. The answer is therefore always the exact sign.
///
/// Cost: O(1) double operations when the filter answers; otherwise exact GMP
/// arithmetic, whose cost grows with the bit length of the inputs.
/// Thread-safe: no shared state.
#pragma once

#include "cvms/sign.hpp"
#include "cvms/vec.hpp"

namespace cvms {

/// Sign of cross(b - a, c - a) (2D): positive iff a, b, c make a left turn
/// (counterclockwise), zero iff collinear.
Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c);

/// Sign of cross(u, v) (2D, z component): positive iff v is counterclockwise of u.
Sign sign_cross2(const Vec2& u, const Vec2& v);

/// Sign of dot(u, v) (2D): positive iff the angle between u and v is acute.
Sign sign_dot(const Vec2& u, const Vec2& v);

/// True iff direction d lies strictly inside the counterclockwise angular
/// sector that starts at direction d1 and ends at direction d2 (d1, d2, d
/// nonzero). When d1 and d2 have the same direction the sector is the whole
/// turn minus that direction. Used to order edges in the planar convolution.
bool ccw_in_between(const Vec2& d, const Vec2& d1, const Vec2& d2);

/// Sign of dot(b - a, cross(c - a, d - a)) = det[b - a, c - a, d - a]:
/// positive iff d lies on the side of the plane through a, b, c into which
/// cross(b - a, c - a) points (a, b, c counterclockwise seen from d),
/// zero iff the four points are coplanar.
/// (Note the order: det[b-a, c-a, d-a] = dot(cross(b-a, c-a), d-a).)
Sign orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Sign of dot(u, v).
Sign sign_dot(const Vec3& u, const Vec3& v);

/// Sign of dot(v, n) - dot(w, n): positive iff v is farther than w in the
/// direction n (the test that picks contributing vertices, paper Eq. 3).
Sign compare_dot(const Vec3& v, const Vec3& w, const Vec3& n);

/// Sign of dot(p, n) - offset: positive iff p is strictly above the plane
/// {x : dot(x, n) = offset} (in the direction n).
Sign side_of_plane(const Vec3& p, const Vec3& n, const Rational& offset);

/// Sign of the triple product det[u, v, w] = dot(u, cross(v, w)).
Sign sign_triple(const Vec3& u, const Vec3& v, const Vec3& w);

/// True iff cross(u, v) == 0 (u, v parallel or one of them zero). Exact; the
/// filter can only prove "not parallel", so a true answer always costs an
/// exact evaluation.
bool is_parallel(const Vec3& u, const Vec3& v);

}  // namespace cvms
