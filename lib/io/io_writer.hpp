// SPDX-License-Identifier: MIT
// Private helper for the writers: a buffered, locale-independent text and
// byte sink. Numbers are formatted with std::to_chars (never through the
// stream's locale), so the output is byte-identical across runs and machines.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <ios>
#include <ostream>
#include <string>
#include <string_view>

#include "cvms/error.hpp"
#include "cvms/io.hpp"
#include "cvms/rational.hpp"
#include "dyadic_points.hpp"
#include "rational_text.hpp"
#include "soup_view.hpp"

namespace cvms::io_detail {

class TextWriter {
 public:
  explicit TextWriter(std::ostream& out) : out_(out) { buffer_.reserve(flush_at + 256); }
  TextWriter(const TextWriter&) = delete;
  TextWriter& operator=(const TextWriter&) = delete;
  ~TextWriter() = default;  // call finish(); a destructor must not throw

  TextWriter& text(std::string_view s) {
    buffer_.append(s);
    if (buffer_.size() >= flush_at) flush();
    return *this;
  }
  TextWriter& byte(char c) {
    buffer_.push_back(c);
    if (buffer_.size() >= flush_at) flush();
    return *this;
  }
  TextWriter& integer(std::uint64_t value) {
    char digits[24];
    auto result = std::to_chars(digits, digits + sizeof digits, value);
    return text(std::string_view(digits, static_cast<std::size_t>(result.ptr - digits)));
  }
  TextWriter& u32_le(std::uint32_t value) {
    for (int i = 0; i < 4; ++i) byte(static_cast<char>((value >> (8 * i)) & 0xffu));
    return *this;
  }
  /// An exact coordinate, or the nearest double printed in the shortest form
  /// that reads back to the same double. \throw Error(invalid_argument) when the
  /// value is beyond the double range.
  TextWriter& coordinate(const Rational& value, Coordinates mode) {
    if (mode == Coordinates::exact) {
      detail::append_exact_text(buffer_, value);  // no string per coordinate
      if (buffer_.size() >= flush_at) flush();
      return *this;
    }
    double d = to_double_nearest(value);
    if (!std::isfinite(d))
      throw Error(ErrorCategory::invalid_argument,
                  "coordinate " + abbreviated(value) + " is beyond the range of double");
    char digits[32];
    auto result = std::to_chars(digits, digits + sizeof digits, d);
    return text(std::string_view(digits, static_cast<std::size_t>(result.ptr - digits)));
  }
  /// coordinate() of a packed value, without making a Rational of it
  /// unless it is to be rounded.
  TextWriter& coordinate(const detail::PackedDyadic& value, Coordinates mode) {
    if (mode != Coordinates::exact) {
      detail::unpack_dyadic(value, scratch_);
      return coordinate(scratch_, mode);
    }
    mpz_t view;
    detail::append_exact_text(buffer_, value.numerator(view), value.exponent);
    if (buffer_.size() >= flush_at) flush();
    return *this;
  }
  /// The point at position j of soup, its coordinates separated by spaces.
  TextWriter& point(const SoupView& soup, std::size_t j, Coordinates mode) {
    if (soup.packed != nullptr) {
      coordinate(soup.packed_coordinate(j, 0), mode).byte(' ').coordinate(soup.packed_coordinate(j, 1), mode);
      return byte(' ').coordinate(soup.packed_coordinate(j, 2), mode);
    }
    const Vec3& p = soup.point(j);
    return coordinate(p.x, mode).byte(' ').coordinate(p.y, mode).byte(' ').coordinate(p.z, mode);
  }
  /// Flushes what is buffered and checks the stream. \throw Error(io) on failure.
  void finish() {
    flush();
    try {
      out_.flush();
    } catch (const std::ios_base::failure&) {
      throw Error(ErrorCategory::io, "writing the output failed");
    }
    if (!out_) throw Error(ErrorCategory::io, "writing the output failed");
  }

 private:
  static constexpr std::size_t flush_at = std::size_t{1} << 16;
  Rational scratch_;  // a packed value to be rounded
  static std::string abbreviated(const Rational& value) {
    std::string s = value.get_str();
    return s.size() > 40 ? s.substr(0, 40) + "..." : s;
  }
  void flush() {
    try {
      out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    } catch (const std::ios_base::failure&) {
      throw Error(ErrorCategory::io, "writing the output failed");
    }
    buffer_.clear();
    if (!out_) throw Error(ErrorCategory::io, "writing the output failed");
  }
  std::ostream& out_;
  std::string buffer_;
};

}  // namespace cvms::io_detail
