// SPDX-License-Identifier: MIT
// Gcd-free exact arithmetic for dyadic rationals (see the header).
#include "dyadic.hpp"

#include <algorithm>
#include <bit>

#include "word_fraction.hpp"

namespace cvms::detail {
namespace {

// Stores num / 2^k into out, reducing by the common power of two first.
void set_reduced_dyadic(mpq_ptr out, mpz_ptr num, mp_bitcnt_t k) {
  if (mpz_sgn(num) == 0) {
    mpz_set_ui(mpq_denref(out), 1);
    mpz_set_ui(mpq_numref(out), 0);
    return;
  }
  const mp_bitcnt_t common = std::min(mpz_scan1(num, 0), k);  // the lowest set bit is the same for -num
  if (common > 0) mpz_tdiv_q_2exp(num, num, common);          // exact: 2^common divides num
  if (num != mpq_numref(out)) mpz_set(mpq_numref(out), num);
  mpz_set_ui(mpq_denref(out), 0);
  mpz_setbit(mpq_denref(out), k - common);
}

// out = x + y or x - y (canonical) in GMP, for operands the machine-word
// path (fixed_sum) declined: the operand with the smaller power-of-two
// denominator is brought to the larger one. With different denominators the
// finer numerator is odd and the other term even, so the result is already
// canonical and set_reduced_dyadic only writes the denominator.
void exact_add_or_subtract(Rational& out, const Rational& x, const Rational& y, bool subtract) {
  if (!is_dyadic(x) || !is_dyadic(y)) {
    (subtract ? mpq_sub : mpq_add)(out.get_mpq_t(), x.get_mpq_t(), y.get_mpq_t());
    return;
  }
  const mp_bitcnt_t kx = log2_of_power_of_two(x.get_den_mpz_t());
  const mp_bitcnt_t ky = log2_of_power_of_two(y.get_den_mpz_t());
  const mp_bitcnt_t k = std::max(kx, ky);
  mpz_ptr num = mpq_numref(out.get_mpq_t());
  auto combine = subtract ? mpz_sub : mpz_add;
  if (kx >= ky) {
    mpz_mul_2exp(num, y.get_num_mpz_t(), k - ky);
    combine(num, x.get_num_mpz_t(), num);
  } else {
    mpz_mul_2exp(num, x.get_num_mpz_t(), k - kx);
    combine(num, num, y.get_num_mpz_t());
  }
  set_reduced_dyadic(out.get_mpq_t(), num, k);
}

template <int L>
void assign_fixed(Rational& out, FixedDyadic<L> value) {
  const mp_bitcnt_t exponent = reduce_dyadic(value.numerator.magnitude, value.exponent);
  assign_dyadic(out, value.numerator.magnitude.data(), L, value.numerator.negative, exponent);
}

void add_or_subtract(Rational& out, const Rational& x, const Rational& y, bool subtract) {
  if (std::optional<FixedDyadic<2>> fixed = subtract ? fixed_difference(x, y) : fixed_sum(x, y)) {
    assign_fixed(out, *fixed);
  } else {
    exact_add_or_subtract(out, x, y, subtract);
  }
}

}  // namespace

void add_into(Rational& out, const Rational& x, const Rational& y) { add_or_subtract(out, x, y, false); }

void subtract_into(Rational& out, const Rational& x, const Rational& y) { add_or_subtract(out, x, y, true); }

Vec3 add(const Vec3& x, const Vec3& y) {
  Vec3 sum;
  for (int i = 0; i < 3; ++i) add_into(sum[i], x[i], y[i]);
  return sum;
}

Vec3 subtract(const Vec3& x, const Vec3& y) {
  Vec3 difference;
  for (int i = 0; i < 3; ++i) subtract_into(difference[i], x[i], y[i]);
  return difference;
}

namespace {

__extension__ using Word2 = unsigned __int128;

// A dyadic value whose numerator and denominator fit one limb each:
// (negative ? -magnitude : magnitude) / 2^exponent, exponent below 64.
struct OneLimbDyadic {
  std::uint64_t magnitude;
  bool negative;
  unsigned exponent;
};

// Read with GMP's inline accessors only (no call per coordinate).
bool read_one_limb(const Rational& q, OneLimbDyadic& out) noexcept {
  mpz_srcptr num = q.get_num_mpz_t();
  mpz_srcptr den = q.get_den_mpz_t();
  if (mpz_size(num) > 1 || mpz_size(den) != 1) return false;
  const mp_limb_t d = mpz_getlimbn(den, 0);
  if ((d & (d - 1)) != 0) return false;
  out = {mpz_getlimbn(num, 0), mpz_sgn(num) < 0, static_cast<unsigned>(std::countr_zero(d))};
  return true;
}

// A signed integer of five limbs in two's complement, the accumulator of
// fixed_integer_dot.
struct Accumulator5 {
  std::uint64_t w[5] = {0, 0, 0, 0, 0};

