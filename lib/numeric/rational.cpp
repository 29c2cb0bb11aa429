// SPDX-License-Identifier: MIT
// Exact decimal/fraction parsing and printing. Decimal text is parsed by
// building the integer of its significant digits and scaling it by a power of
// ten, so "0.1" is exactly 1/10 (never the double nearest to it); the size of
// that power is known from the text before it is built (rational_text.hpp).
#include "cvms/rational.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>

#include "cvms/error.hpp"
#include "exact_double.hpp"
#include "rational_text.hpp"

namespace cvms {
namespace detail {
namespace {

__extension__ using Int128 = __int128;
__extension__ using Uint128 = unsigned __int128;

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// ---- Eight digits at a time ---------------------------------------------
// A little-endian machine reads eight characters as one word, the first in
// the low byte; checking that they are all digits and taking their value
// then cost a few word operations instead of a loop step per character
// (those steps were two thirds of parsing an exact double expansion). Other
// machines take the loops.
constexpr bool words_of_digits = std::endian::native == std::endian::little;

std::uint64_t load_eight(const char* p) {
  std::uint64_t w;
  std::memcpy(&w, p, sizeof w);
  return w;
}

// Whether the eight bytes of w are all '0'..'9': a byte is a digit exactly
// when its high nibble is 3 and adding 6 leaves it 3 (0x30..0x39 become
// 0x36..0x3F, 0x3A..0x3F become 0x40..0x45). A carry out of a byte comes
// only from a byte of 0xFA or more, whose own high nibble already fails.
bool eight_digits(std::uint64_t w) {
  constexpr std::uint64_t high = 0xF0F0F0F0F0F0F0F0u;
  return ((w & high) | (((w + 0x0606060606060606u) & high) >> 4)) == 0x3333333333333333u;
}

// The value of eight digit characters, the first the most significant:
// adjacent bytes, then 16-bit lanes, then 32-bit lanes are combined as
// 10 a + b, 100 a + b and 10^4 a + b; no lane overflows (99 < 2^8,
// 9,999 < 2^16, 99,999,999 < 2^32).
std::uint64_t eight_digit_value(std::uint64_t w) {
  w -= 0x3030303030303030u;
  w = (w * 10 + (w >> 8)) & 0x00FF00FF00FF00FFu;
  w = (w * 100 + (w >> 16)) & 0x0000FFFF0000FFFFu;
  return (w * 10000 + (w >> 32)) & 0xFFFFFFFFu;
}

// The first and the last position of a mantissa (digits and at most one
// '.') that holds a digit other than 0; npos if none does.
std::size_t first_significant(std::string_view mantissa) {
  for (std::size_t i = 0; i < mantissa.size(); ++i)
    if (mantissa[i] != '0' && mantissa[i] != '.') return i;
  return std::string_view::npos;
}
std::size_t last_significant(std::string_view mantissa) {
  for (std::size_t i = mantissa.size(); i-- > 0;)
    if (mantissa[i] != '0' && mantissa[i] != '.') return i;
  return std::string_view::npos;
}

// The end of the run of digits of text that starts at i.
std::size_t digit_run_end(std::string_view text, std::size_t i) {
  if constexpr (words_of_digits)
    while (i + 8 <= text.size() && eight_digits(load_eight(text.data() + i))) i += 8;
  while (i < text.size() && is_digit(text[i])) ++i;
  return i;
}

// floor(n log2(10)) from below (332192809 / 10^8 < log2(10)), saturating
// far beyond any cap; the same for log2(5).
std::uint64_t times_floor(std::uint64_t n, std::uint64_t per_10e8) {
  constexpr std::uint64_t saturated = gmp_max_bits * 4;
  if (n < (std::uint64_t{1} << 32)) return n * per_10e8 / 100000000;  // no 128-bit division per token
  return n > saturated ? saturated : static_cast<std::uint64_t>(n * Uint128{per_10e8} / 100000000);
}
std::uint64_t times_log2_10_floor(std::uint64_t n) { return times_floor(n, 332192809); }
std::uint64_t times_log2_5_floor(std::uint64_t n) { return times_floor(n, 232192809); }

// Sets z to the decimal digits of text (all digits, except a single '.'
// that is skipped). Up to 19 digits never touch the heap.
void set_digits(mpz_ptr z, std::string_view digits) {
  if (digits.size() - (digits.find('.') != std::string_view::npos ? 1 : 0) <= 19) {
    std::uint64_t value = 0;
    for (char c : digits)
      if (c != '.') value = value * 10 + static_cast<std::uint64_t>(c - '0');
    mpz_set_ui(z, value);
    return;
  }
  std::string nul_terminated;  // mpz_set_str needs one
  nul_terminated.reserve(digits.size());
  for (char c : digits)
    if (c != '.') nul_terminated += c;
  mpz_set_str(z, nul_terminated.c_str(), 10);
}

// The bit length of a number of `count` significant decimal digits, from below.
std::uint64_t bits_of_digits_at_least(std::uint64_t count) { return times_log2_10_floor(count - 1) + 1; }

// ---- The fast path: decimals of at most a few hundred digits ----------------
// The usual OBJ/STL/OFF content is a short decimal ("0.123456") or the exact
// expansion of a double (about 17 to 60 digits, always dyadic); both are built
// here from machine words: the digits into limbs 19 at a time, the factors 2
// and 5 of 10^k cancelled by counting them (M is not a multiple of 10, so at
// most one of them cancels), never a general gcd, a digit string or a power
// of ten. It takes only values whose parts are within max_bits by an upper
// bound read off the text, so it never refuses what the general path would
// accept and never builds more than the caps: its results are those of the
// general path (test/rational_test.cpp compares them).

static_assert(GMP_NUMB_BITS == 64, "the fast path assumes 64-bit limbs");

constexpr std::size_t small_limbs = 16;          // 1024 bits: about 308 digits
constexpr std::uint64_t small_max_digits = 300;  // fits small_limbs with room
constexpr std::uint64_t small_max_scale = 350;   // |10^scale| of at most 1163 bits

constexpr unsigned max_pow5_in_limb = 27;  // 5^27 < 2^63, 5^28 > 2^64
constexpr auto pow5_table = [] {
  std::array<std::uint64_t, max_pow5_in_limb + 1> table{};
  table[0] = 1;
  for (std::size_t i = 1; i < table.size(); ++i) table[i] = table[i - 1] * 5;
  return table;
}();
std::uint64_t pow5(unsigned n) { return pow5_table[n]; }

// The inverse of an odd d modulo 2^64, by Newton's iteration x <- x (2 - d x),
// which doubles the number of correct low bits: d itself is right to 3 bits
// (d^2 = 1 mod 8 for every odd d), five steps make 96 >= 64.
constexpr std::uint64_t inverse_mod_2_64(std::uint64_t d) {
  std::uint64_t x = d;
  for (int i = 0; i < 5; ++i) x *= 2 - d * x;
  return x;
}
constexpr auto pow5_inverse_table = [] {
  std::array<std::uint64_t, max_pow5_in_limb + 1> table{};
  for (std::size_t i = 0; i < table.size(); ++i) table[i] = inverse_mod_2_64(pow5_table[i]);
  return table;
}();
static_assert([] {
  for (std::size_t i = 0; i < pow5_table.size(); ++i)
    if (pow5_table[i] * pow5_inverse_table[i] != 1) return false;
  return true;
}());
constexpr mp_limb_t ten_to_19 = 10000000000000000000u;  // < 2^64

// Bits of a number of `count` decimal digits, from above (log2(10) < 3.33).
std::uint64_t bits_of_digits_at_most(std::uint64_t count) { return count * 333 / 100 + 1; }

// A non-negative integer of at most small_limbs limbs, least significant first.
struct SmallNatural {
  mp_limb_t limbs[small_limbs];
  mp_size_t size = 0;  // no high zero limbs; 0 for zero

