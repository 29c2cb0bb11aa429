// SPDX-License-Identifier: MIT
// PLY header reader. The header is text up to the line "end_header"; the
// body after it may be binary, so the header is read one byte at a time
// from the stream (never a chunk past its end), bounded by
// ReadLimits::max_line_bytes as a whole. The counts of the elements
// "vertex" and "face" are checked against ReadLimits as soon as their line
// is read: a header announcing 10^12 vertices is refused before the body
// is touched.
#include "ply_header.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <set>

namespace cvms::io_detail {
namespace {

struct TypeName {
  std::string_view name;
  PlyType type;
};

constexpr std::array<TypeName, 16> type_names{{
    {"char", PlyType::int8},      {"uchar", PlyType::uint8},    {"short", PlyType::int16},
    {"ushort", PlyType::uint16},  {"int", PlyType::int32},      {"uint", PlyType::uint32},
    {"float", PlyType::float32},  {"double", PlyType::float64}, {"int8", PlyType::int8},
    {"uint8", PlyType::uint8},    {"int16", PlyType::int16},    {"uint16", PlyType::uint16},
    {"int32", PlyType::int32},    {"uint32", PlyType::uint32},  {"float32", PlyType::float32},
    {"float64", PlyType::float64},
}};

std::optional<PlyType> type_of(std::string_view name) {
  for (const TypeName& t : type_names)
    if (t.name == name) return t.type;
  return std::nullopt;
}

// The header's lines, read byte by byte so that the stream stops right
// after "end_header\n".
class HeaderLines {
 public:
  HeaderLines(ByteSource& bytes, const ReadLimits& limits) : bytes_(bytes), limits_(limits) {}

  // The next line without its terminator ('\n' or "\r\n"); false at the end of the input.
  bool next(std::string_view& line) {
    line_.clear();
    reading_ = true;
    char c = 0;
    for (;;) {
      if (bytes_.read(&c, 1) == 0) {
        if (line_.empty()) {
          reading_ = false;
          return false;
        }
        break;
      }
      if (bytes_.consumed() > limits_.max_line_bytes) fail_long();
      if (c == '\0') fail("a NUL byte in the header (at byte " + std::to_string(bytes_.consumed() - 1) + ")");
      if (c == '\n') break;
      line_.push_back(c);
      if (number_ == 0) check_magic();
    }
    ++number_;
    reading_ = false;
    if (!line_.empty() && line_.back() == '\r') line_.pop_back();
    line = line_;
    return true;
  }

  [[noreturn]] void fail(const std::string& message, ErrorCategory category = ErrorCategory::parse) const {
    throw Error(category, std::string(bytes_.source()) + ":" + std::to_string(number_ + (reading_ ? 1 : 0)) +
                              ": " + message);
  }
  [[nodiscard]] std::string_view source() const noexcept { return bytes_.source(); }
  [[nodiscard]] std::uint64_t number() const noexcept { return number_; }
  [[nodiscard]] std::uint64_t bytes() const noexcept { return bytes_.consumed(); }

 private:
  // Anything but "ply" on the first line is refused at its first wrong byte
  // (a binary file of another format ends at once).
  void check_magic() const {
    static constexpr std::string_view magic = "ply";
    const std::size_t n = line_.size();
    const bool ok = n <= magic.size() ? std::string_view(line_) == magic.substr(0, n)
                                      : n == magic.size() + 1 && line_.back() == '\r';
    if (!ok) throw Error(ErrorCategory::parse, std::string(bytes_.source()) + ":1: expected 'ply' as the first line");
  }
  [[noreturn]] void fail_long() const {
    fail("the PLY header is longer than the limit of " + std::to_string(limits_.max_line_bytes) +
             " bytes (ReadLimits::max_line_bytes)",
         ErrorCategory::limit);
  }

  ByteSource& bytes_;
  const ReadLimits& limits_;
  std::string line_;
  std::uint64_t number_ = 0;
  bool reading_ = false;  // a message names the line being read, else the one returned
};

// Reads the rest of a header once "ply" has been seen.
class HeaderParser {
 public:
  HeaderParser(HeaderLines& lines, const ReadLimits& limits) : lines_(lines), limits_(limits) {}

