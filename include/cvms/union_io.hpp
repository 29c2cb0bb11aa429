// SPDX-License-Identifier: MIT
/// \file
/// Pieces files: a union of convex polyhedra (cvms/convex_union.hpp) as one
/// Wavefront OBJ file with one object per piece, the form in which collision
/// libraries and modelling tools exchange convex decompositions.
///
/// The file holds, for piece N (counted from 1), the statement `o piece_N`,
/// then the piece's vertices (`v x y z`) and then its facets (`f i j k ...`,
/// 1-based indices into the file's vertices), each piece written as
/// write_file writes a polyhedron: maximal, strictly convex polygonal
/// facets, counter-clockwise seen from outside, each vertex once per piece.
/// With exact coordinates, read_pieces gives back the same pieces in the
/// same order.
///
/// \code
/// cvms::ConvexUnion u = cvms::convex_decomposition(cvms::read_solid("bracket.off"));
/// cvms::write_pieces("bracket_pieces.obj", u);
/// cvms::ConvexUnion back = cvms::read_pieces("bracket_pieces.obj");
/// \endcode
#pragma once

#include <filesystem>
#include <istream>
#include <ostream>
#include <string_view>

#include "cvms/convex_union.hpp"
#include "cvms/io.hpp"

namespace cvms {

/// Writes the pieces of `u` as an OBJ stream (see the file comment).
/// \throw Error(invalid_argument) for an empty union, and naming the piece
///   for a coordinate beyond the double range with Coordinates::double_;
/// \throw Error(io) if the stream fails.
/// Complexity: linear in the size of the output.
void write_pieces(std::ostream& out, const ConvexUnion& u, Coordinates coordinates = Coordinates::exact);

/// Writes the pieces of `u` to an OBJ file, whatever the path's extension,
/// atomically as write_file: on any failure an existing file is left
/// byte-identical.
/// \throw Error(invalid_argument) as the stream version, the message
///   prefixed by "<path>: ";
/// \throw Error(io) naming the file and the reason if it cannot be written.
void write_pieces(const std::filesystem::path& path, const ConvexUnion& u,
                  Coordinates coordinates = Coordinates::exact);

/// Reads a pieces file: an OBJ stream (read as read_obj reads one, within
/// `limits`) whose every face follows an `o` statement; each `o` statement
/// starts a piece, whatever its name, and the faces up to the next one are
/// that piece's boundary. A file without `o` statements is one piece. Each
/// piece is validated as ConvexPolyhedron::from_soup validates a polyhedron
/// (closed, convex, consistently oriented outward; coplanar faces merged).
/// `source` names the input in error messages.
/// \throw Error(parse), Error(limit) as read_obj, naming source and line; also
///   Error(parse) for faces before the first `o` statement and for an `o`
///   statement without faces, naming its line;
/// \throw Error(topology), Error(not_convex), Error(degenerate) (the errors
///   of from_soup) as "<source>:<line>: piece N ('<name>'): <reason>", where
///   the line is that of the piece's `o` statement and the reason numbers the
///   piece's faces from 0 in file order.
/// Complexity: linear in the input size, plus from_soup's for each piece.
ConvexUnion read_pieces(std::istream& in, std::string_view source, const ReadLimits& limits = {});

/// As read_pieces(stream), from a file whatever its extension; errors name
/// the file.
/// \throw Error(io) if the file cannot be opened or is a directory; the
///   errors of the stream version otherwise.
ConvexUnion read_pieces(const std::filesystem::path& path, const ReadLimits& limits = {});

}  // namespace cvms
