// SPDX-License-Identifier: MIT
// STL reader (ASCII and binary) and binary writer. The input is read whole
// (bounded by ReadLimits::max_bytes) because telling the two kinds apart
// needs the size: a binary file is exactly 84 + 50 n bytes for the n its
// header declares, and that test wins even when the 80-byte header starts
// with "solid" (many exporters write such headers). Vertices are merged by
// exact position, in order of first appearance, by sorting (never by
// hashing: an input could choose colliding keys).
#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <vector>

#include "io_reader.hpp"
#include "io_writer.hpp"
#include "representation_order.hpp"

namespace cvms {
namespace io_detail {
namespace {

constexpr std::size_t header_size = 84;
constexpr std::size_t record_size = 50;

std::uint32_t load_u32_le(const std::string& data, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i)
    v = (v << 8) | static_cast<unsigned char>(data[at + static_cast<std::size_t>(i)]);
  return v;
}

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char c = a[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != b[i]) return false;
  }
  return true;
}

bool starts_with_solid(const std::string& data) {
  std::size_t i = data.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;  // UTF-8 byte order mark
  while (i < data.size() && (data[i] == ' ' || data[i] == '\t' || data[i] == '\r' || data[i] == '\n')) ++i;
  if (!iequals(std::string_view(data).substr(i, 5), "solid")) return false;
  i += 5;
  return i == data.size() || data[i] == ' ' || data[i] == '\t' || data[i] == '\r' || data[i] == '\n';
}

[[noreturn]] void fail_at(std::string_view source, std::uint64_t offset, const std::string& message,
                          ErrorCategory category = ErrorCategory::parse) {
  throw Error(category, std::string(source) + ": byte " + std::to_string(offset) + ": " + message);
}

// A corner's position as float bit patterns (-0 as +0), with the corner's
// number in file order.
struct Corner {
  std::array<std::uint32_t, 3> bits;
  std::uint32_t index;
};

// The corners' float bits in file order, checked finite; `first_bad` is the
// first corner with a non-finite coordinate (or `corners.size()`), so that
// errors still come in file order.
struct BinaryCorners {
  std::vector<Corner> corners;
  std::size_t first_bad;
  std::size_t bad_at = 0;  // byte offset of the first non-finite coordinate
  bool bad_is_nan = false;
};

// The bits of a float coordinate as a position: -0 and +0 are the same.
std::uint32_t position_bits(std::uint32_t bits) { return bits == 0x80000000u ? 0 : bits; }

// Byte offset of corner c (3 per triangle).
std::size_t corner_offset(std::size_t c) { return header_size + record_size * (c / 3) + 12 + 12 * (c % 3); }

BinaryCorners load_corners(const std::string& data, std::uint32_t count) {
  BinaryCorners out{std::vector<Corner>(std::size_t{count} * 3), std::size_t{count} * 3};
  for (std::size_t c = 0; c < out.corners.size(); ++c) {
    const std::size_t at = corner_offset(c);
    Corner& corner = out.corners[c];
    corner.index = static_cast<std::uint32_t>(c);
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t bits = load_u32_le(data, at + 4 * k);
      const float value = std::bit_cast<float>(bits);
      if (!std::isfinite(value) && out.first_bad == out.corners.size()) {
        out.first_bad = c;
        out.bad_at = at + 4 * k;
        out.bad_is_nan = std::isnan(value);
      }
      corner.bits[k] = position_bits(bits);
    }
  }
  return out;
}

// For each corner, the first corner (in file order) at the same position:
// corners sorted by (bits, index), so O(n log n) whatever the values (an
// unordered_map goes quadratic on keys that an input makes collide in its
// buckets).
std::vector<std::uint32_t> first_corner_at_same_position(std::vector<Corner> corners) {
  std::sort(corners.begin(), corners.end(), [](const Corner& a, const Corner& b) {
    return a.bits != b.bits ? a.bits < b.bits : a.index < b.index;
  });
  std::vector<std::uint32_t> first(corners.size());
  for (std::size_t k = 0; k < corners.size(); ++k)
    first[corners[k].index] =
        k > 0 && corners[k - 1].bits == corners[k].bits ? first[corners[k - 1].index] : corners[k].index;
  return first;
}

