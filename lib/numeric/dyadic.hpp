// SPDX-License-Identifier: MIT
// Exact rational arithmetic without gcds for dyadic rationals (denominator a
// power of two: every double, and every sum or integer combination of
// doubles). Inputs read from doubles (STL, generated shapes, rounded
// rotations) make almost every coordinate of a Minkowski sum dyadic, and
// GMP's general mpq operations spend most of their time on gcds and on
// temporaries that such values do not need. Every function gives exactly the
// canonical result of the general operation and falls back to it for other
// rationals.
//
// The fixed-width paths (FixedDyadic) go further for the common case of
// short values: a dot product of a primitive normal with a vertex, or the
// sum or difference of two coordinates, is computed in machine words and
// written (into an arena, or into a value's own limbs) with no GMP call at
// all. They take dyadic coordinates whose numerator and denominator fit one
// limb each (a double of magnitude at least 2^-11: every coordinate of the
// unit sphere but those near zero) and normals of at most two limbs. The
// bounds: with exponents below 64, a numerator brought to the common
// denominator is below 2^(64 + 63); a sum of two is below 2^128 (two limbs);
// a normal's coordinate times one is below 2^(128 + 64 + 63), so a dot
// product of three is below 2^257: five limbs in two's complement. Outside
// those bounds the general path runs; the results are the same canonical
// values either way.
#pragma once

#include <optional>
#include <span>

#include "cvms/rational.hpp"
#include "cvms/vec.hpp"
#include "fixed_int.hpp"
#include "limb_arena.hpp"
#include "power_of_two.hpp"

namespace cvms::detail {

/// Whether the (canonical) q has a power-of-two denominator.
[[nodiscard]] inline bool is_dyadic(const Rational& q) noexcept { return is_power_of_two(q.get_den_mpz_t()); }

/// out = x + y, canonical (in machine words when fixed_sum applies). out
/// may alias neither x nor y.
void add_into(Rational& out, const Rational& x, const Rational& y);

/// out = x - y, canonical (in machine words when fixed_difference applies).
/// out may alias neither x nor y.
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
  Rational value;         ///< a result on its way into an arena
};

/// out = dot(n, p), canonical, for an integer vector n and a rational point p: with
/// L the lcm of p's denominators, dot = (sum n_i num_i (L / den_i)) / L,
/// reduced once at the end (by shifts alone when p is dyadic) instead of
/// after each of five rational operations.
/// \pre n has integer coordinates.
/// Writing into an existing out reuses its storage (no Rational is moved:
/// a moved-from mpq_class is re-initialised, which allocates).
void integer_dot(const Vec3& n, const Vec3& p, DotScratch& scratch, Rational& out);

/// numerator / 2^exponent in fixed limbs, not necessarily in lowest terms.
template <int L>
struct FixedDyadic {
  FixedInt<L> numerator;
  mp_bitcnt_t exponent = 0;
};

/// x + y in fixed limbs, when both are dyadic with a numerator and a
/// denominator of one limb each (see the file comment); nullopt otherwise.
[[nodiscard]] std::optional<FixedDyadic<2>> fixed_sum(const Rational& x, const Rational& y) noexcept;

/// x - y, as fixed_sum.
[[nodiscard]] std::optional<FixedDyadic<2>> fixed_difference(const Rational& x, const Rational& y) noexcept;

/// dot(n, p) in fixed limbs, when n's coordinates are integers of at most
/// two limbs and p's are dyadic with a numerator and a denominator of one
/// limb each; nullopt otherwise.
/// \pre n has integer coordinates.
[[nodiscard]] std::optional<FixedDyadic<5>> fixed_integer_dot(const Vec3& n, const Vec3& p) noexcept;

/// Divides magnitude / 2^exponent by the largest power of two dividing both
/// (in place) and returns the new exponent.
mp_bitcnt_t reduce_dyadic(std::span<std::uint64_t> magnitude, mp_bitcnt_t exponent) noexcept;

/// out = value in lowest terms, its limbs in arena (LimbArena::store_dyadic).
template <int L>
void store_dyadic(LimbArena& arena, Rational& out, FixedDyadic<L> value) {
  const mp_bitcnt_t exponent = reduce_dyadic(value.numerator.magnitude, value.exponent);
  arena.store_dyadic(out, value.numerator.magnitude.data(), L, value.numerator.negative, exponent);
}

/// out = x + y like add_into, its limbs in arena. \pre out is not x or y.
void store_sum(LimbArena& arena, Rational& out, const Rational& x, const Rational& y, Rational& scratch);

/// out = dot(n, p) like integer_dot, its limbs in arena.
void store_integer_dot(LimbArena& arena, Rational& out, const Vec3& n, const Vec3& p, DotScratch& scratch);

}  // namespace cvms::detail
