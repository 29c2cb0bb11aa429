// SPDX-License-Identifier: MIT
// The filter stage of the predicates: each predicate's polynomial evaluated
// in double with a running error bound (filtered_arithmetic.hpp, whose
// bounds error_bounds.hpp proves), written once as a template over the leaf
// type: either Approx (cached or on-the-fly approximations with an error) or
// double (all input errors are zero, the common case for inputs that were
// doubles, where the first operations need no error propagation at all).
// predicates.cpp decides with them before falling back to exact arithmetic;
// the quickhull calls them on its points' doubles, which it holds before (or
// instead of) any rational. Inline, so that neither pays a call. Private to
// the library.
#pragma once

#include "approx.hpp"
#include "filtered_arithmetic.hpp"

namespace cvms::filtered {

/// Leaf vectors of doubles, for arguments whose approximations are exact.
struct Doubles2 {
  double x, y;
};
/// See Doubles2.
struct Doubles3 {
  double x, y, z;
};

inline Doubles2 values(const ApproxVec2& a) noexcept { return {a.x.value, a.y.value}; }
inline Doubles3 values(const ApproxVec3& a) noexcept { return {a.x.value, a.y.value, a.z.value}; }

/// True iff every coordinate of every argument is exactly its double. The
/// errors are nonnegative, so a zero sum means all are zero (NaN is not 0).
inline bool all_exact(const ApproxVec2& a) noexcept { return a.x.error + a.y.error == 0.0; }
inline bool all_exact(const ApproxVec3& a) noexcept { return a.x.error + a.y.error + a.z.error == 0.0; }
template <class... Vs>
bool all_exact(const Vs&... vs) noexcept {
  return (all_exact(vs) && ...);
}

// --- the polynomials, over leaf vectors (ApproxVecN or DoublesN) ---
// Function objects rather than templates, so that filtered_value can take
// them as arguments.

inline constexpr auto cross2_approx = [](const auto& u, const auto& v) noexcept {
  return sub(mul(u.x, v.y), mul(u.y, v.x));
};

inline constexpr auto dot2_approx = [](const auto& u, const auto& v) noexcept {
  return add(mul(u.x, v.x), mul(u.y, v.y));
};

inline constexpr auto orient2d_approx = [](const auto& a, const auto& b, const auto& c) noexcept {
  Approx bx = sub(b.x, a.x), by = sub(b.y, a.y);
  Approx cx = sub(c.x, a.x), cy = sub(c.y, a.y);
  return sub(mul(bx, cy), mul(by, cx));
};

inline constexpr auto dot3_approx = [](const auto& u, const auto& v) noexcept {
  return add(add(mul(u.x, v.x), mul(u.y, v.y)), mul(u.z, v.z));
};

/// dot(u, cross(v, w)) for leaves or already-propagated Approx triples.
template <class U, class V>
Approx triple_of(const U& ux, const U& uy, const U& uz, const V& v, const V& w) noexcept {
  Approx cx = sub(mul(v.y, w.z), mul(v.z, w.y));
  Approx cy = sub(mul(v.z, w.x), mul(v.x, w.z));
  Approx cz = sub(mul(v.x, w.y), mul(v.y, w.x));
  return add(add(mul(ux, cx), mul(uy, cy)), mul(uz, cz));
}

/// dot(u, cross(v, w)) for leaf vectors.
inline constexpr auto triple_approx = [](const auto& u, const auto& v, const auto& w) noexcept {
  return triple_of(u.x, u.y, u.z, v, w);
};

struct Approx3 {
  Approx x, y, z;
};

template <class V>
Approx3 difference(const V& a, const V& b) noexcept {
  return {sub(a.x, b.x), sub(a.y, b.y), sub(a.z, b.z)};
}

/// det[b - a, c - a, d - a] = dot(d - a, cross(b - a, c - a)).
inline constexpr auto orient3d_approx = [](const auto& a, const auto& b, const auto& c,
                                           const auto& d) noexcept {
  Approx3 ba = difference(b, a), ca = difference(c, a), da = difference(d, a);
  return triple_of(da.x, da.y, da.z, ba, ca);
};

/// dot(v - w, n): one subtraction per coordinate instead of two dot products.
inline constexpr auto compare_dot_approx = [](const auto& v, const auto& w, const auto& n) noexcept {
  Approx3 d = difference(v, w);
  return add(add(mul(d.x, n.x), mul(d.y, n.y)), mul(d.z, n.z));
};

inline constexpr auto cross3_approx = [](const auto& u, const auto& v) noexcept {
  return Approx3{sub(mul(u.y, v.z), mul(u.z, v.y)), sub(mul(u.z, v.x), mul(u.x, v.z)),
                 sub(mul(u.x, v.y), mul(u.y, v.x))};
};

// --- polynomials on differences of points, for callers that hold the
// points' approximations but not the exact differences (the polygon and
// edge checks of ConvexPolyhedron::from_mesh): each difference is one
// filtered subtraction per coordinate, whose bound covers the points' errors.

/// det[n, a1 - a0, b1 - b0].
inline constexpr auto triple_of_differences_approx = [](const auto& n, const auto& a0, const auto& a1,
                                                        const auto& b0, const auto& b1) noexcept {
  Approx3 a = difference(a1, a0), b = difference(b1, b0);
  return triple_of(n.x, n.y, n.z, a, b);
};

/// dot(a1 - a0, b1 - b0).
inline constexpr auto dot_of_differences_approx = [](const auto& a0, const auto& a1, const auto& b0,
                                                     const auto& b1) noexcept {
  Approx3 a = difference(a1, a0), b = difference(b1, b0);
  return add(add(mul(a.x, b.x), mul(a.y, b.y)), mul(a.z, b.z));
};

/// det[u, v, w1 - w0] = dot(w1 - w0, cross(u, v)).
inline constexpr auto triple_with_difference_approx = [](const auto& u, const auto& v, const auto& w0,
                                                         const auto& w1) noexcept {
  Approx3 d = difference(w1, w0);
  return triple_of(d.x, d.y, d.z, u, v);
};

/// cross(b - a, c - a).
inline constexpr auto cross_of_differences_approx = [](const auto& a, const auto& b, const auto& c) noexcept {
  return cross3_approx(difference(b, a), difference(c, a));
};

/// poly on the approximations: on their doubles when every one is exact
/// (fewer operations, the same result), else with error propagation.
template <class Poly, class... Approximations>
inline auto filtered_value(Poly poly, const Approximations&... a) noexcept {
  return all_exact(a...) ? poly(values(a)...) : poly(a...);
}

}  // namespace cvms::filtered
