// SPDX-License-Identifier: MIT
// Wavefront OBJ reader and writer, polygonal subset: `v x y z [w]` (w must
// be 1; `v x y z r g b` vertex colors are ignored) and `f` with the forms i,
// i/t, i//n, i/t/n and negative (relative) indices. Statements that do not
// change the polygon geometry (vt, vn, g, o, s, usemtl, mtllib, l, p, ...) are
// ignored; free-form geometry and unknown statements are rejected, so that
// nothing is silently dropped.
#include <algorithm>
#include <array>
#include <limits>
#include <string>

#include "float_coordinates.hpp"
#include "io_reader.hpp"
#include "io_writer.hpp"

namespace cvms {
namespace io_detail {
namespace {

bool is_ignored_statement(std::string_view keyword) {
  static constexpr std::array<std::string_view, 20> ignored = {
      "vt",     "vn", "vp", "g",     "o",        "s",        "mg",  "usemtl",     "mtllib",    "usemap",
      "maplib", "l",  "p",  "bevel", "c_interp", "d_interp", "lod", "shadow_obj", "trace_obj", "call"};
  return std::find(ignored.begin(), ignored.end(), keyword) != ignored.end();
}

bool is_free_form_statement(std::string_view keyword) {
  static constexpr std::array<std::string_view, 16> free_form = {
      "cstype", "deg",  "bmat", "step", "curv", "curv2", "surf",  "parm",
      "trim",   "hole", "scrv", "sp",   "end",  "con",   "ctech", "stech"};
  return std::find(free_form.begin(), free_form.end(), keyword) != free_form.end();
}

// The vertex part of a face token "i", "i/t", "i//n" or "i/t/n"; the texture
// and normal parts must be well-formed integers but are otherwise ignored.
// `vertex_text` is set to the vertex part as typed.
std::optional<std::int64_t> parse_face_vertex(std::string_view token, std::string_view& vertex_text) {
  std::array<std::string_view, 3> parts{};
  std::size_t count = 0;
  for (;;) {
    std::size_t slash = token.find('/');
    if (count == 3) return std::nullopt;
    parts[count++] = token.substr(0, slash);
    if (slash == std::string_view::npos) break;
    token.remove_prefix(slash + 1);
  }
  vertex_text = parts[0];
  auto vertex = parse_signed(parts[0]);
  if (!vertex || *vertex == 0) return std::nullopt;
  if (count >= 2 && !(count == 3 && parts[1].empty()) && !parse_signed(parts[1])) return std::nullopt;
  if (count == 3 && !parse_signed(parts[2])) return std::nullopt;
  return vertex;
}

}  // namespace

PolygonSoup parse_obj(LineReader& reader, std::vector<ObjObject>* objects) {
  PolygonSoup soup;
  PointBuffer points;
  // Positive indices may refer to vertices defined further down; the largest
  // one is checked at the end against the final vertex count.
  std::uint64_t max_forward = 0;
  std::uint64_t max_forward_line = 0;
  std::uint64_t max_forward_face = 0;
  bool any_statement = false;
  std::vector<std::uint32_t> face;
  std::string_view line;
  while (reader.next(line)) {
    Tokenizer tokens(line);
    std::string_view keyword = tokens.next();
    if (keyword.empty()) continue;
    any_statement = true;
    if (keyword == "v") {
      const std::uint64_t number = points.size() + 1;  // as OBJ counts
      check_vertex_limit(reader, number);
      Vec3& p = points.append();
      parse_point(
          reader, [&] { return tokens.next(); }, p, "vertex", number);
      auto name = [number] { return "vertex " + std::to_string(number); };
      std::array<std::string_view, 4> extra{};
      std::size_t num_extra = 0;
      for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next()) {
        if (num_extra == 3) reader.fail(name() + " has more than 6 values");
        extra[num_extra++] = t;
      }
      if (num_extra == 1) {
        const Rational& w = check_number(reader, extra[0], {"w coordinate", "vertex", number});
        if (w != 1) reader.fail(name() + " has w = " + quote(extra[0]) + "; only w = 1 is supported");
      } else if (num_extra == 3) {
        for (std::size_t i = 0; i < 3; ++i) check_number(reader, extra[i], {"color value", "vertex", number});
      } else if (num_extra != 0) {
        reader.fail(name() + " has 5 values; expected x y z, x y z w or x y z r g b");
      }
    } else if (keyword == "f") {
      const std::uint64_t f = soup.num_faces();
      auto name = [f] { return "face " + std::to_string(f + 1); };
      face.clear();
      for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next()) {
        std::string_view index_text;
        auto index = parse_face_vertex(t, index_text);
        if (!index)
          reader.fail(name() + ": " + quote(t) +
                      " is not a vertex reference (i, i/t, i//n or i/t/n, i != 0)");
        std::int64_t count = static_cast<std::int64_t>(points.size());
        std::int64_t resolved = 0;
        if (*index < 0) {
          if (-*index > count)
            reader.fail(name() + " has relative index " + typed(index_text) + " but only " +
                        std::to_string(count) + " vertices are defined before it");
          resolved = count + *index;
        } else {
          if (static_cast<std::uint64_t>(*index) > std::numeric_limits<std::uint32_t>::max())
            reader.fail(name() + " has index " + typed(index_text) + ", beyond the 32-bit range");
          resolved = *index - 1;
          if (static_cast<std::uint64_t>(*index) > max_forward) {
            max_forward = static_cast<std::uint64_t>(*index);
            max_forward_line = reader.line_number();
            max_forward_face = f + 1;
          }
        }
        face.push_back(static_cast<std::uint32_t>(resolved));
        if (face.size() % 4096 == 0) check_face_limit(reader, f + 1, soup.face_indices.size() + face.size());
      }
      if (face.size() < 3)
        reader.fail(name() + " has " + std::to_string(face.size()) + " vertices, at least 3 are needed");
      check_face_limit(reader, f + 1, soup.face_indices.size() + face.size());
      soup.add_face(face);
    } else if (keyword == "o" && objects != nullptr) {
      objects->push_back({reader.line_number(), soup.num_faces(), std::string(tokens.next())});
    } else if (is_ignored_statement(keyword)) {
      continue;
    } else if (is_free_form_statement(keyword)) {
      reader.fail("free-form geometry (" + quote(keyword) + ") is not supported");
    } else {
      reader.fail("unknown OBJ statement " + quote(keyword));
    }
  }
  if (!any_statement) {
    if (reader.line_number() == 0)
      throw Error(ErrorCategory::parse, std::string(reader.source()) + ": empty input");
    reader.fail("no OBJ statements in the input");
  }
  soup.points = points.take();
  if (max_forward > soup.points.size())
    throw Error(ErrorCategory::parse, std::string(reader.source()) + ":" + std::to_string(max_forward_line) +
                                          ": face " + std::to_string(max_forward_face) + " has index " +
                                          std::to_string(max_forward) + " but there are " +
                                          std::to_string(soup.points.size()) + " vertices");
  if (soup.points.empty()) reader.fail("no vertices ('v' statements) in the input");
  return soup;
}

}  // namespace io_detail

PolygonSoup read_obj(std::istream& in, std::string_view source, const ReadLimits& limits) {
  io_detail::LineReader reader(in, source, limits);
  return io_detail::parse_obj(reader);
}

void write_obj(std::ostream& out, const PolygonSoup& soup, Coordinates coordinates) {
  io_detail::write_obj_view(out, io_detail::SoupView::of(soup), coordinates);
}

void io_detail::write_obj_view(std::ostream& out, const SoupView& soup, Coordinates coordinates) {
  io_detail::check_soup_coordinates(coordinates);
  io_detail::check_soup_for_writing(soup, 3);
  io_detail::TextWriter w(out);
  for (std::size_t j = 0; j < soup.num_points(); ++j) w.text("v ").point(soup, j, coordinates).byte('\n');
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    w.byte('f');
    for (std::uint32_t i : soup.face(f)) w.byte(' ').integer(std::uint64_t{i} + 1);
    w.byte('\n');
  }
  w.finish();
}

}  // namespace cvms
