// SPDX-License-Identifier: MIT
// Bounded stream reading, line splitting and token parsing shared by the
// readers (see io_reader.hpp). Nothing here allocates more than the input
// actually holds: buffers grow with the data read, never with a declared count.
#include "io_reader.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <ios>
#include <limits>

#include "rational_text.hpp"

namespace cvms::io_detail {
namespace {

constexpr std::size_t chunk_size = std::size_t{1} << 16;

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

bool starts_with_ci(std::string_view text, std::string_view lower_prefix) {
  return text.size() >= lower_prefix.size() && contains_ci(text.substr(0, lower_prefix.size()), lower_prefix);
}

// Whether the '#' at text[at] continues an MSVC non-finite spelling
// ("1.#INF", "-1.#IND00", "1.#QNAN") instead of starting a comment: the
// token so far is [+-]digits. and one of the MSVC words follows.
bool is_msvc_non_finite_hash(std::string_view text, std::size_t at) {
  std::string_view before = text.substr(0, at);
  if (!before.empty() && (before.front() == '+' || before.front() == '-')) before.remove_prefix(1);
  if (before.size() < 2 || before.back() != '.') return false;
  for (char c : before.substr(0, before.size() - 1))
    if (!is_digit(c)) return false;
  std::string_view after = text.substr(at + 1);
  for (std::string_view word : {"inf", "ind", "qnan", "snan", "nan"})
    if (starts_with_ci(after, word)) return true;
  return false;
}

std::uint64_t saturating_product(std::uint64_t a, std::uint64_t b) {
  return b != 0 && a > std::numeric_limits<std::uint64_t>::max() / b
             ? std::numeric_limits<std::uint64_t>::max()
             : a * b;
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

std::optional<std::uint64_t> ByteSource::bytes_left(std::istream& in) {
  const std::streampos failed{std::streamoff(-1)};
  std::streambuf* buffer = in.rdbuf();
  if (buffer == nullptr || !in.good()) return std::nullopt;
  const std::streampos here = buffer->pubseekoff(0, std::ios::cur, std::ios::in);
  if (here == failed) return std::nullopt;  // a pipe or a terminal
  // A device that seeks nowhere (/dev/zero) reports 0, from which the
  // stream subtracts what it has buffered (a peeked byte): no size to tell.
  if (static_cast<std::streamoff>(here) < 0) return std::nullopt;
  const std::streampos end = buffer->pubseekoff(0, std::ios::end, std::ios::in);
  if (buffer->pubseekpos(here, std::ios::in) != here) {
    in.setstate(std::ios::badbit);  // reading on from elsewhere would be wrong
    return std::nullopt;
  }
  if (end == failed || end < here) return std::nullopt;
  return static_cast<std::uint64_t>(end - here);
}

std::size_t LineReader::reserve_for(std::uint64_t declared, std::uint64_t min_bytes) const noexcept {
  const std::optional<std::uint64_t> size =
      bytes_ ? bytes_->size_at_start() : std::optional<std::uint64_t>(buffer_.size());
  if (!size) return safe_reserve(declared);
  const std::uint64_t fits = std::min(*size, limits_.max_bytes) / min_bytes + 1;
  return static_cast<std::size_t>(std::min(declared, fits));
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
      line_end_ = buffer_offset_ + begin_;
      break;
    }
    scanned_ = end_;
    if (eof_) {
      if (begin_ == end_) return false;
      line = std::string_view(base + begin_, end_ - begin_);
      begin_ = scanned_ = end_;
      line_end_ = buffer_offset_ + end_;
      break;
    }
    // Keep the partial line, make room for a chunk, read more.
    if (begin_ > 0) {
      std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
      buffer_offset_ += begin_;
      end_ -= begin_;
      scanned_ -= begin_;
      begin_ = 0;
    }
    if (end_ > limits_.max_line_bytes) fail_long_line();
    if (buffer_.size() - end_ < chunk_size) {
      // Doubling, but never beyond the longest line allowed plus a chunk.
      const std::uint64_t most = std::min(limits_.max_line_bytes, limits_.max_bytes) + chunk_size + 1;
      buffer_.resize(static_cast<std::size_t>(
          std::max<std::uint64_t>(std::min<std::uint64_t>(buffer_.size() * 2, most), end_ + chunk_size)));
    }
    std::size_t got = bytes_ ? bytes_->read(buffer_.data() + end_, buffer_.size() - end_) : 0;
    if (got == 0) eof_ = true;
    if (const void* nul = std::memchr(buffer_.data() + end_, '\0', got); nul != nullptr)
      fail_binary(static_cast<std::size_t>(static_cast<const char*>(nul) - buffer_.data()));
    end_ += got;
  }
  if (line.size() > limits_.max_line_bytes) fail_long_line();
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (line_number_ == 0 && line.substr(0, 3) == "\xEF\xBB\xBF")
    line.remove_prefix(3);  // UTF-8 byte order mark
  ++line_number_;
  last_ = line;
  carriage_return_inside_ = line.find('\r') != std::string_view::npos;
  return true;
}

void LineReader::fail_long_line() const {
  throw Error(ErrorCategory::limit, std::string(source()) + ":" + std::to_string(line_number_ + 1) +
                                        ": line longer than the limit of " +
                                        std::to_string(limits_.max_line_bytes) +
                                        " bytes (ReadLimits::max_line_bytes)");
}

void LineReader::fail_binary(std::size_t at) const {
  const auto begin = buffer_.begin() + static_cast<std::ptrdiff_t>(begin_);
  const auto line = line_number_ + 1 +
                    static_cast<std::uint64_t>(std::count(begin, buffer_.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
  throw Error(ErrorCategory::parse, std::string(source()) + ":" + std::to_string(line) + ": a NUL byte at byte " +
                                        std::to_string(buffer_offset_ + at) +
                                        ": binary data where text is expected");
}

void LineReader::fail(std::string_view message, ErrorCategory category) const {
  // Before the first line (an empty input) there is no line to name.
  std::string text = std::string(source()) + (line_number_ == 0 ? "" : ":" + std::to_string(line_number_)) + ": " +
                     std::string(message);
  // A '\r' inside a line (line ends are stripped of theirs) means the file
  // ends its lines with '\r' alone (classic Mac OS), so the whole file is one
  // line and the error above seems unrelated: say why.
  if (carriage_return_inside_)
    text += " (the line holds a carriage return: lines must end in '\\n' or \"\\r\\n\", not '\\r' alone)";
  throw Error(category, text);
}

bool LineReader::add_number_bits(std::uint64_t bits) noexcept {
  number_bits_ = number_bits_ > std::numeric_limits<std::uint64_t>::max() - bits
                     ? std::numeric_limits<std::uint64_t>::max()
                     : number_bits_ + bits;
  return number_bits_ <= number_bits_allowed();
}

std::uint64_t LineReader::number_bits_allowed() const noexcept {
  return std::max(number_bits_allowance, saturating_product(limits_.max_number_bits_per_byte, line_end_));
}

namespace {

// What ends a token, by character: one table lookup per character instead
// of a chain of comparisons (the token scan was about 8 % of reading an
// exact OFF file).
constexpr unsigned char space_class = 1, hash_class = 2;
constexpr std::array<unsigned char, 256> character_classes = [] {
  std::array<unsigned char, 256> table{};
  for (const char c : {' ', '\t', '\r', '\v', '\f'}) table[static_cast<unsigned char>(c)] = space_class;
  table[static_cast<unsigned char>('#')] = hash_class;
  return table;
}();

// The word scan below finds every byte that may end a token only because
// each of them is below 0x21 or is '#'.
static_assert([] {
  for (int c = 0; c < 256; ++c)
    if (character_classes[static_cast<std::size_t>(c)] != 0 && c >= 0x21 && c != '#') return false;
  return true;
}());

// The first of the eight bytes at p (in memory order, on a little-endian
// machine: the first byte is the word's low one) that may end a token: below
// 0x21 (every space is) or '#'; 8 if none. Each test is exact for its lowest
// flagged byte (a borrow only runs upwards), which is all that is read.
constexpr bool words_of_bytes = std::endian::native == std::endian::little;

unsigned first_stop_candidate(const char* p) {
  constexpr std::uint64_t ones = 0x0101010101010101u, highs = 0x8080808080808080u;
  std::uint64_t w;
  std::memcpy(&w, p, sizeof w);
  const std::uint64_t below_0x21 = (w - ones * 0x21) & ~w & highs;
  const std::uint64_t hashes = w ^ (ones * static_cast<unsigned char>('#'));
  const std::uint64_t is_hash = (hashes - ones) & ~hashes & highs;
  const std::uint64_t flagged = below_0x21 | is_hash;
  return flagged == 0 ? 8 : static_cast<unsigned>(std::countr_zero(flagged)) / 8;
}

// The length of the run of characters of text from `from` on that are in
// none of the classes in mask: eight bytes at a time to the first byte that
// may stop it, which the table then decides (a control byte that is no space
// is part of the token, for the number parser to refuse).
std::size_t run_outside(std::string_view text, std::size_t from, unsigned char mask) {
  std::size_t i = from;
  while (i < text.size()) {
    if (words_of_bytes && i + 8 <= text.size()) {
      const unsigned skip = first_stop_candidate(text.data() + i);
      i += skip;
      if (skip == 8) continue;
    }
    if ((character_classes[static_cast<unsigned char>(text[i])] & mask) != 0) break;
    ++i;
  }
  return i;
}

}  // namespace

void Tokenizer::skip_space() {
  std::size_t i = 0;
  while (i < rest_.size() && character_classes[static_cast<unsigned char>(rest_[i])] == space_class) ++i;
  rest_.remove_prefix(i);
  if (comments_ && !rest_.empty() && rest_.front() == '#') rest_ = {};
}

std::string_view Tokenizer::next() {
  skip_space();
  const unsigned char stop = comments_ ? space_class | hash_class : space_class;
  std::size_t i = run_outside(rest_, 0, stop);
  // A '#' inside "1.#INF" and its kin is part of the token, not a comment.
  while (i < rest_.size() && rest_[i] == '#' && is_msvc_non_finite_hash(rest_, i)) i = run_outside(rest_, i + 1, stop);
  std::string_view token = rest_.substr(0, i);
  rest_.remove_prefix(i);
  return token;
}

bool Tokenizer::next_short_unsigned(std::string_view& token, std::uint64_t& value) {
  skip_space();
  std::uint64_t v = 0;
  std::size_t i = 0;
  while (i < rest_.size() && i < 19 && is_digit(rest_[i]))
    v = v * 10 + static_cast<std::uint64_t>(rest_[i++] - '0');
  // Anything but a space after the digits ('#', a sign, a 20th digit, a
  // letter) is the general route's to read or refuse.
  if (i == 0 || (i < rest_.size() && character_classes[static_cast<unsigned char>(rest_[i])] != space_class))
    return false;
  token = rest_.substr(0, i);
  rest_.remove_prefix(i);
  value = v;
  return true;
}

bool Tokenizer::at_end() {
  skip_space();
  return rest_.empty();
}

bool looks_non_finite(std::string_view token) {
  return contains_ci(token, "nan") || contains_ci(token, "inf") || contains_ci(token, "#ind");
}

std::string ValueName::str() const {
  std::string s = std::string(what) + " of " + element + " " + std::to_string(index);
  if (outer != nullptr) s += std::string(" of ") + outer + " " + std::to_string(outer_index);
  return s;
}

namespace {

// mpz_sizeinbase(z, 2) (1 for zero) from the top limb, inline: every
// coordinate read asks for two, and GMP's is a call that handles any base.
std::uint64_t bit_length(mpz_srcptr z) noexcept {
  const std::size_t limbs = mpz_size(z);
  if (limbs == 0) return 1;
  return 64 * (limbs - 1) +
         static_cast<std::uint64_t>(std::bit_width(mpz_getlimbn(z, static_cast<mp_size_t>(limbs) - 1)));
}

static_assert(GMP_NUMB_BITS == 64, "bit_length reads 64-bit limbs");

}  // namespace

void parse_number(LineReader& reader, std::string_view token, const ValueName& name, Rational& out) {
  const ReadLimits& limits = reader.limits();
  detail::NumberTextResult result{detail::NumberTextStatus::not_a_number};
  if (!token.empty() && token.size() <= limits.max_number_chars) {
    result = detail::parse_rational_into(token, {max_exponent, limits.max_number_bits}, out);
    if (result.status == detail::NumberTextStatus::ok) {
      const std::uint64_t bits = bit_length(out.get_num_mpz_t()) + bit_length(out.get_den_mpz_t());
      if (reader.add_number_bits(bits)) return;
      reader.fail(name.str() + " " + quote(token) + " brings the numbers read to " +
                      std::to_string(reader.number_bits()) + " bits, beyond the " +
                      std::to_string(reader.number_bits_allowed()) + " allowed for the first " +
                      std::to_string(reader.bytes_through_line()) + " bytes of input (" +
                      std::to_string(limits.max_number_bits_per_byte) +
                      " bits per byte, ReadLimits::max_number_bits_per_byte)",
                  ErrorCategory::limit);
    }
  }
  // Only failures pay for the message.
  const std::string what = name.str();
  if (token.empty()) reader.fail("missing " + what);
  if (token.size() > limits.max_number_chars)
    reader.fail(what + " has " + std::to_string(token.size()) + " characters, more than the limit of " +
                    std::to_string(limits.max_number_chars) + " (ReadLimits::max_number_chars)",
                ErrorCategory::limit);
  if (looks_non_finite(token)) reader.fail(what + " is not finite: " + quote(token));
  switch (result.status) {
    case detail::NumberTextStatus::exponent_too_large:
      reader.fail(what + " " + quote(token) + " has an exponent beyond +-" + std::to_string(max_exponent),
                  ErrorCategory::limit);
    case detail::NumberTextStatus::numerator_too_large:
    case detail::NumberTextStatus::denominator_too_large: {
      const bool numerator = result.status == detail::NumberTextStatus::numerator_too_large;
      reader.fail(what + " " + quote(token) + " needs " + (numerator ? "a numerator" : "a denominator") +
                      " of at least " + std::to_string(result.bits) + " bits, beyond the limit of " +
                      std::to_string(limits.max_number_bits) + " (ReadLimits::max_number_bits)",
                  ErrorCategory::limit);
    }
    default:
      break;
  }
  reader.fail(what + " is not a number: " + quote(token));
}

const Rational& check_number(LineReader& reader, std::string_view token, const ValueName& name,
                             bool allow_non_finite) {
  if (allow_non_finite && looks_non_finite(token) && token.size() <= reader.limits().max_number_chars) {
    reader.scratch() = 0;
    return reader.scratch();
  }
  parse_number(reader, token, name, reader.scratch());
  return reader.scratch();
}

// A block is full at its capacity: a vector of rationals is never let grow
// by itself, since growing moves (allocates for) every element. With a
// declared count, the first block starts with room for a few points and
// grows towards the count as points arrive (widen_first_block), so that
// what it reserves stays within a fixed multiple of what was read: input
// refused at its first numbers never pays for its header's count.
Vec3& PointBuffer::append() {
  constexpr std::size_t trial_points = 64;
  if (blocks_.empty()) {
    add_block(declared_ ? std::max<std::size_t>(std::min(*declared_, trial_points), 1) : block_size);
  } else if (blocks_.back().size() == blocks_.back().capacity()) {
    if (declared_ && blocks_.size() == 1 && *declared_ > size_)
      widen_first_block();
    else
      add_block(block_size);
  }
  ++size_;
  return blocks_.back().emplace_back();
}

void PointBuffer::add_block(std::size_t capacity) {
  blocks_.emplace_back();
  blocks_.back().reserve(capacity);
}

// 16-fold, until the declared count is within 64 times the points read;
// then to that count. On an honest header this moves about a tenth of the
// points once (1,088 of Sphere6's 10,242), instead of all of them in take().
void PointBuffer::widen_first_block() {
  const std::size_t read = blocks_.front().size();
  std::vector<Vec3> wide;
  wide.reserve(read * 64 >= *declared_ ? *declared_ : read * 16);
  for (Vec3& p : blocks_.front()) wide.push_back(std::move(p));
  blocks_.front() = std::move(wide);
}

std::vector<Vec3> PointBuffer::take() {
  // Whole only when full: a nearly empty block would keep its unused room
  // for as long as the points live (a polyhedron may take them over).
  if (blocks_.size() == 1 && blocks_.front().size() == blocks_.front().capacity()) {
    std::vector<Vec3> points = std::move(blocks_.front());
    blocks_.clear();
    size_ = 0;
    return points;
  }
  std::vector<Vec3> points;
  points.reserve(size_);
  for (std::vector<Vec3>& block : blocks_) {
    for (Vec3& p : block) points.push_back(std::move(p));
    std::vector<Vec3>().swap(block);  // frees the block (and its moved-from numbers) at once
  }
  blocks_.clear();
  size_ = 0;
  return points;
}

std::string typed(std::string_view token) {
  constexpr std::size_t shown = 40;
  if (token.size() <= shown) return std::string(token);
  return std::string(token.substr(0, shown)) + "...";
}

std::optional<std::uint64_t> parse_unsigned(std::string_view token) {
  if (token.empty()) return std::nullopt;
  std::uint64_t value = 0;
  std::size_t digits = 0;
  constexpr std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
  for (char c : token) {
    if (!is_digit(c)) return std::nullopt;
    auto d = static_cast<std::uint64_t>(c - '0');
    // value * 10 + d > max, without a division per digit; the first 19
    // digits stay below 10^19 < 2^64 and skip the test (face lines are
    // mostly such tokens, a third of an OFF file's).
    const bool overflows = ++digits > 19 && (value > max / 10 || (value == max / 10 && d > max % 10));
    value = overflows ? max : value * 10 + d;
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

void check_soup_for_writing(const SoupView& soup, std::size_t min_size) {
  if (soup.face_offsets.empty() || soup.face_offsets.front() != 0 ||
      soup.face_offsets.back() != soup.face_indices.size())
    throw Error(ErrorCategory::invalid_argument, "polygon soup has inconsistent face offsets");
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    // Checked before face(f) reads the indices: offsets that rise past the
    // end and come back down ({0, 10, 5} with 5 indices) must not be read.
    if (soup.face_offsets[f + 1] < soup.face_offsets[f] || soup.face_offsets[f + 1] > soup.face_indices.size())
      throw Error(ErrorCategory::invalid_argument,
                  "polygon soup has decreasing face offsets at face " + std::to_string(f));
    auto face = soup.face(f);
    if (face.size() < min_size)
      throw Error(ErrorCategory::invalid_argument,
                  "face " + std::to_string(f) + " has " + std::to_string(face.size()) + " vertices");
    for (std::uint32_t i : face)
      if (i >= soup.num_points())
        throw Error(ErrorCategory::invalid_argument, "face " + std::to_string(f) + " has index " +
                                                         std::to_string(i) + " but there are " +
                                                         std::to_string(soup.num_points()) + " vertices");
  }
}

}  // namespace cvms::io_detail
