// SPDX-License-Identifier: MIT
// Solids that need not be convex and unions of convex pieces on the command
// line: reading an operand as either, writing pieces files, and the message
// that tells a user of a convex-only command what to do with a solid that
// is not convex. Errors name the file.
//
// Which files are pieces files: an OBJ file with two or more `o` statements
// (what `cvms decompose` and `cvms sum --pieces` write). Any other mesh is a
// solid; a convex solid is its own one piece.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <string_view>

#include "cvms/convex_union.hpp"
#include "cvms/decomposition.hpp"
#include "cvms/error.hpp"
#include "cvms/io.hpp"
#include "cvms/polygon_soup.hpp"
#include "cvms/solid.hpp"

namespace cvms::cli {

/// True for an .obj path (any case) whose file holds two or more `o`
/// statements; false for "-" and for a file that cannot be read (its reader
/// then names the problem).
bool is_pieces_path(const std::string& path);

/// True when `text` (an OBJ file's bytes) holds two or more `o` statements.
bool is_pieces_text(std::string_view text);

/// The pieces file at `path`, read exactly (read_pieces) within the
/// inputs' memory budget, as every other input is (files.hpp).
ConvexUnion read_pieces_file(const std::string& path);

/// Solid::from_soup with "<source>: " in front of every error message.
Solid solid_from_soup(PolygonSoup soup, const std::string& source);

/// True when the soup's points span space (four of them not in one plane):
/// only then can it be a solid, so a flat file keeps the convex reader's
/// message.
bool spans_space(const PolygonSoup& soup);

/// An operand as a union of convex pieces: a pieces file as it is, any other
/// mesh (or OFF on stdin for "-") validated as a solid and decomposed.
/// Errors name the file; a decomposition limit names its option.
ConvexUnion read_union_operand(const std::string& path, const DecompositionOptions& options);

/// The soup read from `path`, validated as a solid and decomposed; errors
/// as read_union_operand.
ConvexUnion decompose_soup(PolygonSoup soup, const std::string& path, const DecompositionOptions& options);

/// For a command that takes convex sets only, after `convex_error` (from
/// reading `path` as a convex set): when it is a topology or convexity error
/// and the file is a pieces file or a valid solid, throws Error(not_convex)
/// "<file>: <what it is>, not a convex set: <hint>"; when the file spans
/// space but is no valid solid, the solid's located defect (the more
/// general reading); otherwise (a flat file, stdin, which cannot be read
/// again, another error) rethrows `convex_error`.
[[noreturn]] void rethrow_explaining_non_convex(const Error& convex_error, const std::string& path,
                                                std::string_view hint);

/// Throws Error(not_convex) "<file>: <what>, not a convex set: <hint>".
[[noreturn]] void throw_not_a_convex_set(const std::string& path, const std::string& what, std::string_view hint);

/// What a pieces file of `count` pieces is, for throw_not_a_convex_set.
std::string pieces_file_of(std::size_t count);

/// Fails before any work unless `path` is "-" or ends in .obj (any case):
/// pieces are written as OBJ objects. \throw UsageError; Error(io) as
/// check_output_directory.
void check_pieces_output(const std::string& path);

/// write_pieces to the file (atomically), or OBJ on stdout for "-".
void write_pieces_output(const std::string& path, const ConvexUnion& pieces, Coordinates coordinates);

/// --max-pieces and --max-decomposition-memory into `limits` (its values are
/// the defaults shown).
void add_decomposition_limit_options(CLI::App& command, DecompositionLimits& limits);

/// Rethrows `e`; a decomposition's Error(limit) gets the option that raises
/// it appended, a sum's as rethrow_with_limit_hint (sizes.hpp).
[[noreturn]] void rethrow_with_pieces_limit_hint(const Error& e);

}  // namespace cvms::cli
