// SPDX-License-Identifier: MIT
// Compact exact storage: rationals whose limbs live in shared blocks (see the header).
#include "limb_arena.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstring>
#include <functional>
#include <iterator>
#include <utility>

#include "power_of_two.hpp"

namespace cvms::detail {
namespace {

// Zero's (unread) limb and 1's: views of them take no arena space.
constexpr mp_limb_t zero_limb = 0;
constexpr mp_limb_t one_limb = 1;

// Blocks double from 4 KiB (first_block_limbs) up to 1 MiB: small results
// stay small, large ones take about ten blocks. Where large blocks go on
// huge pages (huge_page_blocks.hpp), the blocks after 1 MiB are 2 MiB, one
// huge page each.
constexpr std::size_t max_heap_block_limbs = std::size_t{1} << 17;
constexpr std::size_t huge_block_limbs = huge_page_bytes / sizeof(mp_limb_t);

std::size_t block_after(std::size_t limbs) noexcept {
  if (limbs >= max_heap_block_limbs)
    return huge_page_blocks_enabled() ? huge_block_limbs : max_heap_block_limbs;
  return limbs * 2;
}

// Every power of two below 2^64, for denominators: a view of one of these
// takes neither a heap block nor arena space.
constexpr auto powers_of_two = [] {
  std::array<mp_limb_t, GMP_NUMB_BITS> table{};
  for (std::size_t k = 0; k < table.size(); ++k) table[k] = mp_limb_t{1} << k;
  return table;
}();

// Whether den is a view of the table: a denominator given back
// (give_back_denominator) or stored since. std::less orders pointers into
// different objects too.
bool views_powers_of_two(mpz_srcptr den) noexcept {
  const std::less<const mp_limb_t*> before;
  return den->_mp_alloc == 0 && !before(den->_mp_d, powers_of_two.data()) &&
         before(den->_mp_d, powers_of_two.data() + powers_of_two.size());
}

// den = 2^exponent: a view of the table where den is one already, else
// written into den's own limb (GMP allocates one if den is a view of
// something else).
void set_power_of_two(mpz_ptr den, mp_bitcnt_t exponent) {
  assert(exponent < GMP_NUMB_BITS);
  if (views_powers_of_two(den)) {
    mpz_roinit_n(den, &powers_of_two[exponent], 1);
  } else {
    mpz_set_ui(den, powers_of_two[exponent]);
  }
}

bool is_one(mpz_srcptr z) noexcept { return mpz_size(z) == 1 && mpz_sgn(z) > 0 && mpz_limbs_read(z)[0] == 1; }

std::size_t limbs_needed(mpz_srcptr z) noexcept { return is_one(z) ? 0 : mpz_size(z); }

// out = a view of the n limbs at `limbs` with value's sign; out owns nothing.
void view(mpz_ptr out, const mp_limb_t* limbs, mpz_srcptr value) {
  const auto n = static_cast<mp_size_t>(mpz_size(value));
  mpz_roinit_n(out, n == 0 ? &zero_limb : limbs, mpz_sgn(value) < 0 ? -n : n);
}

#if defined(__GNU_MP_RELEASE) && __GNU_MP_RELEASE >= 60200
// GMP's version string is "major.minor[.patch]"; a function-local constant,
// computed once (thread-safe), so that no store parses it.
bool loaded_gmp_frees_lazily() noexcept {
  static const bool lazily = [] {
    int major = 0, minor = 0;
    const char* v = gmp_version;
    while (*v >= '0' && *v <= '9') major = major * 10 + (*v++ - '0');
    if (*v == '.') ++v;
    while (*v >= '0' && *v <= '9') minor = minor * 10 + (*v++ - '0');
    return major > 6 || (major == 6 && minor >= 2);
  }();
  return lazily;
}
#endif

}  // namespace

bool LimbArena::holds_limbs() noexcept {
#if defined(__GNU_MP_RELEASE) && __GNU_MP_RELEASE >= 60200
  return loaded_gmp_frees_lazily();
#else
  return false;
#endif
}

LimbArena::LimbArena(LimbArena&& other) noexcept
    : blocks_(std::move(other.blocks_)),
      free_(std::exchange(other.free_, nullptr)),
      free_limbs_(std::exchange(other.free_limbs_, 0)),
      next_block_limbs_(std::exchange(other.next_block_limbs_, first_block_limbs)),
      capacity_limbs_(std::exchange(other.capacity_limbs_, 0)) {
  other.blocks_.clear();
}

LimbArena& LimbArena::operator=(LimbArena&& other) noexcept {
  if (this != &other) {
    blocks_ = std::move(other.blocks_);
    other.blocks_.clear();
    free_ = std::exchange(other.free_, nullptr);
    free_limbs_ = std::exchange(other.free_limbs_, 0);
    next_block_limbs_ = std::exchange(other.next_block_limbs_, first_block_limbs);
    capacity_limbs_ = std::exchange(other.capacity_limbs_, 0);
  }
  return *this;
}

mp_limb_t* LimbArena::allocate(std::size_t limbs) {
  if (limbs > free_limbs_) {
    const std::size_t size = std::max(limbs, next_block_limbs_);
    blocks_.emplace_back(size);
    free_ = blocks_.back().data();
    free_limbs_ = size;
    capacity_limbs_ += size;
    next_block_limbs_ = block_after(next_block_limbs_);
  }
  mp_limb_t* result = free_;
  free_ += limbs;
  free_limbs_ -= limbs;
  return result;
}

const mp_limb_t* LimbArena::copy_limbs(const mp_limb_t* source, std::size_t n) {
  mp_limb_t* copy = allocate(n);
  std::copy_n(source, n, copy);
  return copy;
}

void LimbArena::store(Rational& out, const Rational& value) {
  store(out, mpq_numref(value.get_mpq_t()), mpq_denref(value.get_mpq_t()));
}

void LimbArena::store(Rational& out, mpz_srcptr numerator, mpz_srcptr denominator) {
  assert(mpz_sgn(denominator) > 0);
  mpq_ptr o = out.get_mpq_t();
  if (!holds_limbs()) {
    mpz_set(mpq_numref(o), numerator);
    mpz_set(mpq_denref(o), denominator);
    return;
  }
  const std::size_t num_limbs = limbs_needed(numerator);
  // A one-limb denominator (1, or a power of two below 2^64: almost all)
  // goes into the limb mpq_init gave out, or stays a view of the table in a
  // value whose limb was given back (set_power_of_two); a longer one would
  // reallocate that limb, so it comes here.
  const std::size_t den_limbs = mpz_size(denominator) > 1 ? mpz_size(denominator) : 0;
  // Everything that can throw comes before out is given up.
  mp_limb_t* limbs = num_limbs + den_limbs > 0 ? allocate(num_limbs + den_limbs) : nullptr;
  mpz_ptr den = mpq_denref(o);
  if (den_limbs == 0 && is_power_of_two(denominator)) {
    set_power_of_two(den, log2_of_power_of_two(denominator));
  } else if (den_limbs == 0) {
    mpz_set(den, denominator);
  } else {
    std::memcpy(limbs + num_limbs, mpz_limbs_read(denominator), den_limbs * sizeof(mp_limb_t));
    mpz_clear(den);
    view(den, limbs + num_limbs, denominator);
  }
  if (num_limbs > 0) std::memcpy(limbs, mpz_limbs_read(numerator), num_limbs * sizeof(mp_limb_t));
  mpz_clear(mpq_numref(o));
  view(mpq_numref(o), num_limbs > 0 ? limbs : &one_limb, numerator);
}

void LimbArena::store(mpz_class& out, mpz_srcptr value) {
  if (!holds_limbs()) {
    mpz_set(out.get_mpz_t(), value);
    return;
  }
  const std::size_t n = limbs_needed(value);
  mp_limb_t* limbs = n > 0 ? allocate(n) : nullptr;
  if (n > 0) std::memcpy(limbs, mpz_limbs_read(value), n * sizeof(mp_limb_t));
  mpz_clear(out.get_mpz_t());
  view(out.get_mpz_t(), n > 0 ? limbs : &one_limb, value);
}

void LimbArena::store_integer(Rational& out, std::uint64_t low, std::uint64_t high, bool negative) {
  const mp_size_t size = high != 0 ? 2 : (low != 0 ? 1 : 0);
  mpq_ptr o = out.get_mpq_t();
  mpz_ptr num = mpq_numref(o);
  if (!holds_limbs()) {
    if (mpz_cmp_ui(mpq_denref(o), 1) != 0) mpz_set_ui(mpq_denref(o), 1);
    mp_limb_t* limbs = mpz_limbs_write(num, size == 0 ? 1 : size);
    limbs[0] = low;
    if (size == 2) limbs[1] = high;
    mpz_limbs_finish(num, negative ? -size : size);
    return;
  }
  // As in store(): 0 and 1 are views of constants, the rest of new limbs.
  if (mpz_cmp_ui(mpq_denref(o), 1) != 0) set_power_of_two(mpq_denref(o), 0);
  const mp_limb_t* view_limbs = size == 0 ? &zero_limb : &one_limb;
  if (size == 2 || (size == 1 && low != 1)) {
    mp_limb_t* limbs = allocate(static_cast<std::size_t>(size));
    limbs[0] = low;
    if (size == 2) limbs[1] = high;
    view_limbs = limbs;
  }
  mpz_clear(num);
  mpz_roinit_n(num, view_limbs, negative ? -size : size);
}

void assign_dyadic(Rational& out, const std::uint64_t* magnitude, std::size_t size, bool negative,
                   mp_bitcnt_t exponent) {
  static_assert(sizeof(std::uint64_t) == sizeof(mp_limb_t));
  while (size > 0 && magnitude[size - 1] == 0) --size;
  mpz_ptr num = mpq_numref(out.get_mpq_t());
  mp_limb_t* limbs = mpz_limbs_write(num, size == 0 ? 1 : static_cast<mp_size_t>(size));
  if (size > 0) std::memcpy(limbs, magnitude, size * sizeof(mp_limb_t));
  mpz_limbs_finish(num, negative ? -static_cast<mp_size_t>(size) : static_cast<mp_size_t>(size));
  mpz_ptr den = mpq_denref(out.get_mpq_t());
  if (exponent < GMP_NUMB_BITS) {
    mpz_set_ui(den, mp_limb_t{1} << exponent);
  } else {
    mpz_set_ui(den, 0);
    mpz_setbit(den, exponent);
  }
}

void LimbArena::store_dyadic(Rational& out, const std::uint64_t* magnitude, std::size_t size, bool negative,
                             mp_bitcnt_t exponent) {
  if (!holds_limbs()) {
    assign_dyadic(out, magnitude, size, negative, exponent);
    return;
  }
  while (size > 0 && magnitude[size - 1] == 0) --size;
  const auto signed_size =
      static_cast<mp_size_t>(negative ? -static_cast<mp_size_t>(size) : static_cast<mp_size_t>(size));
  mpq_ptr o = out.get_mpq_t();
  mpz_ptr num = mpq_numref(o);
  mpz_ptr den = mpq_denref(o);
  const bool one_limb_denominator = exponent < GMP_NUMB_BITS;
  const bool is_one = size == 1 && magnitude[0] == 1;
  const std::size_t num_limbs = size == 0 || is_one ? 0 : size;
  const std::size_t den_limbs = one_limb_denominator ? 0 : exponent / GMP_NUMB_BITS + 1;
  // As in store(): everything that can throw comes before out is given up.
  mp_limb_t* limbs = num_limbs + den_limbs > 0 ? allocate(num_limbs + den_limbs) : nullptr;
  if (one_limb_denominator) {
    set_power_of_two(den, exponent);
  } else {
    mp_limb_t* d = limbs + num_limbs;
    std::fill(d, d + den_limbs, mp_limb_t{0});
    d[den_limbs - 1] = mp_limb_t{1} << (exponent % GMP_NUMB_BITS);
    mpz_clear(den);
    mpz_roinit_n(den, d, static_cast<mp_size_t>(den_limbs));
  }
  if (num_limbs > 0) std::memcpy(limbs, magnitude, num_limbs * sizeof(mp_limb_t));
  mpz_clear(num);
  mpz_roinit_n(num, size == 0 ? &zero_limb : (is_one ? &one_limb : limbs), signed_size);
}

void LimbArena::give_back_denominator(Rational& fresh) noexcept {
  mpz_ptr den = mpq_denref(fresh.get_mpq_t());
  if (!holds_limbs() || den->_mp_alloc == 0 || !is_one(den) || mpz_sgn(mpq_numref(fresh.get_mpq_t())) != 0)
    return;
  mpz_clear(den);
  mpz_roinit_n(den, &powers_of_two[0], 1);
}

void LimbArena::negate_stored(Rational& out) const {
  mpz_ptr num = mpq_numref(out.get_mpq_t());
  // A value that owns its limbs (never a view) is negated by GMP: made into
  // a view, its limbs would never be freed.
  if (!holds_limbs() || num->_mp_alloc != 0) {
    mpz_neg(num, num);
    return;
  }
  const auto size = static_cast<mp_size_t>(mpz_size(num));
  mpz_roinit_n(num, size == 0 ? &zero_limb : mpz_limbs_read(num), mpz_sgn(num) < 0 ? size : -size);
}

void LimbArena::store(Vec3& out, const Vec3& value) {
  for (int i = 0; i < 3; ++i) store(out[i], value[i]);
}

void LimbArena::absorb(LimbArena&& other) {
  blocks_.reserve(blocks_.size() + other.blocks_.size());
  std::move(other.blocks_.begin(), other.blocks_.end(), std::back_inserter(blocks_));
  capacity_limbs_ += other.capacity_limbs_;
  other = LimbArena();
}

}  // namespace cvms::detail