  // Adds or subtracts the four-limb magnitude x.
  void add(const std::uint64_t (&x)[4], bool subtract) noexcept {
    std::uint64_t carry = subtract ? 1 : 0;  // x's two's complement is ~x + 1
    const std::uint64_t flip = subtract ? ~std::uint64_t{0} : 0;
    for (int i = 0; i < 5; ++i) {
      const Word2 t = Word2{w[i]} + ((i < 4 ? x[i] : 0) ^ flip) + carry;
      w[i] = static_cast<std::uint64_t>(t);
      carry = static_cast<std::uint64_t>(t >> 64);
    }
  }

  [[nodiscard]] FixedInt<5> value() const noexcept {
    FixedInt<5> r;
    r.negative = (w[4] >> 63) != 0;
    std::uint64_t carry = r.negative ? 1 : 0;
    const std::uint64_t flip = r.negative ? ~std::uint64_t{0} : 0;
    for (std::size_t i = 0; i < 5; ++i) {
      const Word2 t = Word2{w[i] ^ flip} + carry;
      r.magnitude[i] = static_cast<std::uint64_t>(t);
      carry = static_cast<std::uint64_t>(t >> 64);
    }
    return r;
  }
};

}  // namespace

mp_bitcnt_t reduce_dyadic(std::span<std::uint64_t> magnitude, mp_bitcnt_t exponent) noexcept {
  const std::size_t n = magnitude.size();
  std::size_t zero_limbs = 0;
  while (zero_limbs < n && magnitude[zero_limbs] == 0) ++zero_limbs;
  if (zero_limbs == n) return 0;  // zero is 0/1
  const mp_bitcnt_t trailing =
      zero_limbs * 64 + static_cast<mp_bitcnt_t>(std::countr_zero(magnitude[zero_limbs]));
  const mp_bitcnt_t common = std::min(trailing, exponent);
  if (common == 0) return exponent;
  const std::size_t whole = common / 64;
  const unsigned bits = common % 64;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t low = i + whole < n ? magnitude[i + whole] : 0;
    const std::uint64_t high = i + whole + 1 < n ? magnitude[i + whole + 1] : 0;
    magnitude[i] = bits == 0 ? low : (low >> bits) | (high << (64 - bits));
  }
  return exponent - common;
}

namespace {

std::optional<FixedDyadic<2>> fixed_combination(const Rational& x, const Rational& y,
                                                bool subtract) noexcept {
  OneLimbDyadic a, b;
  if (!read_one_limb(x, a) || !read_one_limb(y, b)) return std::nullopt;
  b.negative = b.negative != subtract;
  const unsigned k = std::max(a.exponent, b.exponent);
  // Each term is below 2^(64 + 63), so their sum is below 2^128.
  const Word2 ta = Word2{a.magnitude} << (k - a.exponent);
  const Word2 tb = Word2{b.magnitude} << (k - b.exponent);
  FixedDyadic<2> r;
  r.exponent = k;
  Word2 m;
  if (a.negative == b.negative) {
    m = ta + tb;
    r.numerator.negative = a.negative;
  } else {
    const bool a_larger = ta >= tb;
    m = a_larger ? ta - tb : tb - ta;
    r.numerator.negative = a_larger ? a.negative : b.negative;
  }
  r.numerator.magnitude[0] = static_cast<std::uint64_t>(m);
  r.numerator.magnitude[1] = static_cast<std::uint64_t>(m >> 64);
  return r;
}

}  // namespace

std::optional<FixedDyadic<2>> fixed_sum(const Rational& x, const Rational& y) noexcept {
  return fixed_combination(x, y, false);
}

std::optional<FixedDyadic<2>> fixed_difference(const Rational& x, const Rational& y) noexcept {
  return fixed_combination(x, y, true);
}

