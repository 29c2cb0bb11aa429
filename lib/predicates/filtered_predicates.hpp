// SPDX-License-Identifier: MIT
// The predicates as the library's algorithms call them: with the cached
// double approximations of their arguments (Vec3Ref: exact value + proven
// error bound, lib/numeric/approx.hpp), so the filter costs a few flops and no
// conversion. Same exact answers as the public overloads in cvms/predicates.hpp
// (lib/predicates/predicates.cpp holds both). Private: the filter machinery is
// not part of the public API, and SumDiagnostics reports the counters to users.
#pragma once

#include <cstdint>
#include <optional>

#include "approx.hpp"
#include "cvms/predicates.hpp"

namespace cvms {

// How often the floating-point filter answered and how often exact
// arithmetic was needed: one count per sign evaluation (ccw_in_between
// makes two to four; a true is_parallel is always an exact evaluation). Per
// thread: predicates running in different threads never share counters, so
// the library stays free of shared mutable state. minkowski_sum reports the
// difference over its call in SumDiagnostics.
struct PredicateCounters {
  std::uint64_t filtered = 0;  ///< answered by the double filter
  std::uint64_t exact = 0;     ///< fell back to exact rational evaluation
};
// This thread's counters (read or reset them from tests and benchmarks).
PredicateCounters& predicate_counters() noexcept;

// The overloads of cvms/predicates.hpp with cached approximations
// (side_of_plane also takes the offset's approximation).
Sign orient2d(Vec2Ref a, Vec2Ref b, Vec2Ref c);
Sign sign_cross2(Vec2Ref u, Vec2Ref v);
Sign sign_dot(Vec2Ref u, Vec2Ref v);
bool ccw_in_between(Vec2Ref d, Vec2Ref d1, Vec2Ref d2);
Sign orient3d(Vec3Ref a, Vec3Ref b, Vec3Ref c, Vec3Ref d);
/// orient3d when the filter alone proves its sign (never zero), else nothing:
/// for callers with a cheaper exact route than the rational determinant
/// (coplanar points, which no filter can prove, are the usual case).
std::optional<Sign> orient3d_if_certain(Vec3Ref a, Vec3Ref b, Vec3Ref c, Vec3Ref d) noexcept;
Sign sign_dot(Vec3Ref u, Vec3Ref v);
Sign compare_dot(Vec3Ref v, Vec3Ref w, Vec3Ref n);
/// compare_dot when the filter alone proves its sign (never zero), else
/// nothing: for callers that can try another choice before paying for exact
/// arithmetic (an exact tie, dot(v - w, n) = 0, is never proven).
std::optional<Sign> compare_dot_if_certain(Vec3Ref v, Vec3Ref w, Vec3Ref n) noexcept;
Sign side_of_plane(Vec3Ref p, Vec3Ref n, const Rational& offset, Approx offset_approx);
/// side_of_plane when the filter alone proves its sign (never zero) from the
/// approximations of the point, the normal and the offset, else nothing: for
/// a point known only by approximation, such as the corner of a box that
/// holds exact points (its doubles exact, error 0), where no exact value
/// exists to fall back on.
std::optional<Sign> side_of_plane_if_certain(const ApproxVec3& p, const ApproxVec3& n, Approx offset) noexcept;
Sign sign_triple(Vec3Ref u, Vec3Ref v, Vec3Ref w);
bool is_parallel(Vec3Ref u, Vec3Ref v);

// Predicates on differences of points, given by the points (the polygon and
// edge checks of ConvexPolyhedron::from_mesh): the filter subtracts the
// cached approximations, and only an exact fallback forms the differences.
/// Sign of det[n, a1 - a0, b1 - b0].
Sign sign_triple_of_differences(Vec3Ref n, Vec3Ref a0, Vec3Ref a1, Vec3Ref b0, Vec3Ref b1);
/// As sign_triple_of_differences for differences orthogonal to n (points of
/// a polygon in a plane with normal n): then the value is zero iff the
/// differences are parallel, which the exact fallback tests first, without n.
/// \pre a0, a1, b0, b1 lie in one plane orthogonal to n, n nonzero.
Sign sign_triple_in_plane(Vec3Ref n, Vec3Ref a0, Vec3Ref a1, Vec3Ref b0, Vec3Ref b1);
/// Sign of dot(a1 - a0, b1 - b0).
Sign sign_dot_of_differences(Vec3Ref a0, Vec3Ref a1, Vec3Ref b0, Vec3Ref b1);
/// Sign of det[u, v, w1 - w0].
Sign sign_triple_with_difference(Vec3Ref u, Vec3Ref v, Vec3Ref w0, Vec3Ref w1);
/// True iff a, b, c lie on one line (cross(b - a, c - a) = 0).
bool collinear(Vec3Ref a, Vec3Ref b, Vec3Ref c);

}  // namespace cvms