  PlyHeader parse() {
    std::string_view line;
    for (;;) {
      if (!lines_.next(line)) lines_.fail("unexpected end of input in the PLY header (no 'end_header')");
      Tokenizer tokens(line, false);
      const std::string_view keyword = tokens.next();
      if (keyword == "end_header") break;
      statement(keyword, tokens);
    }
    if (!format_seen_) lines_.fail("'end_header' before the 'format' line");
    finish_elements();
    header_.lines = lines_.number();
    header_.bytes = lines_.bytes();
    return std::move(header_);
  }

 private:
  void statement(std::string_view keyword, Tokenizer& tokens) {
    if (keyword == "comment" || keyword == "obj_info" || keyword.empty()) return;
    if (keyword == "format") return format(tokens);
    if (keyword == "element") return element(tokens);
    if (keyword == "property") return property(tokens);
    if (keyword == "ply") lines_.fail("a second 'ply' line in the header");
    lines_.fail("unknown PLY header keyword " + quote(keyword));
  }

  void format(Tokenizer& tokens) {
    if (format_seen_) lines_.fail("a second 'format' line");
    format_seen_ = true;
    const std::string_view encoding = tokens.next();
    if (encoding == "ascii")
      header_.encoding = PlyEncoding::ascii;
    else if (encoding == "binary_little_endian")
      header_.encoding = PlyEncoding::binary_little_endian;
    else if (encoding == "binary_big_endian")
      header_.encoding = PlyEncoding::binary_big_endian;
    else
      lines_.fail("unknown PLY format " + quote(encoding) +
                  " (expected ascii, binary_little_endian or binary_big_endian)");
    const std::string_view version = tokens.next();
    if (version != "1.0") lines_.fail("unsupported PLY version " + quote(version) + " (expected 1.0)");
    if (!tokens.at_end()) lines_.fail("unexpected " + quote(tokens.next()) + " after the format");
  }

  void element(Tokenizer& tokens) {
    if (!format_seen_) lines_.fail("an 'element' line before the 'format' line");
    PlyElement e;
    e.name = std::string(tokens.next());
    if (e.name.empty()) lines_.fail("'element' without a name");
    const std::string_view count = tokens.next();
    const std::optional<std::uint64_t> value = parse_unsigned(count);
    if (!value) lines_.fail("element " + quote(e.name) + ": count " + quote(count) + " is not a non-negative integer");
    if (*value == std::numeric_limits<std::uint64_t>::max())
      lines_.fail("element " + quote(e.name) + ": count " + quote(count) + " is beyond 2^64-1", ErrorCategory::limit);
    if (!tokens.at_end()) lines_.fail("unexpected " + quote(tokens.next()) + " after the element's count");
    e.count = *value;
    e.line = lines_.number();
    if (!element_names_.insert(e.name).second) lines_.fail("a second element " + quote(e.name));
    property_names_.clear();
    check_count(e);
    header_.elements.push_back(std::move(e));
  }

  // The vertex and face counts against the limits, as soon as they are read.
  void check_count(const PlyElement& e) const {
    const std::uint64_t vertex_cap =
        std::min<std::uint64_t>(limits_.max_vertices, std::numeric_limits<std::uint32_t>::max());
    if (e.name == "vertex" && e.count > vertex_cap)
      lines_.fail(std::to_string(e.count) + " vertices exceed the limit of " + std::to_string(vertex_cap),
                  ErrorCategory::limit);
    if (e.name == "face" && e.count > limits_.max_faces)
      lines_.fail(std::to_string(e.count) + " faces exceed the limit of " + std::to_string(limits_.max_faces),
                  ErrorCategory::limit);
  }

  PlyType parse_type(std::string_view name) const {
    const std::optional<PlyType> type = type_of(name);
    if (!type) lines_.fail("unknown PLY property type " + quote(name));
    return *type;
  }

  void property(Tokenizer& tokens) {
    if (header_.elements.empty()) lines_.fail("a 'property' line before any 'element' line");
    PlyElement& e = header_.elements.back();
    PlyProperty p;
    std::string_view type = tokens.next();
    if (type == "list") {
      p.is_list = true;
      p.count_type = parse_type(tokens.next());
      if (!ply_is_integer(p.count_type))
        lines_.fail("the count type of a list must be an integer type, not " + quote(ply_name(p.count_type)));
      type = tokens.next();
    }
    p.type = parse_type(type);
    p.name = std::string(tokens.next());
    if (p.name.empty()) lines_.fail("'property' without a name");
    if (!tokens.at_end()) lines_.fail("unexpected " + quote(tokens.next()) + " after the property's name");
    if (!property_names_.insert(p.name).second)
      lines_.fail("element " + quote(e.name) + " has a second property " + quote(p.name));
    e.properties.push_back(std::move(p));
  }

