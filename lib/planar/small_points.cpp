// SPDX-License-Identifier: MIT
// The common denominator of small_points.hpp: one pass for L over machine
// words (a gcd per coordinate whose denominator is new), one for the scaled
// numerators, each refusing as soon as a bound is passed.
#include "small_points.hpp"

#include <numeric>

namespace cvms::detail {
namespace {

// Scaled coordinates stay below this in magnitude, so that an edge vector's
// coordinates (differences of two) stay below 2^63.
constexpr std::uint64_t kBound = std::uint64_t{1} << 62;

// lcm(l, den(r)) into l; false once it reaches kBound.
bool absorb_denominator(std::uint64_t& l, const Rational& r) {
  mpz_srcptr den = mpq_denref(r.get_mpq_t());
  if (mpz_size(den) != 1) return false;  // denominators are >= 1: one limb or more
  const std::uint64_t d = mpz_getlimbn(den, 0);
  if (l % d == 0) return true;
  const std::uint64_t factor = d / std::gcd(l, d);
  std::uint64_t product = 0;
  if (__builtin_mul_overflow(l, factor, &product) || product >= kBound) return false;
  l = product;
  return true;
}

// l * r into out (an integer: den(r) divides l); false from kBound on.
bool scaled(std::uint64_t l, const Rational& r, std::int64_t& out) {
  mpz_srcptr num = mpq_numref(r.get_mpq_t());
  const std::size_t limbs = mpz_size(num);
  if (limbs == 0) {
    out = 0;
    return true;
  }
  if (limbs != 1) return false;
  const std::uint64_t multiplier = l / mpz_getlimbn(mpq_denref(r.get_mpq_t()), 0);
  std::uint64_t magnitude = 0;
  if (__builtin_mul_overflow(mpz_getlimbn(num, 0), multiplier, &magnitude) || magnitude >= kBound) return false;
  out = mpz_sgn(num) < 0 ? -static_cast<std::int64_t>(magnitude) : static_cast<std::int64_t>(magnitude);
  return true;
}

bool scale(std::uint64_t l, std::span<const Vec2> points, std::vector<SmallPoint2>& out) {
  out.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!scaled(l, points[i].x, out[i].x) || !scaled(l, points[i].y, out[i].y)) return false;
  }
  return true;
}

}  // namespace

bool scale_to_small_points(std::span<const Vec2> p, std::span<const Vec2> q, std::vector<SmallPoint2>& sp,
                           std::vector<SmallPoint2>& sq) {
  if constexpr (sizeof(mp_limb_t) != sizeof(std::uint64_t)) return false;  // limbs read as 64-bit words
  std::uint64_t l = 1;
  for (std::span<const Vec2> points : {p, q}) {
    for (const Vec2& point : points) {
      if (!absorb_denominator(l, point.x) || !absorb_denominator(l, point.y)) return false;
    }
  }
  return scale(l, p, sp) && scale(l, q, sq);
}

}  // namespace cvms::detail
