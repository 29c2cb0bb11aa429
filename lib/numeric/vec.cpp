// SPDX-License-Identifier: MIT
// Mat3 products and determinants, and hashing of exact values.
#include "cvms/vec.hpp"

#include <cstdint>

namespace cvms {

Mat3 Mat3::identity() {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = (i == j) ? 1 : 0;
  return r;
}

Mat3 operator*(const Mat3& a, const Mat3& b) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
  return r;
}

Rational Mat3::determinant() const {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

namespace {
// The splitmix64 finaliser: every input bit affects every output bit, so
// small integers (the common coordinates) do not collide the way a plain
// shift-and-xor combination makes them.
std::uint64_t avalanche(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return x;
}
std::size_t mix(std::size_t seed, std::size_t value) {
  return static_cast<std::size_t>(avalanche(seed * 0x9e3779b97f4a7c15ULL + avalanche(value)));
}
std::size_t hash_mpz(mpz_srcptr z) {
  // Hash the limbs: canonical representation, so equal integers hash equal.
  std::size_t h = static_cast<std::size_t>(z->_mp_size);
  int n = z->_mp_size < 0 ? -z->_mp_size : z->_mp_size;
  for (int i = 0; i < n; ++i) h = mix(h, static_cast<std::size_t>(z->_mp_d[i]));
  return h;
}
}  // namespace

std::size_t hash_value(const Rational& value) noexcept {
  return mix(hash_mpz(value.get_num_mpz_t()), hash_mpz(value.get_den_mpz_t()));
}
std::size_t hash_value(const Vec2& v) noexcept { return mix(hash_value(v.x), hash_value(v.y)); }
std::size_t hash_value(const Vec3& v) noexcept {
  return mix(mix(hash_value(v.x), hash_value(v.y)), hash_value(v.z));
}

}  // namespace cvms
