// SPDX-License-Identifier: MIT
// Private building blocks shared by the OFF, OBJ, STL and point readers: a
// bounded reader over a (possibly non-seekable) stream, a line splitter whose
// memory is bounded by the longest line, a whitespace tokenizer, and helpers
// that turn tokens into exact coordinates, counts and indices while producing
// error messages of the form "<source>:<line>: <what>".
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/io.hpp"
#include "cvms/polygon_soup.hpp"
#include "cvms/rational.hpp"
#include "soup_view.hpp"

namespace cvms::io_detail {

/// The exponent cap of every number token; see io.hpp.
inline constexpr long max_exponent = 100000;
/// The numbers of an input may always hold this many bits in all, however
/// short the input (ReadLimits::max_number_bits_per_byte scales beyond it).
inline constexpr std::uint64_t number_bits_allowance = std::uint64_t{1} << 20;

/// A token shown in a message: at most 40 characters, non-printable bytes as \xNN.
std::string quote(std::string_view token);

/// Reads raw bytes from a stream in chunks, never more than limits.max_bytes
/// in total (one byte more is requested to detect the overrun, which raises
/// Error(limit)); a stream failure other than end of input raises Error(io).
class ByteSource {
 public:
  /// `consumed` bytes of the input were read before (a PLY header): they
  /// count towards max_bytes and the offsets.
  ByteSource(std::istream& in, std::string_view source, std::uint64_t max_bytes, std::uint64_t consumed = 0)
      : in_(in), source_(source), max_bytes_(max_bytes), consumed_(consumed) {}
  /// Reads up to n bytes into dst; returns how many were read (0 only at the end).
  std::size_t read(char* dst, std::size_t n);
  /// Reads everything that is left (bounded by max_bytes).
  std::string read_all();
  [[nodiscard]] std::uint64_t consumed() const noexcept { return consumed_; }
  [[nodiscard]] std::string_view source() const noexcept { return source_; }
  /// Bytes the stream held when this source was made, if it can tell
  /// (files and string streams; not pipes or terminals).
  [[nodiscard]] std::optional<std::uint64_t> size_at_start() const noexcept { return size_at_start_; }

 private:
  std::istream& in_;
  std::string source_;
  std::uint64_t max_bytes_;
  std::uint64_t consumed_ = 0;
  bool at_end_ = false;
  std::optional<std::uint64_t> size_at_start_ = bytes_left(in_);

  static std::optional<std::uint64_t> bytes_left(std::istream& in);
};

/// Splits the input into lines ('\n' or "\r\n"). A line is returned as a view
/// into an internal buffer that stays valid until the next call to next().
/// The buffer only grows to hold the longest line, so memory is bounded by
/// the input size and by limits.max_line_bytes (a longer line is
/// Error(limit)). Input read from a stream must hold no NUL byte.
class LineReader {
 public:
  LineReader(std::istream& in, std::string_view source, const ReadLimits& limits)
      : bytes_(std::in_place, in, source, limits.max_bytes), source_(source), limits_(limits) {}
  /// Where a reader continues a stream whose first lines were read by
  /// another (a PLY header): line numbers and byte offsets go on from there.
  struct Continuation {
    std::uint64_t lines;
    std::uint64_t bytes;
  };
  LineReader(std::istream& in, std::string_view source, const ReadLimits& limits, Continuation at)
      : bytes_(std::in_place, in, source, limits.max_bytes, at.bytes),
        source_(source),
        limits_(limits),
        buffer_offset_(at.bytes),
        line_end_(at.bytes),
        line_number_(at.lines) {}
  /// Lines of data already in memory (read through a ByteSource, so bounded).
  LineReader(std::string data, std::string_view source, const ReadLimits& limits)
      : source_(source), limits_(limits), buffer_(std::move(data)), end_(buffer_.size()), eof_(true) {}

  /// The next line without its terminator; false at the end of the input.
  bool next(std::string_view& line);
  /// Makes the next call to next() return the last line again.
  void unread() noexcept { replay_ = true; }
  /// 1-based number of the line last returned by next().
  [[nodiscard]] std::uint64_t line_number() const noexcept { return line_number_; }
  [[nodiscard]] std::string_view source() const noexcept { return source_; }
  [[nodiscard]] const ReadLimits& limits() const noexcept { return limits_; }

  /// Error(category) with "<source>:<line>: <message>".
  [[noreturn]] void fail(std::string_view message, ErrorCategory category = ErrorCategory::parse) const;
  /// Error(limit): the line being read is longer than limits().max_line_bytes.
  [[noreturn]] void fail_long_line() const;
  /// Error(parse) naming the line and byte offset of the NUL byte at
  /// buffer_[at] (text formats hold none; binary junk such as /dev/zero is
  /// refused at its first chunk).
  [[noreturn]] void fail_binary(std::size_t at) const;

