// SPDX-License-Identifier: MIT
// Primitive directions and their cross products in 64/128-bit integers.
#include "small_direction.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <span>
#include <utility>

#include <gmp.h>

#include "error_bounds.hpp"
#include "gcd128.hpp"
#include "limb_arena.hpp"

namespace cvms::detail {
namespace {

static_assert(GMP_NUMB_BITS == 64, "gcd passes 128-bit integers as two limbs");

__extension__ using Int128 = __int128;
__extension__ using Uint128 = unsigned __int128;

int countr_zero(Uint128 x) noexcept {
  const auto low = static_cast<std::uint64_t>(x);
  return low != 0 ? std::countr_zero(low) : 64 + std::countr_zero(static_cast<std::uint64_t>(x >> 64));
}

Uint128 magnitude(Int128 x) noexcept { return x < 0 ? -static_cast<Uint128>(x) : static_cast<Uint128>(x); }

// gcd(0, x) = x. gcd(1, x) = 1 at once, the usual partial gcd of a
// primitive vector. Else GMP's: mpn_gcd_1 reduces a 128-bit operand modulo a
// 64-bit one first, and mpn_gcd runs GMP's assembly binary gcd on two limbs,
// about 1.4x faster than a portable 128-bit loop. Its preconditions: xn >=
// yn > 0, y's top limb nonzero, an odd operand (the common power of two is
// taken out first and put back at the end).
Uint128 gcd(Uint128 a, Uint128 b) noexcept {
  if (a == 0) return b;
  if (b == 0) return a;
  if (a == 1 || b == 1) return 1;
  if (a < b) std::swap(a, b);
  const auto limbs = [](Uint128 x) { return x >> 64 != 0 ? mp_size_t{2} : mp_size_t{1}; };
  mp_limb_t x[2] = {static_cast<mp_limb_t>(a), static_cast<mp_limb_t>(a >> 64)};
  if (b >> 64 == 0) return mpn_gcd_1(x, limbs(a), static_cast<mp_limb_t>(b));
  const int shift = countr_zero(a | b);
  a >>= countr_zero(a);
  b >>= countr_zero(b);
  if (a < b) std::swap(a, b);
  x[0] = static_cast<mp_limb_t>(a);
  x[1] = static_cast<mp_limb_t>(a >> 64);
  mp_limb_t y[2] = {static_cast<mp_limb_t>(b), static_cast<mp_limb_t>(b >> 64)};
  if (y[1] == 0) return Uint128{mpn_gcd_1(x, limbs(a), y[0])} << shift;
  mp_limb_t g[2] = {0, 0};
  const mp_size_t size = mpn_gcd(g, x, 2, y, 2);
  return (Uint128{g[0]} | (size > 1 ? Uint128{g[1]} << 64 : 0)) << shift;
}

// Divides the nonzero integer vector v by the gcd of its coordinates.
void make_primitive(Int128 (&v)[3]) noexcept {
  const Uint128 g = gcd(gcd(magnitude(v[0]), magnitude(v[1])), magnitude(v[2]));
  if (g == 1) return;
  for (Int128& x : v) x /= static_cast<Int128>(g);
}

void set_integer(Rational& out, Int128 x) {
  mpz_ptr num = mpq_numref(out.get_mpq_t());
  if (x >= INT64_MIN && x <= INT64_MAX) {
    mpz_set_si(num, static_cast<long>(x));
  } else {
    const Uint128 m = magnitude(x);
    const std::uint64_t words[2] = {static_cast<std::uint64_t>(m), static_cast<std::uint64_t>(m >> 64)};
    mpz_import(num, 2, -1, sizeof(std::uint64_t), 0, 0, words);
    if (x < 0) mpz_neg(num, num);
  }
  mpz_set_ui(mpq_denref(out.get_mpq_t()), 1);
}

// Approx::of(x) for an integer x below 2^125 in magnitude: x truncated
// toward zero to 53 significant bits (a normal double), exact or with the
// truncation bound, as Approx::of gives it.
Approx truncated_integer(Int128 x) noexcept {
  const Uint128 m = magnitude(x);
  const int bits = 128 - (static_cast<std::uint64_t>(m >> 64) != 0
                              ? std::countl_zero(static_cast<std::uint64_t>(m >> 64))
                              : 64 + std::countl_zero(static_cast<std::uint64_t>(m)));
  if (bits <= 53) {
    const double d = static_cast<double>(static_cast<std::uint64_t>(m));  // exact
    return {x < 0 ? -d : d, 0.0};
  }
  const int shift = bits - 53;
  const bool exact = (m & ((Uint128{1} << shift) - 1)) == 0;
  const double d = std::ldexp(static_cast<double>(static_cast<std::uint64_t>(m >> shift)), shift);
  const double value = x < 0 ? -d : d;
  return {value, exact ? 0.0 : filtered::truncation_error(value)};
}

// A finite nonzero double as odd mantissa * 2^exponent, read off its bits.
struct Decomposed {
  std::int64_t mantissa;
  int exponent;
};

Decomposed decompose(double d) noexcept {
  const auto bits = std::bit_cast<std::uint64_t>(d);
  const auto biased = static_cast<int>((bits >> 52) & 0x7ff);
  std::uint64_t m = bits & ((std::uint64_t{1} << 52) - 1);
  int e = -1074;  // subnormal
  if (biased != 0) {
    m |= std::uint64_t{1} << 52;
    e = biased - 1075;
  }
  const int zeros = std::countr_zero(m);
  const auto mantissa = static_cast<std::int64_t>(m >> zeros);
  return {(bits >> 63) != 0 ? -mantissa : mantissa, e + zeros};
}

}  // namespace

Vec3 SmallDirection::to_vec3() const {
  return {Rational(static_cast<long>(c[0])), Rational(static_cast<long>(c[1])),
          Rational(static_cast<long>(c[2]))};
}

std::optional<SmallDirection> small_integer_direction(const ApproxVec3& from, const ApproxVec3& to) noexcept {
  const Approx* coordinates[2][3] = {{&from.x, &from.y, &from.z}, {&to.x, &to.y, &to.z}};
  Decomposed parts[2][3];
  int lowest = 0;
  bool any = false;
  for (int p = 0; p < 2; ++p)
    for (int i = 0; i < 3; ++i) {
      const Approx& a = *coordinates[p][i];
      if (a.error != 0.0 || !std::isfinite(a.value)) return std::nullopt;
      if (a.value == 0.0) {
        parts[p][i] = {0, 0};
        continue;
      }
      parts[p][i] = decompose(a.value);
      lowest = any ? std::min(lowest, parts[p][i].exponent) : parts[p][i].exponent;
      any = true;
    }
  if (!any) return std::nullopt;
  // In units of 2^lowest every value is mantissa 2^(exponent - lowest); with
  // shifts up to 72 each is below 2^125 and a difference below 2^126.
  constexpr int max_shift = 72;
  Int128 d[3];
  for (int i = 0; i < 3; ++i) {
    Int128 v[2];
    for (int p = 0; p < 2; ++p) {
      const Decomposed& part = parts[p][i];
      const int shift = part.exponent - lowest;
      if (shift > max_shift) return std::nullopt;
      v[p] = part.mantissa == 0 ? 0 : static_cast<Int128>(part.mantissa) * (Int128{1} << shift);
    }
    d[i] = v[1] - v[0];
  }
  const Uint128 any_bits = magnitude(d[0]) | magnitude(d[1]) | magnitude(d[2]);
  if (any_bits == 0) return std::nullopt;
  // Dropping the common power of two is cheap and is most of the gcd of
  // double differences; primitive_cross removes whatever remains.
  const int common = countr_zero(any_bits);
  constexpr Int128 limit = Int128{1} << 62;
  SmallDirection result{};
  for (int i = 0; i < 3; ++i) {
    const Int128 c = d[i] >> common;  // exact: 2^common divides d[i]
    if (c >= limit || c <= -limit) return std::nullopt;
    result.c[static_cast<std::size_t>(i)] = static_cast<std::int64_t>(c);
  }
  return result;
}

namespace {

// The limits of the fraction directions: scaled coordinates below 2^61 in
// magnitude make differences below 2^62 (SmallDirection's bound); a common
// denominator below 2^63 keeps the lcm's steps (a one-limb quotient times a
// one-limb denominator) and the scaling (a factor below 2^63 times a
// one-limb numerator) within 128-bit products. Shortest round-trip decimals
// of doubles of magnitude near 1 have denominators up to about 10^17 (< 2^57)
// and 6-digit ones 10^6, so both fit.
constexpr std::uint64_t max_denominator = std::uint64_t{1} << 63;
constexpr Int128 max_scaled = Int128{1} << 61;

// The lcm of the points' denominators, or 0 when one is not one limb or the
// lcm reaches max_denominator.
std::uint64_t common_denominator(std::span<const Vec3* const> points) {
  std::uint64_t l = 1;
  for (const Vec3* p : points)
    for (int i = 0; i < 3; ++i) {
      mpz_srcptr den = (*p)[i].get_den_mpz_t();
      if (mpz_size(den) != 1) return 0;
      const std::uint64_t d = mpz_getlimbn(den, 0);
      if (l % d == 0) continue;
      const Uint128 next = Uint128{l / std::gcd(l, d)} * d;
      if (next >= max_denominator) return 0;
      l = static_cast<std::uint64_t>(next);
    }
  return l;
}

// x * l as an integer (l a multiple of x's denominator), when it is below
// max_scaled in magnitude.
std::optional<Int128> scaled(const Rational& x, std::uint64_t l) {
  mpz_srcptr num = x.get_num_mpz_t();
  if (mpz_size(num) > 1) return std::nullopt;
  const Uint128 factor = l / mpz_getlimbn(x.get_den_mpz_t(), 0);  // exact: the den divides l
  const Uint128 magnitude = factor * mpz_getlimbn(num, 0);       // below 2^63 * 2^64: no overflow
  if (magnitude >= static_cast<Uint128>(max_scaled)) return std::nullopt;
  return mpz_sgn(num) < 0 ? -static_cast<Int128>(magnitude) : static_cast<Int128>(magnitude);
}

// (points[p] - points[0]) * L for p = 1 .. n-1, L the lcm of all the points'
// denominators, into out[p - 1]; false when a limit above is exceeded or a
// difference is zero.
bool scaled_differences(std::span<const Vec3* const> points, std::span<SmallDirection> out) {
  const std::uint64_t l = common_denominator(points);
  if (l == 0) return false;
  Int128 origin[3];
  for (int i = 0; i < 3; ++i) {
    const std::optional<Int128> x = scaled((*points[0])[i], l);
    if (!x) return false;
    origin[i] = *x;
  }
  for (std::size_t p = 1; p < points.size(); ++p) {
    auto& v = out[p - 1].c;
    for (int i = 0; i < 3; ++i) {
      const std::optional<Int128> x = scaled((*points[p])[i], l);
      if (!x) return false;
      v[static_cast<std::size_t>(i)] = static_cast<std::int64_t>(*x - origin[i]);  // below 2^62: both below 2^61
    }
    if (v[0] == 0 && v[1] == 0 && v[2] == 0) return false;
  }
  return true;
}

}  // namespace

std::optional<SmallDirection> small_fraction_direction(const Vec3& from, const Vec3& to) {
  const Vec3* const points[2] = {&from, &to};
  std::array<SmallDirection, 1> d{};
  if (!scaled_differences(points, d)) return std::nullopt;
  return d[0];
}

std::optional<std::array<SmallDirection, 2>> small_fraction_directions(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3* const points[3] = {&a, &b, &c};
  std::array<SmallDirection, 2> d{};
  if (!scaled_differences(points, d)) return std::nullopt;
  return d;
}

SmallNormal primitive_cross(const SmallDirection& u, const SmallDirection& v) noexcept {
  // Each product is below 2^124 in magnitude, each difference below 2^125.
  Int128 c[3];
  for (int i = 0; i < 3; ++i) {
    const auto j = static_cast<std::size_t>((i + 1) % 3), k = static_cast<std::size_t>((i + 2) % 3);
    c[i] = static_cast<Int128>(u.c[j]) * v.c[k] - static_cast<Int128>(u.c[k]) * v.c[j];
  }
  make_primitive(c);
  return {{c[0], c[1], c[2]}};
}

SmallNormal primitive_vector(Int128 x, Int128 y, Int128 z) noexcept {
  Int128 c[3] = {x, y, z};
  make_primitive(c);
  return {{c[0], c[1], c[2]}};
}

std::optional<SmallDirection> as_small_direction(const SmallNormal& v) noexcept {
  constexpr Uint128 limit = Uint128{1} << 62;
  if (magnitude(v.c[0]) >= limit || magnitude(v.c[1]) >= limit || magnitude(v.c[2]) >= limit) return std::nullopt;
  return SmallDirection{{static_cast<std::int64_t>(v.c[0]), static_cast<std::int64_t>(v.c[1]),
                         static_cast<std::int64_t>(v.c[2])}};
}

std::optional<SmallDirection> small_multiple(Int128 x, Int128 y, Int128 z) noexcept {
  Uint128 m[3] = {magnitude(x), magnitude(y), magnitude(z)};
  const int twos = countr_zero(m[0] | m[1] | m[2]);  // nonzero
  for (Uint128& v : m) v >>= twos;
  // While all three are multiples of 5 (ends: some coordinate is nonzero).
  for (Uint128 q[3] = {m[0], m[1], m[2]}; divide_by_5(q[0]) && divide_by_5(q[1]) && divide_by_5(q[2]);)
    for (int i = 0; i < 3; ++i) m[i] = q[i];
  constexpr Uint128 limit = Uint128{1} << 62;
  if (m[0] < limit && m[1] < limit && m[2] < limit)
    return SmallDirection{{static_cast<std::int64_t>(x < 0 ? -m[0] : m[0]),
                           static_cast<std::int64_t>(y < 0 ? -m[1] : m[1]),
                           static_cast<std::int64_t>(z < 0 ? -m[2] : m[2])}};
  return as_small_direction(primitive_vector(x, y, z));
}

void SmallNormal::negate() noexcept {
  for (Int128& x : c) x = -x;
}

ApproxVec3 SmallNormal::approx() const noexcept {
  ApproxVec3 out;
  Approx* parts[3] = {&out.x, &out.y, &out.z};
  for (std::size_t i = 0; i < 3; ++i) *parts[i] = truncated_integer(c[i]);
  return out;
}

void SmallNormal::assign_to(Vec3& out) const {
  for (std::size_t i = 0; i < 3; ++i) set_integer(out[static_cast<int>(i)], c[i]);
}

void SmallNormal::pack(LimbArena& arena, DyadicPoints& out, std::size_t j) const {
  for (std::size_t i = 0; i < 3; ++i) {
    const Uint128 m = magnitude(c[i]);
    FixedDyadic<2> value;
    value.numerator.magnitude = {static_cast<std::uint64_t>(m), static_cast<std::uint64_t>(m >> 64)};
    value.numerator.negative = c[i] < 0;
    pack_dyadic(value, arena, out.coordinate(j, static_cast<int>(i)));
  }
}

void SmallNormal::store(LimbArena& arena, Vec3& out) const {
  for (std::size_t i = 0; i < 3; ++i) {
    const Uint128 m = magnitude(c[i]);
    arena.store_integer(out[static_cast<int>(i)], static_cast<std::uint64_t>(m), static_cast<std::uint64_t>(m >> 64),
                        c[i] < 0);
  }
}

}  // namespace cvms::detail