PolygonSoup parse_binary(const std::string& data, std::uint32_t count, std::string_view source,
                         const ReadLimits& limits) {
  if (count > limits.max_faces)
    fail_at(source, 80,
            std::to_string(count) + " triangles exceed the limit of " + std::to_string(limits.max_faces),
            ErrorCategory::limit);
  if (std::uint64_t{count} * 3 > std::numeric_limits<std::uint32_t>::max())
    fail_at(source, 80, "more than 2^32-1 face indices in total", ErrorCategory::limit);
  const std::uint64_t max_vertices =
      std::min<std::uint64_t>(limits.max_vertices, std::numeric_limits<std::uint32_t>::max());
  // The size check of the caller proved that the input holds `count` triangles.
  BinaryCorners loaded = load_corners(data, count);
  const std::size_t num_corners = loaded.corners.size();
  const std::vector<std::uint32_t> first = first_corner_at_same_position(std::move(loaded.corners));
  PolygonSoup soup;
  soup.face_indices.resize(num_corners);
  PointBuffer points;
  for (std::size_t c = 0; c < num_corners; ++c) {
    const std::size_t t = c / 3;
    if (c == loaded.first_bad)
      fail_at(source, loaded.bad_at,
              "triangle " + std::to_string(t) + " vertex " + std::to_string(c % 3) +
                  " has a non-finite coordinate (" + (loaded.bad_is_nan ? "nan" : "inf") + ")");
    if (first[c] != c) {
      soup.face_indices[c] = soup.face_indices[first[c]];
      continue;
    }
    if (points.size() + 1 > max_vertices)
      fail_at(source, corner_offset(c),
              "more than " + std::to_string(max_vertices) + " distinct vertices (the limit)",
              ErrorCategory::limit);
    soup.face_indices[c] = static_cast<std::uint32_t>(points.size());
    Vec3& p = points.append();
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t bits = load_u32_le(data, corner_offset(c) + 4 * static_cast<std::size_t>(k));
      p[k] = rational_from_float(std::bit_cast<float>(position_bits(bits)));
    }
  }
  soup.face_offsets.resize(std::size_t{count} + 1);
  for (std::size_t t = 0; t <= count; ++t) soup.face_offsets[t] = static_cast<std::uint32_t>(3 * t);
  soup.points = points.take();
  return soup;
}

// Tokens of an ASCII STL across line breaks, with its keywords.
class StlTokens : public TokenStream {
 public:
  using TokenStream::TokenStream;
  /// Consumes `keyword`; `context` makes the rest of the message, only on failure.
  template <class Context>
  void expect(std::string_view keyword, Context&& context) {
    std::string_view t = next();
    if (!t.empty() && iequals(t, keyword)) return;
    const std::string expected = "expected '" + std::string(keyword) + "' " + context();
    if (t.empty()) reader().fail("unexpected end of input, " + expected);
    reader().fail(expected + ", found " + quote(t));
  }
};

PolygonSoup parse_ascii(LineReader& reader) {
  StlTokens tokens(reader);
  PolygonSoup soup;
  // A balanced tree of the distinct points (which never move in the
  // PointBuffer) in an exact order: O(log n) per vertex whatever the values,
  // where a hash map goes quadratic on points that share one hash.
  std::map<const Vec3*, std::uint32_t, detail::RepresentationLess> index_of;
  PointBuffer points;
  Vec3 p;
  tokens.expect("solid", [] { return std::string("at the start of an ASCII STL"); });
  tokens.skip_rest_of_line();  // the solid's name
  for (;;) {
    std::string_view t = tokens.next();
    if (t.empty()) reader.fail("unexpected end of input, expected 'facet' or 'endsolid'");
    if (iequals(t, "endsolid")) {
      tokens.skip_rest_of_line();
      t = tokens.next();
      if (t.empty()) break;
      if (!iequals(t, "solid")) reader.fail("unexpected " + quote(t) + " after 'endsolid'");
      tokens.skip_rest_of_line();
      continue;
    }
    if (!iequals(t, "facet")) reader.fail("expected 'facet' or 'endsolid', found " + quote(t));
    const std::size_t f = soup.num_faces();
    auto name = [f] { return "facet " + std::to_string(f); };
    tokens.expect("normal", [] { return std::string("after 'facet'"); });
    for (std::uint64_t c = 0; c < 3; ++c) {
      // The normal is ignored, but must be there and is checked like a
      // coordinate, except that exporters write nan for degenerate facets.
      check_number(reader, tokens.next(), {"normal component", "facet", f}, true);
    }
    tokens.expect("outer", [&] { return "after the normal of " + name(); });
    tokens.expect("loop", [] { return std::string("after 'outer'"); });
    for (std::size_t k = 0; k < 3; ++k) {
      tokens.expect("vertex", [&] {
        // Built by appending: GCC 12's -O3 -Wrestrict misfires on "(" + std::string.
        std::string context = name();
        context.insert(0, 1, '(');
        context += " needs 3 vertices)";
        return context;
      });
      parse_point(
          reader, [&] { return tokens.next(); }, p, "vertex", k, "facet", f);
      auto it = index_of.find(p);
      if (it == index_of.end()) {
        check_vertex_limit(reader, points.size() + 1);
        const auto index = static_cast<std::uint32_t>(points.size());
        Vec3& stored = points.append();
        stored = std::move(p);
        it = index_of.emplace(&stored, index).first;
      }
      soup.face_indices.push_back(it->second);
    }
    tokens.expect("endloop", [&] { return "after the 3 vertices of " + name(); });
    tokens.expect("endfacet", [&] { return "at the end of " + name(); });
    check_face_limit(reader, f + 1, soup.face_indices.size());
    soup.face_offsets.push_back(static_cast<std::uint32_t>(soup.face_indices.size()));
  }
  soup.points = points.take();
  return soup;
}