  /// Bytes of input up to the end of the line last returned by next().
  [[nodiscard]] std::uint64_t bytes_through_line() const noexcept { return line_end_; }
  /// Adds the bits of a number read to the input's total; false once the
  /// total is beyond what limits().max_number_bits_per_byte allows for the
  /// bytes read so far (never less than number_bits_allowance).
  bool add_number_bits(std::uint64_t bits) noexcept;
  [[nodiscard]] std::uint64_t number_bits() const noexcept { return number_bits_; }
  /// What add_number_bits allows now.
  [[nodiscard]] std::uint64_t number_bits_allowed() const noexcept;
  /// How many elements to reserve for `declared` ones that need at least
  /// `min_bytes` of input each: `declared` when the input is known to hold
  /// that many bytes (so an honest count reserves once, and a lying one
  /// reserves no more than the input's size allows), else safe_reserve's cap.
  [[nodiscard]] std::size_t reserve_for(std::uint64_t declared, std::uint64_t min_bytes) const noexcept;
  /// Where numbers that are checked but not kept (colors, normals) are parsed.
  Rational& scratch() noexcept { return scratch_; }

 private:
  std::optional<ByteSource> bytes_;  // empty when reading from memory
  std::string source_;
  ReadLimits limits_;
  std::string buffer_;
  std::size_t begin_ = 0;    // start of the unread data in buffer_
  std::size_t end_ = 0;      // end of the data in buffer_
  std::size_t scanned_ = 0;  // [begin_, scanned_) is known to hold no '\n'
  std::uint64_t buffer_offset_ = 0;  // input offset of buffer_[0]
  std::uint64_t line_end_ = 0;
  std::uint64_t number_bits_ = 0;
  Rational scratch_;
  bool eof_ = false;
  bool replay_ = false;
  bool carriage_return_inside_ = false;  // in the last line (kept: last_ may dangle at the end)
  std::string_view last_;
  std::uint64_t line_number_ = 0;
};

/// Splits a line into whitespace-separated tokens; '#' starts a comment that
/// runs to the end of the line when comments are enabled, except inside an
/// MSVC spelling of a non-finite value ("1.#INF", "-1.#IND", "1.#QNAN"),
/// which stays one token so that it is refused rather than read as "1.".
class Tokenizer {
 public:
  explicit Tokenizer(std::string_view line, bool comments = true) : rest_(line), comments_(comments) {}
  /// The next token, or an empty view when the line is exhausted.
  std::string_view next();
  /// True when only whitespace (and a comment) is left.
  bool at_end();
  /// When the next token is 1 to 19 decimal digits ending the line or
  /// followed by whitespace (every face index of a well-formed file), takes
  /// it into `token` and its value into `value` and returns true, in one
  /// pass over its digits. Otherwise returns false, and next() returns that
  /// token as it would have (a caller then takes the general route, with
  /// its checks and messages).
  bool next_short_unsigned(std::string_view& token, std::uint64_t& value);

 private:
  void skip_space();
  std::string_view rest_;
  bool comments_;
};

/// The tokens of a reader's lines across line breaks, without comments
/// (ASCII STL, PLY bodies). A token stays valid until the next call.
class TokenStream {
 public:
  explicit TokenStream(LineReader& reader) : reader_(reader) {}
  /// The next token, or an empty view at the end of the input.
  std::string_view next() {
    for (;;) {
      std::string_view t = tokens_.next();
      if (!t.empty()) return t;
      std::string_view line;
      if (!reader_.next(line)) return {};
      tokens_ = Tokenizer(line, false);
    }
  }
  void skip_rest_of_line() noexcept { tokens_ = Tokenizer(std::string_view{}, false); }
  [[nodiscard]] LineReader& reader() const noexcept { return reader_; }

