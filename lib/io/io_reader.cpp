// SPDX-License-Identifier: MIT
// Bounded stream reading, line splitting and token parsing shared by the
// readers (see io_reader.hpp). Nothing here allocates more than the input
// actually holds: buffers grow with the data read, never with a declared count.
#include "io_reader.hpp"

#include <algorithm>
#include <cstring>
#include <ios>
#include <limits>

namespace cvms::io_detail {
namespace {

constexpr std::size_t chunk_size = std::size_t{1} << 16;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

bool contains_ci(std::string_view text, std::string_view needle) {
  if (needle.size() > text.size()) return false;
  for (std::size_t i = 0; i + needle.size() <= text.size(); ++i) {
    bool match = true;
    for (std::size_t j = 0; j < needle.size() && match; ++j) match = lower(text[i + j]) == needle[j];
    if (match) return true;
  }
  return false;
}

// True if the token has the shape of a decimal number with an exponent
// (so that a failed parse can only be due to the exponent cap).
bool is_decimal_with_exponent(std::string_view t) {
  std::size_t i = 0;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < t.size() && is_digit(t[i])) ++i, ++digits;
  if (i < t.size() && t[i] == '.') {
    ++i;
    while (i < t.size() && is_digit(t[i])) ++i, ++digits;
  }
  if (digits == 0 || i >= t.size() || (t[i] != 'e' && t[i] != 'E')) return false;
  ++i;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  std::size_t exp_digits = 0;
  while (i < t.size() && is_digit(t[i])) ++i, ++exp_digits;
  return exp_digits > 0 && i == t.size();
}

}  // namespace

std::string quote(std::string_view token) {
  constexpr std::size_t shown = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < shown; ++i) {
    auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f && c != '\'') {
      out += static_cast<char>(c);
    } else {
      constexpr const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (token.size() > shown) out += "...";
  out += '\'';
  return out;
}

std::size_t ByteSource::read(char* dst, std::size_t n) {
  if (at_end_ || n == 0) return 0;
  // Ask for at most one byte beyond the limit: enough to know it was exceeded.
  // (consumed_ <= max_bytes_ here, or the previous call would have thrown.)
  const std::uint64_t remaining = max_bytes_ - consumed_;
  const std::uint64_t allowed =
      remaining == std::numeric_limits<std::uint64_t>::max() ? remaining : remaining + 1;
  auto want = static_cast<std::streamsize>(std::min<std::uint64_t>(n, allowed));
  try {
    in_.read(dst, want);
  } catch (const std::ios_base::failure&) {
    // A stream with exceptions enabled throws at the end of input too.
    if (!in_.eof() || in_.bad())
      throw Error(ErrorCategory::io, source_ + ": read error after " + std::to_string(consumed_) + " bytes");
  }
  auto got = static_cast<std::size_t>(in_.gcount());
  if (in_.bad())
    throw Error(ErrorCategory::io, source_ + ": read error after " + std::to_string(consumed_) + " bytes");
  if (got < static_cast<std::size_t>(want)) at_end_ = true;
  consumed_ += got;
  if (consumed_ > max_bytes_)
    throw Error(ErrorCategory::limit,
                source_ + ": input is larger than the limit of " + std::to_string(max_bytes_) + " bytes");
  return got;
}

std::string ByteSource::read_all() {
  std::string data;
  for (;;) {
    std::size_t old = data.size();
    data.resize(old + chunk_size);
    std::size_t got = read(data.data() + old, chunk_size);
    data.resize(old + got);
    if (got == 0) return data;
  }
}

bool LineReader::next(std::string_view& line) {
  if (replay_) {
    replay_ = false;
    line = last_;
    return true;
  }
  for (;;) {
    const char* base = buffer_.data();
    const void* nl = end_ > scanned_ ? std::memchr(base + scanned_, '\n', end_ - scanned_) : nullptr;
    if (nl != nullptr) {
      auto pos = static_cast<std::size_t>(static_cast<const char*>(nl) - base);
      line = std::string_view(base + begin_, pos - begin_);
      begin_ = scanned_ = pos + 1;
      break;
    }
    scanned_ = end_;
    if (eof_) {
      if (begin_ == end_) return false;
      line = std::string_view(base + begin_, end_ - begin_);
      begin_ = scanned_ = end_;
      break;
    }
    // Keep the partial line, make room for a chunk, read more.
    if (begin_ > 0) {
      std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
      end_ -= begin_;
      scanned_ -= begin_;
      begin_ = 0;
    }
    if (buffer_.size() - end_ < chunk_size) buffer_.resize(std::max(buffer_.size() * 2, end_ + chunk_size));
    std::size_t got = bytes_ ? bytes_->read(buffer_.data() + end_, buffer_.size() - end_) : 0;
    if (got == 0) eof_ = true;
    end_ += got;
  }
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (line_number_ == 0 && line.substr(0, 3) == "\xEF\xBB\xBF")
    line.remove_prefix(3);  // UTF-8 byte order mark
  ++line_number_;
  last_ = line;
  return true;
}

