// SPDX-License-Identifier: MIT
// Writing a union as a pieces file (cvms/union_io.hpp): each piece is an OBJ
// object written from its own mesh as write_file writes a polyhedron (the io
// layer's polyhedron view: its points, packed or not, and its faces'
// index lists), with the indices moved past the vertices of the pieces
// before it, since OBJ numbers the vertices of the whole file. In doubles,
// each piece is rounded as a convex set first.
#include <cstdint>
#include <fstream>
#include <optional>
#include <string>

#include "cvms/error.hpp"
#include "cvms/union_io.hpp"
#include "cvms/float_mesh.hpp"
#include "file_output.hpp"
#include "float_coordinates.hpp"
#include "io_writer.hpp"
#include "soup_view.hpp"

namespace cvms {
namespace {

// Writes piece `number` (1-based) whose first vertex has the 0-based file
// index `first_vertex`; returns the number of vertices written.
std::size_t write_piece(io_detail::TextWriter& w, const ConvexPolyhedron& piece, std::size_t number,
                        std::uint64_t first_vertex, Coordinates coordinates) {
  detail::FaceLists faces;
  io_detail::SoupView view = io_detail::polyhedron_view(piece, FileFormat::obj, faces);
  // In doubles each piece is rounded as the convex set it is (float_mesh.hpp):
  // nearest keeps every piece a valid convex polyhedron in the doubles
  // written, outer keeps it containing the exact piece, so that the union
  // of the written pieces contains the exact union.
  std::optional<PolygonSoup> rounded;
  try {
    const auto round = [&piece](FloatMode mode) { return round_to_doubles(piece, mode); };
    rounded = io_detail::rounded_soup(FileFormat::obj, coordinates, {}, round);
  } catch (const Error& e) {
    throw Error(e.category(), "piece " + std::to_string(number) + ": " + e.message());
  }
  if (rounded) {
    view = io_detail::SoupView::of(*rounded);
    coordinates = Coordinates::double_;
  }
  w.text("o piece_").integer(number).byte('\n');
  try {
    for (std::size_t j = 0; j < view.num_points(); ++j) w.text("v ").point(view, j, coordinates).byte('\n');
  } catch (const Error& e) {
    if (e.category() == ErrorCategory::io) throw;
    throw Error(e.category(), "piece " + std::to_string(number) + ": " + e.message());
  }
  for (std::size_t f = 0; f < view.num_faces(); ++f) {
    w.byte('f');
    for (std::uint32_t i : view.face(f)) w.byte(' ').integer(first_vertex + i + 1);
    w.byte('\n');
  }
  return view.num_points();
}

}  // namespace

void write_pieces(std::ostream& out, const ConvexUnion& u, Coordinates coordinates) {
  if (u.empty()) throw Error(ErrorCategory::invalid_argument, "an empty union has no pieces to write");
  io_detail::TextWriter w(out);
  std::uint64_t first_vertex = 0;
  for (std::size_t i = 0; i < u.size(); ++i)
    first_vertex += write_piece(w, u.pieces()[i], i + 1, first_vertex, coordinates);
  w.finish();
}

void write_pieces(const std::filesystem::path& path, const ConvexUnion& u, Coordinates coordinates) {
  try {
    io_detail::write_atomically(path, [&](std::ostream& out) { write_pieces(out, u, coordinates); });
  } catch (const Error& e) {
    // write_atomically names the file in its io errors; the writer names a
    // piece, never the file.
    if (e.category() == ErrorCategory::io) throw;
    throw Error(e.category(), path.string() + ": " + e.message());
  }
}

}  // namespace cvms
