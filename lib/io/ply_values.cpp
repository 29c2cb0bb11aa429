// SPDX-License-Identifier: MIT
// PLY body values, ASCII and binary (see ply_values.hpp). A binary value is
// converted exactly: an integer is itself, a float or double is the dyadic
// rational it denotes (rational_from_double), so a file written with double
// coordinates reads back as exactly those doubles.
#include "ply_values.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

namespace cvms::io_detail {
namespace {

// The range of an integer type.
std::pair<std::int64_t, std::int64_t> integer_range(PlyType type) noexcept {
  switch (type) {
    case PlyType::int8:
      return {-128, 127};
    case PlyType::uint8:
      return {0, 255};
    case PlyType::int16:
      return {-32768, 32767};
    case PlyType::uint16:
      return {0, 65535};
    case PlyType::int32:
      return {std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()};
    default:
      return {0, std::numeric_limits<std::uint32_t>::max()};
  }
}

bool in_range(std::int64_t value, PlyType type) noexcept {
  const auto [low, high] = integer_range(type);
  return value >= low && value <= high;
}

std::string not_of_type(const std::string& what, std::string_view token, PlyType type) {
  const auto [low, high] = integer_range(type);
  return what + " " + quote(token) + " is not an integer from " + std::to_string(low) + " to " +
         std::to_string(high) + " (type '" + ply_name(type) + "')";
}

// The value of the low `size` bytes of `bits` as the integer type `type`.
std::int64_t as_integer(std::uint64_t bits, PlyType type) noexcept {
  switch (type) {
    case PlyType::int8:
      return static_cast<std::int8_t>(static_cast<std::uint8_t>(bits));
    case PlyType::int16:
      return static_cast<std::int16_t>(static_cast<std::uint16_t>(bits));
    case PlyType::int32:
      return static_cast<std::int32_t>(static_cast<std::uint32_t>(bits));
    default:
      return static_cast<std::int64_t>(bits);  // unsigned types: at most 2^32-1
  }
}

}  // namespace

// ---- ASCII ----

void AsciiValues::number(PlyType type, const ValueName& name, Rational& out) {
  const std::string_view token = tokens_.next();
  parse_number(reader_, token, name, out);
  if (!ply_is_integer(type)) return;
  const bool integral = out.get_den() == 1 && out.get_num().fits_slong_p();
  if (!integral || !in_range(out.get_num().get_si(), type)) fail(not_of_type(name.str(), token, type));
}

void AsciiValues::skip(PlyType, const ValueName& name) { check_number(reader_, tokens_.next(), name, true); }

std::uint64_t AsciiValues::count(PlyType type, const ValueName& name) {
  const std::string_view token = tokens_.next();
  if (token.empty()) fail("unexpected end of input: missing the count of " + name.str());
  const std::optional<std::uint64_t> value = parse_unsigned(token);
  if (!value) fail("the count of " + name.str() + " " + quote(token) + " is not a non-negative integer");
  if (*value > static_cast<std::uint64_t>(integer_range(type).second))
    fail(not_of_type("the count of " + name.str(), token, type));
  return *value;
}

std::int64_t AsciiValues::integer(PlyType type, const ValueName& name) {
  const std::string_view token = tokens_.next();
  if (token.empty()) fail("unexpected end of input: missing " + name.str());
  const std::optional<std::int64_t> value = parse_signed(token);
  if (!value) fail(name.str() + " " + quote(token) + " is not an integer");
  if (!in_range(*value, type)) fail(not_of_type(name.str(), token, type));
  return *value;
}

void AsciiValues::skip_list(const PlyProperty& p, const ValueName& name) {
  const std::uint64_t n = count(p.count_type, name);
  for (std::uint64_t k = 0; k < n; ++k) skip(p.type, name);
}

void AsciiValues::finish() {
  const std::string_view token = tokens_.next();
  if (!token.empty()) fail("unexpected " + quote(token) + " after the last element the header declares");
}

// ---- binary ----

bool BinaryValues::fill(std::size_t n) {
  if (begin_ > 0) {
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  while (end_ < n) {
    const std::size_t got = bytes_.read(buffer_.data() + end_, buffer_.size() - end_);
    if (got == 0) return false;
    end_ += got;
  }
  return true;
}

std::uint64_t BinaryValues::take(std::size_t n, const ValueName& name) {
  value_at_ = offset();
  if (end_ - begin_ < n && !fill(n)) fail("unexpected end of input in " + name.str());
  std::uint64_t bits = 0;
  const auto* p = reinterpret_cast<const unsigned char*>(buffer_.data() + begin_);
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char b = big_endian_ ? p[i] : p[n - 1 - i];
    bits = (bits << 8) | b;
  }
  begin_ += n;
  return bits;
}

void BinaryValues::skip_bytes(std::uint64_t n, const std::string& what) {
  while (n > 0) {
    value_at_ = offset();
    if (begin_ == end_ && !fill(1)) fail("unexpected end of input in " + what);
    const auto step = static_cast<std::size_t>(std::min<std::uint64_t>(n, end_ - begin_));
    begin_ += step;
    n -= step;
  }
}

void BinaryValues::number(PlyType type, const ValueName& name, Rational& out) {
  const std::uint64_t bits = take(ply_size(type), name);
  double value = 0;
  if (type == PlyType::float32)
    value = std::bit_cast<float>(static_cast<std::uint32_t>(bits));
  else if (type == PlyType::float64)
    value = std::bit_cast<double>(bits);
  else
    value = static_cast<double>(as_integer(bits, type));  // at most 32 bits: exact
  if (!std::isfinite(value)) fail(name.str() + " is not finite (" + (std::isnan(value) ? "nan" : "inf") + ")");
  out = rational_from_double(value);
}

std::uint64_t BinaryValues::count(PlyType type, const ValueName& name) {
  const std::int64_t value = as_integer(take(ply_size(type), name), type);
  if (value < 0) fail("the count of " + name.str() + " is negative (" + std::to_string(value) + ")");
  return static_cast<std::uint64_t>(value);
}

std::int64_t BinaryValues::integer(PlyType type, const ValueName& name) {
  return as_integer(take(ply_size(type), name), type);
}

void BinaryValues::skip_list(const PlyProperty& p, const ValueName& name) {
  const std::uint64_t n = count(p.count_type, name);
  // n < 2^32 and a size of at most 8: no overflow.
  skip_bytes(n * ply_size(p.type), name.str());
}

void BinaryValues::skip_records(std::uint64_t records, std::uint64_t size, const std::string& what) {
  const std::uint64_t total =
      size != 0 && records > std::numeric_limits<std::uint64_t>::max() / size ? std::numeric_limits<std::uint64_t>::max()
                                                                               : records * size;
  skip_bytes(total, what);
}

void BinaryValues::finish() {
  value_at_ = offset();
  if (begin_ == end_ && !fill(1)) return;
  fail("bytes after the last element the header declares");
}

void BinaryValues::fail(const std::string& message, ErrorCategory category) const {
  throw Error(category, std::string(bytes_.source()) + ": byte " + std::to_string(value_at_) + ": " + message);
}

}  // namespace cvms::io_detail