void LineReader::fail(std::string_view message, ErrorCategory category) const {
  throw Error(category,
              std::string(source()) + ":" + std::to_string(line_number_) + ": " + std::string(message));
}

void Tokenizer::skip_space() {
  std::size_t i = 0;
  while (i < rest_.size() && is_space(rest_[i])) ++i;
  rest_.remove_prefix(i);
  if (comments_ && !rest_.empty() && rest_.front() == '#') rest_ = {};
}

std::string_view Tokenizer::next() {
  skip_space();
  std::size_t i = 0;
  while (i < rest_.size() && !is_space(rest_[i]) && !(comments_ && rest_[i] == '#')) ++i;
  std::string_view token = rest_.substr(0, i);
  rest_.remove_prefix(i);
  return token;
}

bool Tokenizer::at_end() {
  skip_space();
  return rest_.empty();
}

bool looks_non_finite(std::string_view token) {
  return contains_ci(token, "nan") || contains_ci(token, "inf");
}

std::string ValueName::str() const {
  std::string s = std::string(what) + " of " + element + " " + std::to_string(index);
  if (outer != nullptr) s += std::string(" of ") + outer + " " + std::to_string(outer_index);
  return s;
}

Rational parse_number(const LineReader& reader, std::string_view token, const ValueName& name) {
  if (!token.empty() && token.size() <= reader.limits().max_number_chars)
    if (auto value = try_parse_rational(token, max_exponent)) return *std::move(value);
  // Only failures pay for the message.
  const std::string what = name.str();
  if (token.empty()) reader.fail("missing " + what);
  if (token.size() > reader.limits().max_number_chars)
    reader.fail(std::string(what) + " has " + std::to_string(token.size()) +
                    " characters, more than the limit of " + std::to_string(reader.limits().max_number_chars),
                ErrorCategory::limit);
  if (looks_non_finite(token)) reader.fail(std::string(what) + " is not finite: " + quote(token));
  if (is_decimal_with_exponent(token))
    reader.fail(
        std::string(what) + " " + quote(token) + " has an exponent beyond +-" + std::to_string(max_exponent),
        ErrorCategory::limit);
  reader.fail(std::string(what) + " is not a number: " + quote(token));
}

std::optional<std::uint64_t> parse_unsigned(std::string_view token) {
  if (token.empty()) return std::nullopt;
  std::uint64_t value = 0;
  constexpr std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
  for (char c : token) {
    if (!is_digit(c)) return std::nullopt;
    auto d = static_cast<std::uint64_t>(c - '0');
    value = value > (max - d) / 10 ? max : value * 10 + d;
  }
  return value;
}

std::optional<std::int64_t> parse_signed(std::string_view token) {
  bool negative = false;
  if (!token.empty() && (token.front() == '-' || token.front() == '+')) {
    negative = token.front() == '-';
    token.remove_prefix(1);
  }
  auto magnitude = parse_unsigned(token);
  if (!magnitude) return std::nullopt;
  constexpr auto max = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
  std::int64_t value = static_cast<std::int64_t>(std::min(*magnitude, max));
  return negative ? -value : value;
}

void check_vertex_limit(const LineReader& reader, std::uint64_t vertices) {
  // Indices are 32-bit, whatever the configured limit says.
  std::uint64_t cap =
      std::min<std::uint64_t>(reader.limits().max_vertices, std::numeric_limits<std::uint32_t>::max());
  if (vertices > cap)
    reader.fail(std::to_string(vertices) + " vertices exceed the limit of " + std::to_string(cap),
                ErrorCategory::limit);
}

void check_face_limit(const LineReader& reader, std::uint64_t faces, std::uint64_t indices) {
  if (faces > reader.limits().max_faces)
    reader.fail(
        std::to_string(faces) + " faces exceed the limit of " + std::to_string(reader.limits().max_faces),
        ErrorCategory::limit);
  if (indices > std::numeric_limits<std::uint32_t>::max())
    reader.fail("more than 2^32-1 face indices in total", ErrorCategory::limit);
}

void check_soup_for_writing(const PolygonSoup& soup, std::size_t min_size) {
  if (soup.face_offsets.empty() || soup.face_offsets.front() != 0 ||
      soup.face_offsets.back() != soup.face_indices.size())
    throw Error(ErrorCategory::invalid_argument, "polygon soup has inconsistent face offsets");
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (soup.face_offsets[f + 1] < soup.face_offsets[f])
      throw Error(ErrorCategory::invalid_argument,
                  "polygon soup has decreasing face offsets at face " + std::to_string(f));
    auto face = soup.face(f);
    if (face.size() < min_size)
      throw Error(ErrorCategory::invalid_argument,
                  "face " + std::to_string(f) + " has " + std::to_string(face.size()) + " vertices");
    for (std::uint32_t i : face)
      if (i >= soup.points.size())
        throw Error(ErrorCategory::invalid_argument, "face " + std::to_string(f) + " has index " +
                                                         std::to_string(i) + " but there are " +
                                                         std::to_string(soup.points.size()) + " vertices");
  }
}

}  // namespace cvms::io_detail