// The float nearest to an exact value (ties to even), without the double
// rounding of going through double. \throw Error(invalid_argument) beyond the float range.
float to_float_nearest(const Rational& value) {
  // Values at or beyond FLT_MAX + ulp/2 round to infinity in IEEE arithmetic.
  static const Rational overflow = Rational(FLT_MAX) + Rational(std::ldexp(1.0, 103));
  if (abs(value) >= overflow)
    throw Error(ErrorCategory::invalid_argument, "coordinate " + to_string(value).substr(0, 40) +
                                                     " is beyond the range of float (binary STL)");
  float guess = static_cast<float>(to_double_nearest(value));
  float best = guess;
  Rational best_distance = abs(value - Rational(guess));
  for (float candidate : {std::nextafter(guess, -FLT_MAX), std::nextafter(guess, FLT_MAX)}) {
    if (!std::isfinite(candidate)) continue;
    Rational distance = abs(value - Rational(candidate));
    int c = cmp(distance, best_distance);
    if (c < 0 || (c == 0 && (std::bit_cast<std::uint32_t>(candidate) & 1u) == 0)) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

// The unit normal of triangle abc in float: the exact cross product, scaled
// exactly so that its largest component is +-1 (no overflow or underflow),
// then normalised in double. Zero for a degenerate triangle.
std::array<float, 3> unit_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
  Vec3 n = cross(b - a, c - a);
  if (is_zero(n)) return {0.0f, 0.0f, 0.0f};
  Rational largest = abs(n.x);
  if (cmp(abs(n.y), largest) > 0) largest = abs(n.y);
  if (cmp(abs(n.z), largest) > 0) largest = abs(n.z);
  double x = to_double_nearest(n.x / largest);
  double y = to_double_nearest(n.y / largest);
  double z = to_double_nearest(n.z / largest);
  double length = std::sqrt(x * x + y * y + z * z);
  return {static_cast<float>(x / length), static_cast<float>(y / length), static_cast<float>(z / length)};
}

}  // namespace
}  // namespace io_detail

namespace io_detail {
namespace {

// Appends up to n bytes of `bytes` to data; false if fewer were left.
bool read_more(ByteSource& bytes, std::string& data, std::uint64_t n) {
  constexpr std::size_t chunk = std::size_t{1} << 16;
  while (n > 0) {
    const auto want = static_cast<std::size_t>(std::min<std::uint64_t>(n, chunk));
    const std::size_t old = data.size();
    data.resize(old + want);
    const std::size_t got = bytes.read(data.data() + old, want);
    data.resize(old + got);
    if (got == 0) return false;
    n -= got;
  }
  return true;
}

// Bytes left in `bytes`, counted (not kept) up to `cap`; nullopt beyond it.
std::optional<std::uint64_t> count_rest(ByteSource& bytes, std::uint64_t cap) {
  std::string sink(std::size_t{1} << 16, '\0');
  std::uint64_t total = 0;
  while (total <= cap) {
    const std::size_t got = bytes.read(sink.data(), sink.size());
    if (got == 0) return total;
    total += got;
  }
  return std::nullopt;
}

bool all_blank(std::string_view text) {
  return text.find_first_not_of(" \t\r\n\xEF\xBB\xBF") == std::string_view::npos;
}

std::string count_mismatch(std::uint32_t count, std::uint64_t expected, const std::string& size) {
  return "the binary STL header declares " + std::to_string(count) + " triangles, which need " +
         std::to_string(expected) + " bytes, but the input has " + size;
}

// An input that does not start with "solid" can only be binary: read no more
// than its declared size and a bounded look past it (so /dev/zero, whose
// header declares 0 triangles, ends after a megabyte).
PolygonSoup read_binary_only(ByteSource& bytes, std::string data, std::string_view source,
                             const ReadLimits& limits) {
  const std::uint32_t count = load_u32_le(data, 80);
  const std::uint64_t expected = header_size + record_size * std::uint64_t{count};
  const bool longer = read_more(bytes, data, expected + 1 - data.size()) && data.size() > expected;
  if (!longer && data.size() == expected) return parse_binary(data, count, source, limits);
  if (data.size() < expected) {
    const std::uint64_t complete = (data.size() - header_size) / record_size;
    fail_at(source, header_size + complete * record_size,
            count_mismatch(count, expected, std::to_string(data.size())) + " (truncated in triangle " +
                std::to_string(complete) + ")");
  }
  constexpr std::uint64_t look_past = std::uint64_t{1} << 20;
  const std::optional<std::uint64_t> rest = count_rest(bytes, look_past);
  if (!rest)
    fail_at(source, expected,
            count_mismatch(count, expected, "more than " + std::to_string(expected + look_past)) +
                " (extra bytes after the last triangle)");
  const std::uint64_t size = data.size() + *rest;
  fail_at(source, expected,
          count_mismatch(count, expected, std::to_string(size)) + " (" + std::to_string(size - expected) +
              " bytes after the last triangle)");
}

}  // namespace
}  // namespace io_detail