std::optional<FixedDyadic<5>> fixed_integer_dot(const Vec3& n, const Vec3& p) noexcept {
  OneLimbDyadic c[3];
  unsigned k = 0;
  for (int i = 0; i < 3; ++i) {
    mpz_srcptr ni = n[i].get_num_mpz_t();
    if (mpz_size(ni) > 2) return std::nullopt;
    c[i] = {0, false, 0};
    if (mpz_sgn(ni) != 0 && !read_one_limb(p[i], c[i])) return std::nullopt;
    k = std::max(k, c[i].exponent);
  }
  Accumulator5 sum;
  for (int i = 0; i < 3; ++i) {
    mpz_srcptr ni = n[i].get_num_mpz_t();
    if (mpz_sgn(ni) == 0 || c[i].magnitude == 0) continue;
    // |n_i| m_i in three limbs (below 2^192), then shifted by s < 64 into four.
    const Word2 low = Word2{mpz_getlimbn(ni, 0)} * c[i].magnitude;
    const Word2 high = Word2{mpz_getlimbn(ni, 1)} * c[i].magnitude;
    const Word2 middle = (low >> 64) + static_cast<std::uint64_t>(high);
    const std::uint64_t w0 = static_cast<std::uint64_t>(low);
    const std::uint64_t w1 = static_cast<std::uint64_t>(middle);
    const std::uint64_t w2 =
        static_cast<std::uint64_t>(high >> 64) + static_cast<std::uint64_t>(middle >> 64);
    const unsigned s = k - c[i].exponent;
    std::uint64_t term[4] = {w0, w1, w2, 0};
    if (s != 0) {
      term[3] = w2 >> (64 - s);
      term[2] = (w2 << s) | (w1 >> (64 - s));
      term[1] = (w1 << s) | (w0 >> (64 - s));
      term[0] = w0 << s;
    }
    sum.add(term, (mpz_sgn(ni) < 0) != c[i].negative);
  }
  return FixedDyadic<5>{sum.value(), k};
}

namespace {

// integer_dot in GMP, for the operands fixed_integer_dot declined.
void exact_integer_dot(const Vec3& n, const Vec3& p, DotScratch& scratch, Rational& out) {
  mpz_class& sum = scratch.sum;
  mpz_class& term = scratch.term;
  sum = 0;
  if (is_dyadic(p.x) && is_dyadic(p.y) && is_dyadic(p.z)) {
    mp_bitcnt_t k = 0;
    for (int i = 0; i < 3; ++i) k = std::max(k, log2_of_power_of_two(p[i].get_den_mpz_t()));
    for (int i = 0; i < 3; ++i) {
      if (mpz_sgn(n[i].get_num_mpz_t()) == 0 || mpz_sgn(p[i].get_num_mpz_t()) == 0) continue;
      mpz_mul_2exp(term.get_mpz_t(), p[i].get_num_mpz_t(), k - log2_of_power_of_two(p[i].get_den_mpz_t()));
      mpz_addmul(sum.get_mpz_t(), term.get_mpz_t(), n[i].get_num_mpz_t());
    }
    set_reduced_dyadic(out.get_mpq_t(), sum.get_mpz_t(), k);
    return;
  }
  mpz_class& l = scratch.denominator;
  l = p.x.get_den();
  for (int i = 1; i < 3; ++i)
    if (p[i].get_den() != l) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), p[i].get_den_mpz_t());
  for (int i = 0; i < 3; ++i) {
    if (mpz_sgn(n[i].get_num_mpz_t()) == 0 || mpz_sgn(p[i].get_num_mpz_t()) == 0) continue;
    mpz_divexact(term.get_mpz_t(), l.get_mpz_t(), p[i].get_den_mpz_t());
    term *= p[i].get_num();
    mpz_addmul(sum.get_mpz_t(), term.get_mpz_t(), n[i].get_num_mpz_t());
  }
  mpz_set(mpq_numref(out.get_mpq_t()), sum.get_mpz_t());
  mpz_set(mpq_denref(out.get_mpq_t()), l.get_mpz_t());
  out.canonicalize();
}

}  // namespace

void store_sum(LimbArena& arena, Rational& out, const Rational& x, const Rational& y, Rational& scratch) {
  if (const std::optional<FixedDyadic<2>> sum = fixed_sum(x, y)) {
    store_dyadic(arena, out, *sum);
    return;
  }
  if (const std::optional<WordFraction> sum = word_fraction_sum(x, y)) {  // decimals as files hold them
    store_word_fraction(arena, out, *sum);
    return;
  }
  exact_add_or_subtract(scratch, x, y, false);
  arena.store(out, scratch);
}

void store_integer_dot(LimbArena& arena, Rational& out, const Vec3& n, const Vec3& p, DotScratch& scratch) {
  if (const std::optional<FixedDyadic<5>> dot = fixed_integer_dot(n, p)) {
    store_dyadic(arena, out, *dot);
    return;
  }
  exact_integer_dot(n, p, scratch, scratch.value);
  arena.store(out, scratch.value);
}

void integer_dot(const Vec3& n, const Vec3& p, DotScratch& scratch, Rational& out) {
  if (std::optional<FixedDyadic<5>> dot = fixed_integer_dot(n, p)) {
    assign_fixed(out, *dot);
  } else {
    exact_integer_dot(n, p, scratch, out);
  }
}

}  // namespace cvms::detail
