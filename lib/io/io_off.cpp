// SPDX-License-Identifier: MIT
// OFF reader and writer. The reader is line based: the header keyword
// ([ST][C][N]OFF), the counts "V F [E]" (free-form: on the header line or
// the lines after it), one vertex per line, one face "n i_1 ... i_n [color]" per line; '#'
// starts a comment anywhere and blank lines are skipped. Counts are checked
// against ReadLimits but never used to allocate more than a small fixed
// reserve, so a header that lies costs nothing.
#include <limits>
#include <string>
#include <utility>

#include "float_coordinates.hpp"
#include "io_reader.hpp"
#include "io_writer.hpp"

namespace cvms {
namespace io_detail {
namespace {

// Which optional per-vertex values the header announces (COFF, NOFF, STOFF, ...).
struct OffHeader {
  bool texture = false;  // ST: 2 values
  bool color = false;    // C: 3 or 4 values
  bool normal = false;   // N: 3 values
  bool four_d = false;   // 4: unsupported
  bool n_dim = false;    // n: unsupported
};

std::optional<OffHeader> parse_off_keyword(std::string_view token) {
  OffHeader h;
  auto take = [&token](std::string_view prefix) {
    if (token.substr(0, prefix.size()) != prefix) return false;
    token.remove_prefix(prefix.size());
    return true;
  };
  h.texture = take("ST");
  h.color = take("C");
  h.normal = take("N");
  h.four_d = take("4");
  h.n_dim = take("n");
  if (token != "OFF") return std::nullopt;
  return h;
}

// The next line holding a token (comments and blank lines skipped), with a
// tokenizer positioned after that first token. False at the end of input.
bool next_content_line(LineReader& reader, Tokenizer& tokens, std::string_view& first) {
  std::string_view line;
  while (reader.next(line)) {
    tokens = Tokenizer(line);
    first = tokens.next();
    if (!first.empty()) return true;
  }
  return false;
}

[[noreturn]] void fail_end(const LineReader& reader, const std::string& message) {
  if (reader.line_number() == 0)
    throw Error(ErrorCategory::parse, std::string(reader.source()) + ": empty input (" + message + ")");
  reader.fail("unexpected end of input: " + message);
}

std::uint64_t parse_count(const LineReader& reader, std::string_view token, const char* what) {
  if (token.empty()) reader.fail(std::string("missing ") + what + " count in the OFF header");
  auto value = parse_unsigned(token);
  if (!value) reader.fail(std::string(what) + " count " + quote(token) + " is not a non-negative integer");
  if (*value == std::numeric_limits<std::uint64_t>::max())
    reader.fail(std::string(what) + " count " + quote(token) + " is beyond 2^64-1", ErrorCategory::limit);
  return *value;
}

// What the values after x y z are called in messages.
const char* extra_value_name(const OffHeader& h) {
  if (int{h.texture} + int{h.color} + int{h.normal} != 1) return "normal, color or texture value";
  return h.color ? "color value" : h.normal ? "normal component" : "texture coordinate";
}

struct OffCounts {
  std::uint64_t vertices = 0;
  std::uint64_t faces = 0;
};

// The next count token: the rest of the current line, else the next content line.
std::string_view next_count_token(LineReader& reader, Tokenizer& tokens, const char* expected) {
  std::string_view token = tokens.next();
  if (token.empty() && !next_content_line(reader, tokens, token))
    fail_end(reader, std::string("expected the ") + expected);
  return token;
}

// The counts "V F [E]" after the keyword (`token` is the first token after
// it, or empty). The format is free-form: V and F may each be on the header
// line or on lines of their own; E is taken from F's line, or from a line
// holding nothing else right after a line that held F alone (a vertex line
// has at least 3 values, so that line cannot be one).
OffCounts parse_off_counts(LineReader& reader, Tokenizer& tokens, std::string_view token) {
  if (token.empty() && !next_content_line(reader, tokens, token))
    fail_end(reader, "expected the counts 'V F E'");
  OffCounts counts;
  counts.vertices = parse_count(reader, token, "vertex");
  const std::uint64_t line_of_vertices = reader.line_number();
  counts.faces = parse_count(reader, next_count_token(reader, tokens, "face count"), "face");
  if (std::string_view edges = tokens.next(); !edges.empty()) {
    parse_count(reader, edges, "edge");
  } else if (reader.line_number() != line_of_vertices) {
    // F stood alone on its line: E may stand alone on the next one.
    std::string_view first;
    if (next_content_line(reader, tokens, first)) {
      if (tokens.at_end() && parse_unsigned(first))
        parse_count(reader, first, "edge");
      else
        reader.unread();
    }
    return counts;
  }
  if (!tokens.at_end()) reader.fail("unexpected " + quote(tokens.next()) + " after the counts 'V F E'");
  return counts;
}

}  // namespace

bool is_off_keyword(std::string_view token) { return parse_off_keyword(token).has_value(); }

PolygonSoup parse_off(LineReader& reader) {
  Tokenizer tokens{std::string_view{}};
  std::string_view first;
  if (!next_content_line(reader, tokens, first)) fail_end(reader, "expected an 'OFF' header");
  auto header = parse_off_keyword(first);
  if (!header) reader.fail("expected an 'OFF' header, found " + quote(first));
  if (header->four_d || header->n_dim) reader.fail("only 3D OFF is supported, not " + quote(first));
  // A copy: `first` views the reader's line buffer, which the next line
  // replaces (found by fuzzing: a heap use-after-free in a later message).
  const std::string keyword(first);

  std::string_view token = tokens.next();
  if (token == "BINARY") reader.fail("binary OFF is not supported");
  const OffCounts counts = parse_off_counts(reader, tokens, token);
  const std::uint64_t num_vertices = counts.vertices;
  const std::uint64_t num_faces = counts.faces;
  check_vertex_limit(reader, num_vertices);
  check_face_limit(reader, num_faces, 0);

  const std::size_t min_extra =
      (header->texture ? 2 : 0) + (header->color ? 3 : 0) + (header->normal ? 3 : 0);
  const std::size_t max_extra = min_extra + (header->color ? 1 : 0);
  // The values after x y z are ignored but checked like coordinates.
  const char* extra_name = extra_value_name(*header);

  PolygonSoup soup;
  // A vertex line holds at least "0 0 0" and a separator.
  constexpr std::uint64_t min_vertex_bytes = 6;
  PointBuffer points(PointBuffer::Declared{reader.reserve_for(num_vertices, min_vertex_bytes)});
  for (std::uint64_t v = 0; v < num_vertices; ++v) {
    if (!next_content_line(reader, tokens, token))
      fail_end(reader, "the header declares " + std::to_string(num_vertices) + " vertices but only " +
                           std::to_string(v) + " were found");
    bool first_token = true;
    parse_point(
        reader, [&] { return std::exchange(first_token, false) ? token : tokens.next(); }, points.append(),
        "vertex", v);
    std::size_t extra = 0;
    for (Tokenizer rest = tokens; !rest.next().empty();) ++extra;
    if (extra < min_extra || extra > max_extra)
      reader.fail("vertex " + std::to_string(v) + " has " + std::to_string(3 + extra) + " values, expected " +
                  std::to_string(3 + min_extra) +
                  (max_extra != min_extra ? " or " + std::to_string(3 + max_extra) : std::string()) +
                  " for a '" + keyword + "' file");
    for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next())
      check_number(reader, t, {extra_name, "vertex", v});
  }

