// SPDX-License-Identifier: MIT
// Exact rational evaluation of every predicate, without the floating-point
// filter and without touching the counters. The fallback of the filtered
// predicates (predicates.cpp), and the baseline of the benchmark.
#pragma once

#include "filtered_predicates.hpp"

namespace cvms::exact {

// Same conventions as the public predicates of the same name.
Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c);
Sign sign_cross2(const Vec2& u, const Vec2& v);
Sign sign_dot(const Vec2& u, const Vec2& v);
Sign orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
Sign sign_dot(const Vec3& u, const Vec3& v);
Sign compare_dot(const Vec3& v, const Vec3& w, const Vec3& n);
Sign side_of_plane(const Vec3& p, const Vec3& n, const Rational& offset);
Sign sign_triple(const Vec3& u, const Vec3& v, const Vec3& w);
bool is_parallel(const Vec3& u, const Vec3& v);
// The predicates on differences of points (filtered_predicates.hpp).
Sign sign_triple_of_differences(const Vec3& n, const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1);
Sign sign_triple_in_plane(const Vec3& n, const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1);
Sign sign_dot_of_differences(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1);
Sign sign_triple_with_difference(const Vec3& u, const Vec3& v, const Vec3& w0, const Vec3& w1);
bool collinear(const Vec3& a, const Vec3& b, const Vec3& c);
// side_of_plane for a normal with integer coordinates: one integer
// comparison over a common denominator, with no gcd (the planarity test of
// from_mesh, where every answer is zero and the filter never decides).
// \pre n has integer coordinates.
Sign side_of_integer_plane(const Vec3& p, const Vec3& n, const Rational& offset);

}  // namespace cvms::exact
