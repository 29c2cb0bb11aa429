// SPDX-License-Identifier: MIT
#include "dyadic_points.hpp"

#include <limits>
#include <span>

#include "power_of_two.hpp"

namespace cvms::detail {

namespace {

constexpr std::uint64_t max_exponent = std::numeric_limits<std::uint32_t>::max();

void pack_limbs(const mp_limb_t* magnitude, std::size_t size, bool negative, std::uint32_t exponent,
                LimbArena& arena, PackedDyadic& out) {
  while (size > 0 && magnitude[size - 1] == 0) --size;
  // The word first: copying the limbs may throw, and then out is unchanged.
  if (size <= 1) {
    out.word = size == 0 ? 0 : magnitude[0];
  } else {
    out.word = reinterpret_cast<std::uintptr_t>(arena.copy_limbs(magnitude, size));
  }
  out.exponent = size == 0 ? 0 : exponent;
  out.size = static_cast<std::int32_t>(negative ? -static_cast<std::int64_t>(size)
                                                : static_cast<std::int64_t>(size));
}

}  // namespace

bool pack_dyadic(const Rational& value, LimbArena& arena, PackedDyadic& out) {
  mpz_srcptr denominator = value.get_den_mpz_t();
  if (!is_power_of_two(denominator)) return false;
  const mp_bitcnt_t exponent = log2_of_power_of_two(denominator);
  mpz_srcptr numerator = value.get_num_mpz_t();
  const std::size_t size = mpz_size(numerator);
  if (exponent > max_exponent || size > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    return false;
  pack_limbs(mpz_limbs_read(numerator), size, mpz_sgn(numerator) < 0, static_cast<std::uint32_t>(exponent),
             arena, out);
  return true;
}

void pack_dyadic(FixedDyadic<2> value, LimbArena& arena, PackedDyadic& out) {
  std::uint64_t* magnitude = value.numerator.magnitude.data();
  const mp_bitcnt_t exponent = reduce_dyadic(std::span<std::uint64_t>(magnitude, 2), value.exponent);
  pack_limbs(magnitude, 2, value.numerator.negative, static_cast<std::uint32_t>(exponent), arena, out);
}

void unpack_dyadic(const PackedDyadic& value, Rational& out) {
  mpz_t view;
  mpz_set(out.get_num_mpz_t(), value.numerator(view));
  mpz_set_ui(out.get_den_mpz_t(), 1);
  mpz_mul_2exp(out.get_den_mpz_t(), out.get_den_mpz_t(), value.exponent);
}

Vec3 DyadicPoints::point(std::size_t j) const {
  Vec3 p;
  for (int axis = 0; axis < 3; ++axis) unpack_dyadic(coordinate(j, axis), p[axis]);
  return p;
}

std::vector<Vec3> DyadicPoints::to_vectors() const {
  // Built in place: moving an mpq_class re-initialises the source, which allocates.
  std::vector<Vec3> points(size());
  for (std::size_t j = 0; j < points.size(); ++j)
    for (int axis = 0; axis < 3; ++axis) unpack_dyadic(coordinate(j, axis), points[j][axis]);
  return points;
}

}  // namespace cvms::detail