  // Roles: x, y and z of "vertex" (scalars, required), the index list of
  // "face" (vertex_indices or vertex_index, required when there is a face element).
  void finish_elements() {
    bool have_vertex = false;
    for (PlyElement& e : header_.elements) {
      if (e.name == "vertex") {
        have_vertex = true;
        header_.vertices = e.count;
        assign_coordinates(e);
      } else if (e.name == "face") {
        header_.faces = e.count;
        assign_indices(e);
      }
    }
    if (!have_vertex) lines_.fail("the PLY header declares no 'vertex' element");
  }

  void assign_coordinates(PlyElement& e) const {
    constexpr std::array<std::pair<std::string_view, PlyRole>, 3> axes{
        {{"x", PlyRole::x}, {"y", PlyRole::y}, {"z", PlyRole::z}}};
    for (const auto& [axis, role] : axes) {
      auto p = std::find_if(e.properties.begin(), e.properties.end(),
                            [axis = axis](const PlyProperty& q) { return q.name == axis; });
      if (p == e.properties.end())
        fail_at(e, "element 'vertex' has no property " + quote(axis));
      if (p->is_list) fail_at(e, "property " + quote(axis) + " of element 'vertex' is a list, not a number");
      p->role = role;
    }
  }

  void assign_indices(PlyElement& e) const {
    PlyProperty* found = nullptr;
    for (PlyProperty& p : e.properties) {
      if (p.name != "vertex_indices" && p.name != "vertex_index") continue;
      if (found != nullptr) fail_at(e, "element 'face' has both 'vertex_indices' and 'vertex_index'");
      found = &p;
    }
    if (found == nullptr) fail_at(e, "element 'face' has no list property 'vertex_indices' (or 'vertex_index')");
    if (!found->is_list) fail_at(e, "property " + quote(found->name) + " of element 'face' is not a list");
    if (!ply_is_integer(found->type))
      fail_at(e, "the indices of " + quote(found->name) + " must be of an integer type, not " +
                     quote(ply_name(found->type)));
    found->role = PlyRole::vertex_indices;
  }

  [[noreturn]] void fail_at(const PlyElement& e, const std::string& message) const {
    throw Error(ErrorCategory::parse, std::string(source()) + ":" + std::to_string(e.line) + ": " + message);
  }
  [[nodiscard]] std::string_view source() const noexcept { return lines_.source(); }

  HeaderLines& lines_;
  const ReadLimits& limits_;
  PlyHeader header_;
  // Names seen so far, in balanced trees: a header may hold millions of
  // elements or properties, so duplicates are not searched for linearly.
  std::set<std::string, std::less<>> element_names_;
  std::set<std::string, std::less<>> property_names_;  // of the last element
  bool format_seen_ = false;
};

}  // namespace

std::size_t ply_size(PlyType type) noexcept {
  switch (type) {
    case PlyType::int8:
    case PlyType::uint8:
      return 1;
    case PlyType::int16:
    case PlyType::uint16:
      return 2;
    case PlyType::int32:
    case PlyType::uint32:
    case PlyType::float32:
      return 4;
    case PlyType::float64:
      return 8;
  }
  return 8;
}

bool ply_is_integer(PlyType type) noexcept { return type != PlyType::float32 && type != PlyType::float64; }

const char* ply_name(PlyType type) noexcept {
  for (const TypeName& t : type_names)
    if (t.type == type) return t.name.data();  // the names are literals, NUL-terminated
  return "?";
}

std::uint64_t PlyElement::fixed_size() const noexcept {
  std::uint64_t size = 0;
  for (const PlyProperty& p : properties) {
    if (p.is_list) return 0;
    size += ply_size(p.type);
  }
  return size;
}

PlyHeader read_ply_header(ByteSource& bytes, const ReadLimits& limits) {
  HeaderLines lines(bytes, limits);
  std::string_view first;
  if (!lines.next(first)) throw Error(ErrorCategory::parse, std::string(bytes.source()) + ": empty input");
  if (first != "ply") lines.fail("expected 'ply' as the first line");
  HeaderParser parser(lines, limits);
  return parser.parse();
}

}  // namespace cvms::io_detail