PolygonSoup read_stl(std::istream& in, std::string_view source, const ReadLimits& limits) {
  using namespace io_detail;
  ByteSource bytes(in, source, limits.max_bytes);
  std::string data;
  read_more(bytes, data, header_size);
  if (data.empty()) throw Error(ErrorCategory::parse, std::string(source) + ": empty input");
  if (data.size() == header_size && !starts_with_solid(data) && !all_blank(data))
    return read_binary_only(bytes, std::move(data), source, limits);
  // ASCII, or binary with a header that starts with "solid": read whole, but
  // once it is too long to be binary, a NUL byte rules out ASCII too.
  std::optional<std::uint64_t> expected;
  if (data.size() == header_size) expected = header_size + record_size * std::uint64_t{load_u32_le(data, 80)};
  std::size_t checked = data.size();
  while (read_more(bytes, data, std::uint64_t{1} << 20)) {
    if (!expected || data.size() <= *expected) continue;
    if (const void* nul = std::memchr(data.data() + checked, '\0', data.size() - checked); nul != nullptr)
      fail_at(source, static_cast<std::uint64_t>(static_cast<const char*>(nul) - data.data()),
              "a NUL byte in an ASCII STL; not binary either: " +
                  count_mismatch(load_u32_le(data, 80), *expected, "more than " + std::to_string(*expected)));
    checked = data.size();
  }
  const bool solid = starts_with_solid(data);
  std::string binary_hint;
  if (data.size() >= header_size) {
    const std::uint32_t count = load_u32_le(data, 80);
    if (*expected == data.size()) return parse_binary(data, count, source, limits);
    const std::string mismatch = count_mismatch(count, *expected, std::to_string(data.size()));
    if (!solid) fail_at(source, std::min<std::uint64_t>(*expected, data.size()), mismatch);
    if (std::memchr(data.data(), '\0', data.size()) != nullptr) binary_hint = "; not binary either: " + mismatch;
  } else if (!solid) {
    fail_at(source, 0,
            "input of " + std::to_string(data.size()) +
                " bytes neither starts with 'solid' nor holds an 84-byte binary STL header");
  }
  LineReader reader(std::move(data), source, limits);
  try {
    return parse_ascii(reader);
  } catch (const Error& e) {
    if (binary_hint.empty() || e.category() != ErrorCategory::parse) throw;
    throw Error(e.category(), e.message() + binary_hint);
  }
}

void write_stl(std::ostream& out, const PolygonSoup& soup) { io_detail::write_stl_view(out, io_detail::SoupView::of(soup)); }

void io_detail::write_stl_view(std::ostream& out, const SoupView& soup) {
  using namespace io_detail;
  check_soup_for_writing(soup, 3);
  std::uint64_t triangles = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) triangles += soup.face(f).size() - 2;
  if (triangles > std::numeric_limits<std::uint32_t>::max())
    throw Error(ErrorCategory::invalid_argument,
                std::to_string(triangles) + " triangles do not fit a binary STL");
  std::vector<std::array<float, 3>> rounded;
  rounded.reserve(soup.points.size());
  for (std::size_t j = 0; j < soup.points.size(); ++j) {
    const Vec3& p = soup.point(j);
    rounded.push_back({to_float_nearest(p.x), to_float_nearest(p.y), to_float_nearest(p.z)});
  }

  TextWriter w(out);
  char header[80] = "binary STL written by cvms";  // never starts with "solid"
  w.text(std::string_view(header, sizeof header));
  w.u32_le(static_cast<std::uint32_t>(triangles));
  auto put = [&w](float value) { w.u32_le(std::bit_cast<std::uint32_t>(value)); };
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto face = soup.face(f);
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      const std::uint32_t corners[3] = {face[0], face[k], face[k + 1]};
      for (float c : unit_normal(soup.point(corners[0]), soup.point(corners[1]), soup.point(corners[2])))
        put(c);
      for (std::uint32_t v : corners)
        for (float c : rounded[v]) put(c);
      w.byte('\0').byte('\0');
    }
  }
  w.finish();
}

}  // namespace cvms