  void multiply_add(mp_limb_t factor, mp_limb_t addend) {
    mp_limb_t carry = size == 0 ? addend : mpn_mul_1(limbs, limbs, size, factor);
    if (size == 0) {
      if (addend != 0) limbs[size++] = addend;
      return;
    }
    carry += mpn_add_1(limbs, limbs, size, addend);  // cannot both carry out
    if (carry != 0) limbs[size++] = carry;
  }
  // Divides by the odd d (inverse: d's inverse modulo 2^64) when it divides
  // exactly; returns whether it did. Hensel's division, lowest limb first:
  // q_i clears limb i of what is left, and c carries the rest upwards. By
  // induction, Q d = N + c B^size with Q = sum q_i B^i < B^size and B = 2^64
  // (each q_i d = n_i - c_i + c_(i+1) B). So c = 0 means Q d = N; and if d
  // divides N, N/d is the one residue below B^size that d times is N modulo
  // B^size, so Q = N/d and c = 0. No division instruction; c <= d < B (the
  // high half of q d is at most d - 1, plus a borrow of 1).
  bool divide_if_exact(mp_limb_t d, mp_limb_t inverse) {
    mp_limb_t quotient[small_limbs];
    mp_limb_t carry = 0;
    for (mp_size_t i = 0; i < size; ++i) {
      const mp_limb_t borrow = limbs[i] < carry ? 1 : 0;
      const mp_limb_t q = (limbs[i] - carry) * inverse;
      quotient[i] = q;
      carry = static_cast<mp_limb_t>((Uint128{q} * d) >> 64) + borrow;
    }
    if (carry != 0) return false;
    std::copy(quotient, quotient + size, limbs);
    if (limbs[size - 1] == 0) --size;
    return true;
  }
  bool divide_by_pow5_if_exact(unsigned n) { return divide_if_exact(pow5_table[n], pow5_inverse_table[n]); }
  std::uint64_t trailing_zero_bits() const {
    std::uint64_t bits = 0;
    mp_size_t i = 0;
    while (limbs[i] == 0) ++i, bits += 64;
    return bits + static_cast<std::uint64_t>(std::countr_zero(limbs[i]));
  }
  void shift_right(std::uint64_t bits) {
    const auto whole = static_cast<mp_size_t>(bits / 64);
    std::copy(limbs + whole, limbs + size, limbs);
    size -= whole;
    if (const auto rest = static_cast<unsigned>(bits % 64); rest != 0) mpn_rshift(limbs, limbs, size, rest);
    if (limbs[size - 1] == 0) --size;
  }
  void store(mpz_ptr z, bool negative) const {
    mp_limb_t* out = mpz_limbs_write(z, size);
    std::copy(limbs, limbs + size, out);
    mpz_limbs_finish(z, negative ? -size : size);
  }
};

// Digits into a SmallNatural, 19 at a time: each run of at most 19 digits
// (a chunk, < 10^19 < 2^64) is one multiply-add of the limbs.
struct DigitAccumulator {
  SmallNatural& m;
  mp_limb_t chunk = 0;  // the digits since the last flush, fewer than 19
  unsigned in_chunk = 0;

