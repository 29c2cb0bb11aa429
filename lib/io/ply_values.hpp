// SPDX-License-Identifier: MIT
// The values of a PLY body, one property at a time, from either encoding:
// AsciiValues reads whitespace-separated tokens (across lines) and parses
// them exactly like the other text readers; BinaryValues reads fixed-size
// little- or big-endian values. Both present the same members so that the
// record walk (io_ply.cpp) is written once, and both name the place of an
// error: "<source>:<line>: ..." for ASCII, "<source>: byte <offset>: ..."
// for binary (the offset of the value's first byte).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "io_reader.hpp"
#include "ply_header.hpp"

namespace cvms::io_detail {

class AsciiValues {
 public:
  explicit AsciiValues(LineReader& reader) : reader_(reader), tokens_(reader) {}
  /// The exact value of a number; one of an integer type must be an
  /// integer in that type's range.
  void number(PlyType type, const ValueName& name, Rational& out);
  /// A value that is not kept: checked to be a number (NaN and infinity
  /// pass, as exporters write them in normals).
  void skip(PlyType type, const ValueName& name);
  /// A list's count, in the range of its type.
  std::uint64_t count(PlyType type, const ValueName& name);
  /// An integer (a face's vertex index), in the range of its type.
  std::int64_t integer(PlyType type, const ValueName& name);
  /// Skips a whole list (its count and items).
  void skip_list(const PlyProperty& p, const ValueName& name);
  /// Skips `records` records of `size` bytes each; never called for ASCII.
  void skip_records(std::uint64_t, std::uint64_t, const std::string&) {}
  /// Nothing but whitespace may follow the last element.
  void finish();
  [[noreturn]] void fail(const std::string& message, ErrorCategory category = ErrorCategory::parse) const {
    reader_.fail(message, category);
  }
  [[nodiscard]] static constexpr bool is_binary() noexcept { return false; }

 private:
  LineReader& reader_;
  TokenStream tokens_;
};

class BinaryValues {
 public:
  /// `bytes` is positioned at the body (its consumed() is the body's offset).
  BinaryValues(ByteSource& bytes, bool big_endian) : bytes_(bytes), big_endian_(big_endian) {}
  /// The exact value (a float or double is its dyadic rational); NaN and
  /// infinity are refused.
  void number(PlyType type, const ValueName& name, Rational& out);
  void skip(PlyType type, const ValueName& name) { take(ply_size(type), name); }
  std::uint64_t count(PlyType type, const ValueName& name);
  std::int64_t integer(PlyType type, const ValueName& name);
  void skip_list(const PlyProperty& p, const ValueName& name);
  /// Skips `records` records of `size` bytes at once (`what` names them in an error).
  void skip_records(std::uint64_t records, std::uint64_t size, const std::string& what);
  /// No byte may follow the last element.
  void finish();
  /// Error(category) with "<source>: byte <offset of the last value>: <message>".
  [[noreturn]] void fail(const std::string& message, ErrorCategory category = ErrorCategory::parse) const;
  [[nodiscard]] static constexpr bool is_binary() noexcept { return true; }

 private:
  // The n bytes of the next value (n <= 8), as an unsigned integer in the
  // body's byte order; fails naming `name` if the input ends first.
  std::uint64_t take(std::size_t n, const ValueName& name);
  // Skips n bytes; fails naming `what` if the input ends first.
  void skip_bytes(std::uint64_t n, const std::string& what);
  bool fill(std::size_t n);
  [[nodiscard]] std::uint64_t offset() const noexcept { return bytes_.consumed() - (end_ - begin_); }

  ByteSource& bytes_;
  bool big_endian_;
  std::vector<char> buffer_ = std::vector<char>(std::size_t{1} << 16);
  std::size_t begin_ = 0;
  std::size_t end_ = 0;
  std::uint64_t value_at_ = 0;  // offset of the value last taken
};

}  // namespace cvms::io_detail
