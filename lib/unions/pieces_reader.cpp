// SPDX-License-Identifier: MIT
// Reading a pieces file (cvms/union_io.hpp). The OBJ reader parses the
// whole file once, within the read limits, and reports where each `o`
// statement starts; each object's faces then become a soup of their own
// (its vertices renumbered in order of first use, through one table over
// the file's vertices that is reset after each piece, so the work is linear
// in the file) validated by ConvexPolyhedron::from_soup. A piece's faces may
// use any vertex of the file, as OBJ allows; its errors name the piece and
// the line of its `o` statement.
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/union_io.hpp"
#include "io_reader.hpp"

namespace cvms {
namespace {

constexpr std::uint32_t unused = std::numeric_limits<std::uint32_t>::max();

// Faces [first, last) of the file's soup as a soup of their own. `remap`
// has one entry per file vertex, all `unused` on entry and on return.
PolygonSoup piece_soup(const PolygonSoup& file, std::size_t first, std::size_t last,
                       std::vector<std::uint32_t>& remap) {
  PolygonSoup piece;
  std::vector<std::uint32_t> face;
  for (std::size_t f = first; f < last; ++f) {
    face.clear();
    for (std::uint32_t v : file.face(f)) {
      if (remap[v] == unused) {
        remap[v] = static_cast<std::uint32_t>(piece.points.size());
        piece.points.push_back(file.points[v]);
      }
      face.push_back(remap[v]);
    }
    piece.add_face(face);
  }
  for (std::size_t f = first; f < last; ++f)
    for (std::uint32_t v : file.face(f)) remap[v] = unused;
  return piece;
}

// "<source>:<line>: piece N ('<name>')", a long name cut short: it may be
// as long as a line.
std::string piece_name(std::string_view source, const io_detail::ObjObject& object, std::size_t number) {
  constexpr std::size_t longest = 64;
  const std::string name = object.name.size() > longest ? object.name.substr(0, longest) + "..." : object.name;
  return std::string(source) + ":" + std::to_string(object.line) + ": piece " + std::to_string(number) + " ('" +
         name + "')";
}

ConvexPolyhedron read_piece(const PolygonSoup& file, std::size_t first, std::size_t last,
                            std::vector<std::uint32_t>& remap, const std::string& name) {
  try {
    return ConvexPolyhedron::from_soup(piece_soup(file, first, last, remap));
  } catch (const Error& e) {
    throw Error(e.category(), name + ": " + e.message());
  }
}

}  // namespace

ConvexUnion read_pieces(std::istream& in, std::string_view source, const ReadLimits& limits) {
  io_detail::LineReader reader(in, source, limits);
  std::vector<io_detail::ObjObject> objects;
  const PolygonSoup file = io_detail::parse_obj(reader, &objects);
  std::vector<std::uint32_t> remap(file.points.size(), unused);
  if (objects.empty()) {
    if (file.num_faces() == 0) throw Error(ErrorCategory::parse, std::string(source) + ": no faces in the input");
    return ConvexUnion(std::vector<ConvexPolyhedron>{
        read_piece(file, 0, file.num_faces(), remap, std::string(source) + ": piece 1")});
  }
  if (objects.front().first_face != 0)
    throw Error(ErrorCategory::parse, std::string(source) + ":" + std::to_string(objects.front().line) + ": " +
                                          std::to_string(objects.front().first_face) +
                                          " faces come before the first 'o' statement: a piece's faces follow its 'o'");
  std::vector<ConvexPolyhedron> pieces;
  pieces.reserve(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::size_t first = objects[i].first_face;
    const std::size_t last = i + 1 < objects.size() ? objects[i + 1].first_face : file.num_faces();
    const std::string name = piece_name(source, objects[i], i + 1);
    if (first == last) throw Error(ErrorCategory::parse, name + " has no faces");
    pieces.push_back(read_piece(file, first, last, remap, name));
  }
  return ConvexUnion(std::move(pieces));
}

ConvexUnion read_pieces(const std::filesystem::path& path, const ReadLimits& limits) {
  std::ifstream in = io_detail::open_input_file(path);
  return read_pieces(in, path.string(), limits);
}

}  // namespace cvms