  soup.points = points.take();
  soup.face_offsets.reserve(safe_reserve(num_faces) + 1);
  soup.face_indices.reserve(safe_reserve(num_faces) * 3);
  for (std::uint64_t f = 0; f < num_faces; ++f) {
    if (!next_content_line(reader, tokens, token))
      fail_end(reader, "the header declares " + std::to_string(num_faces) + " faces but only " +
                           std::to_string(f) + " were found");
    // Named only when something fails: building the name per face cost more
    // than reading its indices.
    const auto name = [f] { return "face " + std::to_string(f); };
    auto size = parse_unsigned(token);
    if (!size) reader.fail(name() + ": vertex count " + quote(token) + " is not a non-negative integer");
    if (*size < 3) reader.fail(name() + " has " + std::to_string(*size) + " vertices, at least 3 are needed");
    for (std::uint64_t k = 0; k < *size; ++k) {
      std::string_view t;
      std::uint64_t short_index = 0;
      std::optional<std::uint64_t> index;
      if (tokens.next_short_unsigned(t, short_index)) {
        index = short_index;
      } else {
        t = tokens.next();
        if (t.empty())
          reader.fail(name() + " declares " + typed(token) + " vertices but lists " + std::to_string(k));
        index = parse_unsigned(t);
        if (!index) reader.fail(name() + ": index " + quote(t) + " is not a non-negative integer");
      }
      if (*index >= num_vertices)
        reader.fail(name() + " has index " + typed(t) + " but there are " + std::to_string(num_vertices) +
                    " vertices");
      soup.face_indices.push_back(static_cast<std::uint32_t>(*index));
      if (soup.face_indices.size() % 4096 == 0) check_face_limit(reader, f + 1, soup.face_indices.size());
    }
    check_face_limit(reader, f + 1, soup.face_indices.size());
    // Up to four color components may follow the indices; they are ignored,
    // but checked like coordinates.
    std::size_t extra = 0;
    for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next()) {
      if (++extra > 4) reader.fail(name() + " has more than 4 values after its " + typed(token) + " indices");
      check_number(reader, t, {"color value", "face", f});
    }
    soup.face_offsets.push_back(static_cast<std::uint32_t>(soup.face_indices.size()));
  }

  if (next_content_line(reader, tokens, token))
    reader.fail("unexpected " + quote(token) + " after the last of the " + std::to_string(num_faces) +
                " faces the header declares");
  return soup;
}

}  // namespace io_detail

PolygonSoup read_off(std::istream& in, std::string_view source, const ReadLimits& limits) {
  io_detail::LineReader reader(in, source, limits);
  return io_detail::parse_off(reader);
}

void write_off(std::ostream& out, const PolygonSoup& soup, Coordinates coordinates) {
  io_detail::write_off_view(out, io_detail::SoupView::of(soup), coordinates);
}

void io_detail::write_off_view(std::ostream& out, const SoupView& soup, Coordinates coordinates) {
  io_detail::check_soup_coordinates(coordinates);
  io_detail::check_soup_for_writing(soup, 3);
  io_detail::TextWriter w(out);
  w.text("OFF\n").integer(soup.num_points()).byte(' ').integer(soup.num_faces()).text(" 0\n");
  for (std::size_t j = 0; j < soup.num_points(); ++j) w.point(soup, j, coordinates).byte('\n');
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto face = soup.face(f);
    w.integer(face.size());
    for (std::uint32_t i : face) w.byte(' ').integer(i);
    w.byte('\n');
  }
  w.finish();
}

}  // namespace cvms
