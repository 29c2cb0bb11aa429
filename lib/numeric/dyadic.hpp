// SPDX-License-Identifier: MIT
// Exact rational arithmetic without gcds for dyadic rationals (denominator a
// power of two: every double, and every sum or integer combination of
// doubles). Inputs read from doubles (STL, generated shapes, rounded
// rotations) make almost every coordinate of a Minkowski sum dyadic, and
// GMP's general mpq operations spend most of their time on gcds and on
// temporaries that such values do not need. Every function gives exactly the
// canonical result of the general operation and falls back to it for other
// rationals.
#pragma once

#include "cvms/rational.hpp"
#include "cvms/vec.hpp"
#include "power_of_two.hpp"

namespace cvms::detail {

/// Whether the (canonical) q has a power-of-two denominator.
[[nodiscard]] inline bool is_dyadic(const Rational& q) noexcept { return is_power_of_two(q.get_den_mpz_t()); }

/// out = x + y, canonical. out may alias neither x nor y.
void add_into(Rational& out, const Rational& x, const Rational& y);

/// out = x - y, canonical. out may alias neither x nor y.
void subtract_into(Rational& out, const Rational& x, const Rational& y);

/// x + y coordinatewise (add_into per coordinate).
[[nodiscard]] Vec3 add(const Vec3& x, const Vec3& y);

/// x - y coordinatewise (subtract_into per coordinate).
[[nodiscard]] Vec3 subtract(const Vec3& x, const Vec3& y);

/// Reusable integer scratch for integer_dot, so that a loop of dot products
/// allocates only for its results.
struct DotScratch {
  mpz_class denominator;  ///< common denominator of the point
  mpz_class sum;          ///< numerator being accumulated
  mpz_class term;         ///< one scaled coordinate
};

/// out = dot(n, p), canonical, for an integer vector n and a rational point p: with
/// L the lcm of p's denominators, dot = (sum n_i num_i (L / den_i)) / L,
/// reduced once at the end (by shifts alone when p is dyadic) instead of
/// after each of five rational operations.
/// \pre n has integer coordinates.
/// Writing into an existing out reuses its storage (no Rational is moved:
/// a moved-from mpq_class is re-initialised, which allocates).
void integer_dot(const Vec3& n, const Vec3& p, DotScratch& scratch, Rational& out);

}  // namespace cvms::detail