  // run: digits only (the parser has checked them).
  void append(std::string_view run) {
    for (std::size_t i = 0; i < run.size();) {
      if (words_of_digits && in_chunk + 8 <= 19 && i + 8 <= run.size()) {
        chunk = chunk * 100000000u + eight_digit_value(load_eight(run.data() + i));
        in_chunk += 8;
        i += 8;
      } else {
        chunk = chunk * 10 + static_cast<mp_limb_t>(run[i] - '0');
        ++in_chunk;
        ++i;
      }
      if (in_chunk == 19) {
        m.multiply_add(ten_to_19, chunk);
        chunk = 0;
        in_chunk = 0;
      }
    }
  }
  void finish() {
    if (in_chunk != 0) m.multiply_add(pow5(in_chunk) << in_chunk, chunk);  // 10^in_chunk
  }
};

// The significant digits as an integer: `digits` with the '.' at `dot`
// (npos: none) left out.
void set_small_digits(SmallNatural& m, std::string_view digits, std::size_t dot) {
  DigitAccumulator accumulator{m};
  if (dot == std::string_view::npos) {
    accumulator.append(digits);
  } else {
    accumulator.append(digits.substr(0, dot));
    accumulator.append(digits.substr(dot + 1));
  }
  accumulator.finish();
}

// Cancels the factors 5 of m, at most `cap` of them; returns how many.
std::uint64_t remove_fives(SmallNatural& m, std::uint64_t cap) {
  std::uint64_t removed = 0;
  while (cap - removed >= max_pow5_in_limb && m.divide_by_pow5_if_exact(max_pow5_in_limb))
    removed += max_pow5_in_limb;
  // Fewer than 27 remain (or may be taken): take them by binary descent.
  for (unsigned step = 16; step > 0; step /= 2)
    if (cap - removed >= step && m.divide_by_pow5_if_exact(step)) removed += step;
  return removed;
}

// Asks for a second limb only when the value needs it: a one-limb
// denominator (that of every double) then fits the limb mpq_init gave it,
// without a reallocation per number.
void set_u128(mpz_ptr z, Uint128 value) {
  const auto low = static_cast<mp_limb_t>(value);
  const auto high = static_cast<mp_limb_t>(value >> 64);
  mp_limb_t* out = mpz_limbs_write(z, high != 0 ? 2 : 1);
  out[0] = low;
  if (high != 0) out[1] = high;
  mpz_limbs_finish(z, high != 0 ? 2 : (low != 0 ? 1 : 0));
}

// 2^twos 5^fives.
void set_power_2_5(mpz_ptr z, std::uint64_t twos, std::uint64_t fives) {
  if (fives <= max_pow5_in_limb && twos + 64 <= 128) {
    set_u128(z, Uint128{pow5(static_cast<unsigned>(fives))} << twos);
    return;
  }
  mpz_ui_pow_ui(z, 5, fives);
  mpz_mul_2exp(z, z, twos);
}

// Builds M x 10^scale in lowest terms when both parts are surely within the
// caps and small; returns false (out untouched) to leave it to the general path.
bool set_small_decimal(std::string_view significant, std::size_t dot, std::uint64_t digits, Int128 scale,
                       bool negative, const NumberTextLimits& limits, Rational& out) {
  if (digits > small_max_digits || scale > Int128{small_max_scale} || scale < -Int128{small_max_scale})
    return false;
  const std::uint64_t magnitude = static_cast<std::uint64_t>(scale < 0 ? -scale : scale);
  const std::uint64_t num_bits_at_most = bits_of_digits_at_most(digits + (scale > 0 ? magnitude : 0));
  const std::uint64_t den_bits_at_most = scale < 0 ? bits_of_digits_at_most(magnitude + 1) : 1;
  if (num_bits_at_most > limits.max_bits || den_bits_at_most > limits.max_bits) return false;
  mpz_ptr num = out.get_num_mpz_t();
  mpz_ptr den = out.get_den_mpz_t();
  SmallNatural m;
  set_small_digits(m, significant, dot);
  if (scale >= 0) {
    if (num_bits_at_most > small_limbs * 64) return false;
    for (std::uint64_t s = magnitude; s > 0;) {
      const unsigned step = s >= 19 ? 19u : static_cast<unsigned>(s);
      m.multiply_add(pow5(step) << step, 0);  // 10^step
      s -= step;
    }
    m.store(num, negative);
    mpz_set_ui(den, 1);
    return true;
  }
  const std::uint64_t k = magnitude;
  const std::uint64_t twos = std::min(m.trailing_zero_bits(), k);
  std::uint64_t fives = 0;
  if (twos > 0)
    m.shift_right(twos);
  else
    fives = remove_fives(m, k);
  m.store(num, negative);
  set_power_2_5(den, k - twos, k - fives);
  return true;
}

NumberTextResult parse_fraction_into(std::string_view text, std::size_t slash, const NumberTextLimits& limits,
                                     Rational& out) {
  std::string_view num = text.substr(0, slash);
  std::string_view den = text.substr(slash + 1);
  bool negative = false;
  if (!num.empty() && (num[0] == '+' || num[0] == '-')) {
    negative = num[0] == '-';
    num.remove_prefix(1);
  }
  auto all_digits = [](std::string_view digits) {
    if (digits.empty()) return false;
    for (char c : digits)
      if (!is_digit(c)) return false;
    return true;
  };
  if (!all_digits(num) || !all_digits(den)) return {NumberTextStatus::not_a_number};
  num.remove_prefix(std::min(num.find_first_not_of('0'), num.size()));
  den.remove_prefix(std::min(den.find_first_not_of('0'), den.size()));
  if (den.empty()) return {NumberTextStatus::not_a_number};  // q = 0
  if (!num.empty() && bits_of_digits_at_least(num.size()) > limits.max_bits)
    return NumberTextResult{NumberTextStatus::numerator_too_large, bits_of_digits_at_least(num.size())};
  if (bits_of_digits_at_least(den.size()) > limits.max_bits)
    return NumberTextResult{NumberTextStatus::denominator_too_large, bits_of_digits_at_least(den.size())};
  mpz_ptr p = out.get_num_mpz_t();
  mpz_ptr q = out.get_den_mpz_t();
  set_digits(p, num);
  set_digits(q, den);
  // The estimate from below may let a part through that is a few bits over.
  if (mpz_sizeinbase(p, 2) > limits.max_bits)
    return NumberTextResult{NumberTextStatus::numerator_too_large, mpz_sizeinbase(p, 2)};
  if (mpz_sizeinbase(q, 2) > limits.max_bits)
    return NumberTextResult{NumberTextStatus::denominator_too_large, mpz_sizeinbase(q, 2)};
  if (negative) mpz_neg(p, p);
  out.canonicalize();
  return {};
}

// ---- Exact text, fast: integers and decimals of a few hundred digits -------
// value = p / (2^a 5^b) is printed as the integer |p| 2^(n-a) 5^(n-b), n =
// max(a, b), with a point n digits from its end. The integer is built in
// limbs on the stack and its digits come from machine division when it is
// one or two limbs, else from mpn_get_str: no mpz temporaries, no
// intermediate strings. Other
// values (p/q, or more limbs than the stack takes) go to exact_text_general,
// whose text this matches byte for byte (test/rational_test.cpp).

constexpr std::size_t print_limbs = 40;  // 2560 bits, about 770 digits

// Writes part (below 10^19) as exactly 19 digits, zeros in front; returns
// the end.
char* nineteen_digits(char* at, std::uint64_t part) {
  for (int i = 18; i >= 0; --i) {
    at[i] = static_cast<char>('0' + part % 10);
    part /= 10;
  }
  return at + 19;
}

// The decimal digits of {limbs, size} (size 1 or 2, so below 2^128 < 10^39)
// into out, without leading zeros ("0" for zero); returns how many. A
// k-digit decimal coordinate scaled to an integer is one or two words (a
// 17-digit one is one, a sum of two is two), and machine division by 10^19
// writes those directly, where mpn_get_str goes through its general base
// conversion and a digit-value buffer.
std::size_t word_digits(char* out, const mp_limb_t* limbs, mp_size_t size) {
  static_assert(GMP_NUMB_BITS == 64 && sizeof(mp_limb_t) == sizeof(std::uint64_t));
  constexpr std::uint64_t ten_19 = 10000000000000000000u;
  Uint128 value = limbs[0];
  if (size == 2) value |= Uint128{limbs[1]} << 64;
  // value = top 10^38 + middle 10^19 + low, with top < 4 (2^128 < 3.5 10^38).
  const auto low = static_cast<std::uint64_t>(value % ten_19);
  const Uint128 rest = value / ten_19;
  const auto middle = static_cast<std::uint64_t>(rest % ten_19);
  const auto top = static_cast<std::uint64_t>(rest / ten_19);
  // The leading group without zeros in front, the others as 19 digits each.
  const std::uint64_t lead = top != 0 ? top : middle != 0 ? middle : low;
  char* at = std::to_chars(out, out + 20, lead).ptr;
  if (top != 0) at = nineteen_digits(at, middle);
  if (top != 0 || middle != 0) at = nineteen_digits(at, low);
  return static_cast<std::size_t>(at - out);
}

// Appends the decimal digits of {limbs, size} (size > 0, top limb nonzero;
// destroyed) with a point `places` digits from the end, zero-padded to at
// least one digit before the point; a few appends, no per-digit branches.
void append_digits(std::string& out, mp_limb_t* limbs, mp_size_t size, std::size_t places) {
  unsigned char raw[print_limbs * 20 + 1];
  char* digits = reinterpret_cast<char*>(raw);
  std::size_t count = 0;
  if (size <= 2) {
    count = word_digits(digits, limbs, size);
  } else {
    count = mpn_get_str(raw, 10, limbs, size);
    std::size_t skip = 0;
    while (skip + 1 < count && raw[skip] == 0) ++skip;
    count -= skip;
    digits = reinterpret_cast<char*>(raw + skip);
    for (std::size_t i = 0; i < count; ++i) digits[i] = static_cast<char>('0' + raw[skip + i]);
  }
  if (places == 0) {
    out.append(digits, count);
  } else if (count <= places) {  // 0.000ddd
    out += "0.";
    out.append(places - count, '0');
    out.append(digits, count);
  } else {
    out.append(digits, count - places);
    out += '.';
    out.append(digits + count - places, places);
  }
}

// The b of den = 2^a 5^b, when the odd part fits a limb and is a power of 5.
std::optional<unsigned> fives_of(mpz_srcptr den, std::uint64_t twos) {
  if (mpz_sizeinbase(den, 2) - twos > 64) return std::nullopt;
  mp_limb_t rest = mpz_getlimbn(den, static_cast<mp_size_t>(twos / 64)) >> (twos % 64);
  if (twos % 64 != 0 && twos / 64 + 1 < mpz_size(den))
    rest |= mpz_getlimbn(den, static_cast<mp_size_t>(twos / 64) + 1) << (64 - twos % 64);
  for (unsigned b = 0; b <= max_pow5_in_limb; ++b)
    if (pow5(b) == rest) return b;
  return std::nullopt;
}

// num / (2^twos 5^fives) printed as above; false when it does not fit the stack.
bool append_decimal_fast(std::string& out, mpz_srcptr num, std::uint64_t twos, std::uint64_t fives) {
  if (mpz_sgn(num) == 0) {
    out += '0';
    return true;
  }
  const std::uint64_t places = std::max(twos, fives);
  const std::uint64_t extra_twos = places - twos;
  const std::uint64_t extra_fives = places - fives;
  // Bits of |p| 2^extra_twos 5^extra_fives, from above (log2(5) < 2.33).
  const std::uint64_t bits = mpz_sizeinbase(num, 2) + extra_twos + extra_fives * 233 / 100 + 1;
  if (bits > (print_limbs - 1) * 64 || places >= print_limbs * 20) return false;
  mp_limb_t limbs[print_limbs];
  auto size = static_cast<mp_size_t>(mpz_size(num));
  std::copy(mpz_limbs_read(num), mpz_limbs_read(num) + size, limbs);
  for (std::uint64_t left = extra_fives; left > 0;) {
    const auto step = static_cast<unsigned>(std::min<std::uint64_t>(left, max_pow5_in_limb));
    if (mp_limb_t carry = mpn_mul_1(limbs, limbs, size, pow5(step)); carry != 0) limbs[size++] = carry;
    left -= step;
  }
  if (extra_twos > 0) {
    const auto whole = static_cast<mp_size_t>(extra_twos / 64);
    std::copy_backward(limbs, limbs + size, limbs + size + whole);
    std::fill(limbs, limbs + whole, mp_limb_t{0});
    size += whole;
    if (const auto rest = static_cast<unsigned>(extra_twos % 64); rest != 0)
      if (mp_limb_t carry = mpn_lshift(limbs, limbs, size, rest); carry != 0) limbs[size++] = carry;
  }
  if (mpz_sgn(num) < 0) out += '-';
  append_digits(out, limbs, size, places);
  return true;
}

bool append_exact_text_fast(std::string& out, const Rational& value) {
  mpz_srcptr num = value.get_num_mpz_t();
  mpz_srcptr den = value.get_den_mpz_t();
  if (mpz_sgn(num) == 0) {
    out += '0';
    return true;
  }
  const std::uint64_t twos = mpz_scan1(den, 0);
  const std::optional<unsigned> fives = fives_of(den, twos);
  return fives && append_decimal_fast(out, num, twos, *fives);
}

}  // namespace

std::string exact_text_general(const Rational& value) {
  const mpz_class& den = value.get_den();
  // Strip factors 2 and 5 from the denominator; a finite decimal exists iff nothing else remains.
  mpz_class rest = den;
  unsigned long twos = mpz_remove(rest.get_mpz_t(), rest.get_mpz_t(), mpz_class(2).get_mpz_t());
  unsigned long fives = mpz_remove(rest.get_mpz_t(), rest.get_mpz_t(), mpz_class(5).get_mpz_t());
  if (rest != 1) return value.get_str();
  unsigned long places = twos > fives ? twos : fives;
  if (places == 0) return value.get_num().get_str();
  // value * 10^places is an integer: num * (10^places / den).
  mpz_class scale;
  mpz_ui_pow_ui(scale.get_mpz_t(), 10, places);
  mpz_class scaled = value.get_num() * (scale / den);
  bool negative = scaled < 0;
  if (negative) scaled = -scaled;
  std::string digits = scaled.get_str();
  if (digits.size() <= places) digits.insert(0, places + 1 - digits.size(), '0');
  digits.insert(digits.size() - places, 1, '.');
  return negative ? "-" + digits : digits;
}

void append_exact_text(std::string& out, const Rational& value) {
  if (!append_exact_text_fast(out, value)) out += exact_text_general(value);
}

void append_exact_text(std::string& out, mpz_srcptr numerator, mp_bitcnt_t exponent) {
  if (append_decimal_fast(out, numerator, exponent, 0)) return;
  Rational value;
  mpz_set(value.get_num_mpz_t(), numerator);
  mpz_mul_2exp(value.get_den_mpz_t(), value.get_den_mpz_t(), exponent);
  out += exact_text_general(value);
}

NumberTextResult parse_rational_into(std::string_view text, const NumberTextLimits& requested,
                                     Rational& out) {
  const NumberTextLimits limits{requested.max_exponent, std::min(requested.max_bits, gmp_max_bits)};
  if (text.empty()) return {NumberTextStatus::not_a_number};
  if (auto slash = text.find('/'); slash != std::string_view::npos)
    return parse_fraction_into(text, slash, limits, out);

  std::size_t i = 0;
  bool negative = false;
  if (text[i] == '+' || text[i] == '-') {
    negative = text[i] == '-';
    ++i;
  }
  const std::size_t mantissa_start = i;
  i = digit_run_end(text, i);
  bool has_digits = i > mantissa_start;
  std::size_t frac_len = 0;
  std::size_t dot = std::string_view::npos;  // in the mantissa
  if (i < text.size() && text[i] == '.') {
    dot = i - mantissa_start;
    ++i;
    const std::size_t frac_start = i;
    i = digit_run_end(text, i);
    frac_len = i - frac_start;
    has_digits = has_digits || frac_len > 0;
  }
  const std::size_t mantissa_end = i;
  if (!has_digits) return {NumberTextStatus::not_a_number};
  // The exponent is accumulated saturating at max_exponent + 1, so that no
  // digit string (and no max_exponent up to LONG_MAX) can overflow it.
  const long max_exponent = limits.max_exponent < 0 ? 0 : limits.max_exponent;
  long exponent = 0;
  bool exponent_too_large = false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    bool exp_negative = false;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
      exp_negative = text[i] == '-';
      ++i;
    }
    const std::size_t exp_start = i;
    while (i < text.size() && is_digit(text[i])) {
      long digit = text[i] - '0';
      if (exponent > max_exponent / 10 || exponent * 10 > max_exponent - digit)
        exponent_too_large = true;
      else
        exponent = exponent * 10 + digit;
      ++i;
    }
    if (i == exp_start) return {NumberTextStatus::not_a_number};
    if (exp_negative) exponent = -exponent;
  }
  if (i != text.size()) return {NumberTextStatus::not_a_number};
  if (exponent_too_large) return {NumberTextStatus::exponent_too_large};

