// SPDX-License-Identifier: MIT
// The byte decoders the fuzz targets share (fuzz_targets.cpp,
// fuzz_halfspace_targets.cpp): every input decodes to something, so that
// libFuzzer's mutations always reach the library. test/fuzz/make_seeds.py
// writes seed inputs in these layouts: keep the two in step.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "cvms/convex_set.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/vec.hpp"

namespace cvms::fuzz {

/// Reads the input front to back; past the end every byte is 0.
class ByteStream {
 public:
  explicit ByteStream(std::span<const std::uint8_t> data) : data_(data) {}
  std::uint8_t next() { return pos_ < data_.size() ? data_[pos_++] : 0; }
  [[nodiscard]] bool empty() const { return pos_ >= data_.size(); }
  /// The bytes not read yet.
  [[nodiscard]] std::span<const std::uint8_t> rest() const {
    return pos_ < data_.size() ? data_.subspan(pos_) : std::span<const std::uint8_t>();
  }

 private:
  std::span<const std::uint8_t> data_;
  std::size_t pos_ = 0;
};

/// Throws FuzzFinding (fuzz_targets.hpp).
[[noreturn]] void finding(const std::string& what);

/// p/q in canonical form (gmpxx's two-argument constructor does not reduce).
Rational fraction(long p, long q);

/// Whether r is in lowest terms with a positive denominator.
bool is_canonical(const Rational& r);

/// Options with the algorithm set.
Options with(Algorithm algorithm);

/// 2^e exactly, for any e.
Rational power_of_two(long e);

/// A point of three bytes: on the grid {-2..2}^3, or of decode_coordinate values.
Vec3 decode_point(ByteStream& in, bool grid);

/// Up to `count` points (fewer when the input ends).
std::vector<Vec3> decode_cloud(ByteStream& in, std::size_t count, bool grid);

/// Scales every point by 2^e, e in [-1024, 1016], from one byte.
void scale_extreme(std::vector<Vec3>& points, ByteStream& in);

/// Moves some points by tiny steps (k * 2^-(20..79)).
void perturb_tiny(std::vector<Vec3>& points, ByteStream& in);

/// One small convex set of any dimension (see fuzz_bytes.cpp for the layout).
ConvexSet decode_set(ByteStream& in);

}  // namespace cvms::fuzz
