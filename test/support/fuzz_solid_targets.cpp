// SPDX-License-Identifier: MIT
// The fuzz targets of the non-convex paths (fuzz_targets.hpp): the pieces
// reader and the solid reader. Each accepted input is checked against what
// the library promises, with the test's own exact arithmetic where it can.
#include <sstream>
#include <string>
#include <vector>

#include "cvms/decomposition.hpp"
#include "cvms/error.hpp"
#include "cvms/solid.hpp"
#include "cvms/union_io.hpp"
#include "support/fuzz_targets.hpp"
#include "support/union_oracle.hpp"

namespace cvms::fuzz {
namespace {

[[noreturn]] void finding(const std::string& what) { throw FuzzFinding(what); }

std::string text_of(std::span<const std::uint8_t> data) {
  return std::string(reinterpret_cast<const char*>(data.data()), data.size());
}

}  // namespace

void read_pieces_target(std::span<const std::uint8_t> data) {
  std::istringstream in(text_of(data));
  ConvexUnion pieces;
  try {
    pieces = read_pieces(in, "<fuzz>", fuzz_limits());
  } catch (const Error&) {
    return;
  }
  if (pieces.empty()) finding("read_pieces: accepted a file without pieces");
  for (const ConvexPolyhedron& piece : pieces.pieces())
    if (!piece.is_convex() || test::volume_by_tetrahedra(piece) <= 0) finding("read_pieces: a piece is not a convex body");
  std::ostringstream out;
  write_pieces(out, pieces);
  std::istringstream back(out.str());
  ConvexUnion again;
  try {
    again = read_pieces(back, "<round trip>");
  } catch (const Error& e) {
    finding(std::string("read_pieces: the written pieces do not read back: ") + e.what());
  }
  if (again.size() != pieces.size()) finding("read_pieces: write + read changed the number of pieces");
  for (std::size_t i = 0; i < pieces.size(); ++i)
    if (test::vertex_set(again.pieces()[i]) != test::vertex_set(pieces.pieces()[i]))
      finding("read_pieces: write + read changed piece " + std::to_string(i));
}

void read_solid_target(std::span<const std::uint8_t> data) {
  std::istringstream in(text_of(data));
  Solid solid;
  try {
    solid = Solid::from_soup(read_off(in, "<fuzz>", fuzz_limits()));
  } catch (const Error&) {
    return;
  }
  if (solid.volume() <= 0) finding("read_solid: accepted a solid without positive volume");
  if (solid.is_convex() != (solid.num_reflex_edges() == 0 && solid.num_shells() == 1))
    finding("read_solid: is_convex disagrees with the reflex edges and shells");
  if (solid.triangles().size() > 64) return;  // the decomposition of small solids only
  ConvexUnion pieces;
  try {
    pieces = convex_decomposition(solid);
  } catch (const Error& e) {
    finding(std::string("read_solid: a valid solid does not decompose: ") + e.what());
  }
  Rational total = 0;
  for (const ConvexPolyhedron& piece : pieces.pieces()) total += test::volume_by_tetrahedra(piece);
  if (total != solid.volume()) finding("read_solid: the pieces' volumes do not sum to the solid's");
}

}  // namespace cvms::fuzz