  // The significant digits [first, last] (a '.' may sit among them); the
  // zeros after the last one only scale the value.
  std::string_view mantissa = text.substr(mantissa_start, mantissa_end - mantissa_start);
  const std::size_t first = first_significant(mantissa);
  if (first == std::string_view::npos) {
    out = 0;
    return {};
  }
  const std::size_t last = last_significant(mantissa);
  std::string_view significant = mantissa.substr(first, last + 1 - first);
  const bool dot_inside = dot != std::string_view::npos && dot > first && dot < last;
  const std::uint64_t digits = significant.size() - (dot_inside ? 1 : 0);
  // Zeros after the last significant digit, counted as digits of the mantissa.
  std::uint64_t trailing = mantissa.size() - 1 - last;
  if (dot != std::string_view::npos && dot > last) --trailing;
  // value = M * 10^scale, M the significant digits as an integer.
  const Int128 scale = Int128{exponent} - static_cast<Int128>(frac_len) + static_cast<Int128>(trailing);

  if (set_small_decimal(significant, dot_inside ? dot - first : std::string_view::npos, digits, scale,
                        negative, limits, out))
    return {};

  mpz_ptr num = out.get_num_mpz_t();
  mpz_ptr den = out.get_den_mpz_t();
  if (scale >= 0) {
    const std::uint64_t shift =
        scale > Int128{gmp_max_bits} ? gmp_max_bits : static_cast<std::uint64_t>(scale);
    const std::uint64_t at_least = times_log2_10_floor(digits - 1 + shift) + 1;
    if (at_least > limits.max_bits) return NumberTextResult{NumberTextStatus::numerator_too_large, at_least};
    set_digits(num, significant);
    if (shift > 0) {
      mpz_class power;
      mpz_ui_pow_ui(power.get_mpz_t(), 10, shift);
      mpz_mul(num, num, power.get_mpz_t());
    }
    if (mpz_sizeinbase(num, 2) > limits.max_bits)
      return NumberTextResult{NumberTextStatus::numerator_too_large, mpz_sizeinbase(num, 2)};
    mpz_set_ui(den, 1);
  } else {
    // The reduced denominator 2^(k-a) 5^(k-b) has at least k + 1 bits, and
    // as 10^k / gcd(M, 10^k) >= 10^k / M at least those of 10^(k-digits).
    const std::uint64_t k = -scale > Int128{gmp_max_bits} ? gmp_max_bits : static_cast<std::uint64_t>(-scale);
    const std::uint64_t den_early = std::max(k + 1, k > digits ? times_log2_10_floor(k - digits) + 1 : 0);
    if (den_early > limits.max_bits)
      return NumberTextResult{NumberTextStatus::denominator_too_large, den_early};
    set_digits(num, significant);  // no bigger than the text
    // M is not a multiple of 10: at most one of 2 and 5 divides it.
    const std::uint64_t a = std::min<std::uint64_t>(mpz_scan1(num, 0), k);
    std::uint64_t b = 0;
    if (a > 0) {
      mpz_tdiv_q_2exp(num, num, a);
    } else if (mpz_divisible_ui_p(num, 5)) {
      // A read-only 5 on the stack: an mpz_class would allocate per number.
      const mp_limb_t five_limb = 5;
      mpz_t five;
      b = mpz_remove(num, num, mpz_roinit_n(five, &five_limb, 1));
      if (b > k) {  // keep the fives the denominator cannot take
        mpz_class extra;
        mpz_ui_pow_ui(extra.get_mpz_t(), 5, b - k);
        mpz_mul(num, num, extra.get_mpz_t());
        b = k;
      }
    }
    const std::uint64_t den_at_least = (k - a) + times_log2_5_floor(k - b) + 1;
    if (den_at_least > limits.max_bits)
      return NumberTextResult{NumberTextStatus::denominator_too_large, den_at_least};
    if (mpz_sizeinbase(num, 2) > limits.max_bits)
      return NumberTextResult{NumberTextStatus::numerator_too_large, mpz_sizeinbase(num, 2)};
    mpz_ui_pow_ui(den, 5, k - b);
    mpz_mul_2exp(den, den, k - a);
    if (mpz_sizeinbase(den, 2) > limits.max_bits)
      return NumberTextResult{NumberTextStatus::denominator_too_large, mpz_sizeinbase(den, 2)};
  }
  if (negative) mpz_neg(num, num);
  return {};  // in lowest terms by construction
}

}  // namespace detail