 private:
  LineReader& reader_;
  Tokenizer tokens_{std::string_view{}, false};
};

/// True for the spellings of NaN and infinity that C and common exporters
/// produce ("nan", "-nan(ind)", "inf", "+Infinity", "1.#INF", "1.#IND",
/// "1.#QNAN", ...).
bool looks_non_finite(std::string_view token);

/// Names a value in messages ("x coordinate of vertex 3", "z coordinate of
/// vertex 2 of facet 7"); the text is only built when a message needs it.
struct ValueName {
  const char* what;     ///< "x coordinate", "color value", ...
  const char* element;  ///< "vertex", "point"
  std::uint64_t index;
  const char* outer = nullptr;  ///< "facet", or none
  std::uint64_t outer_index = 0;
  [[nodiscard]] std::string str() const;
};

/// Sets `out` to the exact value of a number token, or fails with a message
/// naming the line and the value: Error(parse) for NaN/inf and junk,
/// Error(limit) for a token longer than limits.max_number_chars, an exponent
/// beyond max_exponent, a numerator or denominator beyond
/// limits.max_number_bits (refused from the text, before it is built) and
/// numbers beyond limits.max_number_bits_per_byte in all.
void parse_number(LineReader& reader, std::string_view token, const ValueName& name, Rational& out);
/// A value that is checked like a coordinate but not kept (a color, a
/// normal); with allow_non_finite, NaN and inf spellings pass too (STL
/// normals of degenerate facets). Returns the value, in reader.scratch().
const Rational& check_number(LineReader& reader, std::string_view token, const ValueName& name,
                             bool allow_non_finite = false);
/// Sets p to the coordinates x y z of the next three tokens of `next()`.
template <class NextToken>
void parse_point(LineReader& reader, NextToken&& next, Vec3& p, const char* element, std::uint64_t index,
                 const char* outer = nullptr, std::uint64_t outer_index = 0) {
  parse_number(reader, next(), {"x coordinate", element, index, outer, outer_index}, p.x);
  parse_number(reader, next(), {"y coordinate", element, index, outer, outer_index}, p.y);
  parse_number(reader, next(), {"z coordinate", element, index, outer, outer_index}, p.z);
}

/// The points of a reader, kept in blocks that never move until take(). A
/// growing std::vector<Vec3> copies every number each time it grows
/// (gmpxx's mpq_class move constructor is not noexcept), so at that moment
/// it holds all of them twice; here each number is moved exactly once, into
/// a vector of the final size, block by block, so the memory in use never
/// exceeds that of the result by more than a block.
class PointBuffer {
 public:
  /// Blocks of a fixed size: a point, once appended, never moves until
  /// take() (readers may keep its address, as the ASCII STL reader does).
  PointBuffer() = default;
  /// For a declared count (a header's, bounded by LineReader::reserve_for):
  /// the first block grows towards it as points arrive, and when the count
  /// is right take() hands that block over whole, so that no point is moved
  /// one by one (moving a rational allocates a limb for the moved-from one).
  /// Growing moves the points appended before: do not keep their addresses.
  struct Declared {
    std::size_t count;
  };
  explicit PointBuffer(Declared declared) : declared_(declared.count) {}
  /// A new default point at the end.
  Vec3& append();
  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  /// All points in order; the buffer is empty afterwards.
  std::vector<Vec3> take();

 private:
  void add_block(std::size_t capacity);
  void widen_first_block();

  static constexpr std::size_t block_size = 4096;
  std::optional<std::size_t> declared_;
  std::vector<std::vector<Vec3>> blocks_;
  std::size_t size_ = 0;
};

/// An integer token as typed, for messages (at most 40 characters, so a
/// saturated value is never shown as 2^63-1).
std::string typed(std::string_view token);

/// A non-negative decimal integer token (no sign, no exponent); nullopt if the
/// token is not one; values beyond 2^64-1 saturate to UINT64_MAX.
std::optional<std::uint64_t> parse_unsigned(std::string_view token);
/// A decimal integer token with optional sign; values beyond +-2^63 saturate.
std::optional<std::int64_t> parse_signed(std::string_view token);

/// Raises Error(limit) unless the soup may grow to `vertices` points.
void check_vertex_limit(const LineReader& reader, std::uint64_t vertices);
/// Raises Error(limit) unless the soup may grow to `faces` faces with
/// `indices` indices in total (indices must fit the 32-bit offsets).
void check_face_limit(const LineReader& reader, std::uint64_t faces, std::uint64_t indices);

/// How many elements to reserve for a header count that has not been checked
/// against the input yet: never more than a small fixed cap, so a lying header
/// cannot make us allocate.
inline std::size_t safe_reserve(std::uint64_t declared) {
  constexpr std::uint64_t cap = 1u << 12;
  return static_cast<std::size_t>(declared < cap ? declared : cap);
}

/// Parsers that continue on a LineReader (so that read_points can look at the
/// first line before choosing one).
PolygonSoup parse_off(LineReader& reader);
/// An OBJ object: an `o` statement, and the faces that follow it up to the
/// next one.
struct ObjObject {
  std::uint64_t line = 0;        ///< of the `o` statement (1-based)
  std::uint64_t first_face = 0;  ///< index of its first face in the soup
  std::string name;              ///< the first token after `o`, may be empty
};
/// When `objects` is given, each `o` statement is appended to it (else they
/// are ignored, as the other statements that do not change the geometry).
PolygonSoup parse_obj(LineReader& reader, std::vector<ObjObject>* objects = nullptr);
/// True if the token is an OFF header keyword we recognise (OFF, COFF, NOFF,
/// STOFF, ... and the unsupported 4OFF/nOFF, which parse_off rejects).
bool is_off_keyword(std::string_view token);

/// Opens a file for reading, binary. \throw Error(io) naming it (and the
/// system's reason) if it cannot be opened or is a directory.
std::ifstream open_input_file(const std::filesystem::path& path);

/// Validation for writers: every face has >= min_size indices, each < points.size().
void check_soup_for_writing(const SoupView& soup, std::size_t min_size);

}  // namespace cvms::io_detail
