// SPDX-License-Identifier: MIT
// nearest_double_sqrt(): the double nearest to sqrt(q), correctly rounded.
// Scale q = 4^k r with r in [1, 16) or so (exact: k from the bit lengths), so
// that sqrt(r) is far from overflow and underflow; start from the double
// square root of r's nearest double (within a few ulps of sqrt(r)) and move
// to a neighbour while it is nearer: for doubles x < y, sqrt(r) is nearer to
// y iff r > ((x + y) / 2)^2, an exact rational comparison. Then scale back by
// 2^k, exact unless the result is below 2^-1022: there the doubles are the
// multiples of 2^-1074, and scaling back would round a second time, so the
// answer is found directly as the integer j nearest to sqrt(q 2^2148):
// j0 = isqrt(floor(m)) = floor(sqrt(m)) for m = q 2^2148, and sqrt(m) is
// nearer to j0 + 1 iff m > (j0 + 1/2)^2 (ties to even j).
#include <cmath>

#include "cvms/error.hpp"
#include "cvms/proximity.hpp"

namespace cvms {
namespace {

long bit_length(const mpz_class& z) { return static_cast<long>(mpz_sizeinbase(z.get_mpz_t(), 2)); }

Rational power_of_four(long k) {
  mpz_class p = 1;
  mpz_mul_2exp(p.get_mpz_t(), p.get_mpz_t(), static_cast<mp_bitcnt_t>(2 * (k < 0 ? -k : k)));
  return k >= 0 ? Rational(p) : Rational(mpz_class(1), p);
}

Rational midpoint_squared(double x, double y) {
  const Rational m = (Rational(x) + Rational(y)) / 2;
  return m * m;
}

bool is_even(double x) {
  int e = 0;
  const double m = std::frexp(x, &e);
  return std::fmod(std::ldexp(m, 53), 2.0) == 0.0;
}

// The nearest multiple of 2^-1074 to sqrt(q), for q below 2^-2042 (every
// multiple below 2^-1021 is a double).
double nearest_small_sqrt(const Rational& q) {
  mpz_class num = q.get_num();
  mpz_mul_2exp(num.get_mpz_t(), num.get_mpz_t(), 2148);
  mpz_class j = num / q.get_den();  // floor(m), m >= 0
  mpz_sqrt(j.get_mpz_t(), j.get_mpz_t());
  // 4m against 4 (j + 1/2)^2 = 4j^2 + 4j + 1, over the denominator.
  const mpz_class four_m = 4 * num;
  const mpz_class midpoint = (4 * j * j + 4 * j + 1) * q.get_den();
  const int c = cmp(four_m, midpoint);
  if (c > 0 || (c == 0 && mpz_odd_p(j.get_mpz_t()) != 0)) ++j;
  return std::ldexp(j.get_d(), -1074);  // j < 2^53: exact
}

}  // namespace

double nearest_double_sqrt(const Rational& q) {
  if (sgn(q) < 0) throw Error(ErrorCategory::invalid_argument, "nearest_double_sqrt: negative argument " + to_string(q));
  if (sgn(q) == 0) return 0.0;
  const long k = (bit_length(q.get_num()) - bit_length(q.get_den())) / 2;
  const Rational r = q / power_of_four(k);
  double d = std::sqrt(to_double_nearest(r));
  for (;;) {
    const double up = std::nextafter(d, HUGE_VAL);
    const int c = cmp(r, midpoint_squared(d, up));
    if (c > 0 || (c == 0 && is_even(up))) {
      d = up;
      continue;
    }
    const double down = std::nextafter(d, 0.0);
    const int c2 = cmp(r, midpoint_squared(down, d));
    if (c2 < 0 || (c2 == 0 && is_even(down))) {
      d = down;
      continue;
    }
    break;
  }
  const double scaled = std::ldexp(d, static_cast<int>(k));
  return scaled >= 0x1p-1022 ? scaled : nearest_small_sqrt(q);
}

}  // namespace cvms