std::optional<Rational> try_parse_rational(std::string_view text, long max_exponent) {
  Rational value;
  if (detail::parse_rational_into(text, {max_exponent, detail::gmp_max_bits}, value).status !=
      detail::NumberTextStatus::ok)
    return std::nullopt;
  return value;
}

Rational parse_rational(std::string_view text) {
  if (auto r = try_parse_rational(text)) return *r;
  std::string shown(text.substr(0, 64));
  if (text.size() > 64) shown += "...";
  throw Error(ErrorCategory::parse, "not an exact number: '" + shown + "'");
}

Rational rational_from_double(double value) {
  if (!std::isfinite(value))
    throw Error(ErrorCategory::invalid_argument, "cannot convert a non-finite double to a rational");
  return Rational(value);  // mpq_set_d is exact
}

Rational rational_from_float(float value) { return rational_from_double(static_cast<double>(value)); }

std::string to_string(const Rational& value) {
  std::string text;
  detail::append_exact_text(text, value);
  return text;
}

double to_double_nearest(const Rational& value) {
  double truncated = value.get_d();  // rounds toward zero; infinity beyond the range
  if (std::isinf(truncated) || is_double_exact(value)) return truncated;
  // A negative value that rounds to zero is -0, as IEEE rounding gives.
  if (truncated == 0.0) truncated = std::copysign(0.0, static_cast<double>(sgn(value)));
  double away = std::nextafter(truncated, sgn(value) > 0 ? std::numeric_limits<double>::infinity()
                                                         : -std::numeric_limits<double>::infinity());
  // The candidates are truncated and away; when away is infinite the
  // midpoint is DBL_MAX + ulp(DBL_MAX)/2 = 2^1024 - 2^970, and at the tie
  // IEEE rounds to infinity (DBL_MAX's significand is odd).
  Rational upper =
      std::isinf(away) ? Rational(truncated) * 2 - Rational(std::nextafter(truncated, 0.0)) : Rational(away);
  Rational midpoint = (Rational(truncated) + upper) / 2;
  int c = cmp(abs(value), abs(midpoint));
  if (c < 0) return truncated;
  if (c > 0) return away;
  // Tie: the one whose significand is even (last bit of the encoding zero,
  // which also holds for subnormals and for the overflow case above).
  return (std::bit_cast<std::uint64_t>(truncated) & 1u) == 0 ? truncated : away;
}

bool is_double_exact(const Rational& value) { return is_double_exact_fast(value); }

}  // namespace cvms
